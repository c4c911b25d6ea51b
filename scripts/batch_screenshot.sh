#!/usr/bin/env bash
# The status page of yade-batch, as a browser shows it, into doc/images/batch-status.png: the getting-started
# deposition (doc/getting-started.md) run for three dampings and one line that fails on purpose, the page taken
# with headless Chromium (apt-get install chromium) while the jobs run.
# Usage: bash scripts/batch_screenshot.sh
set -euo pipefail
REPO="$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/.." && pwd)"
command -v chromium >/dev/null || { echo "batch_screenshot.sh: needs chromium (apt-get install chromium)" >&2; exit 1; }
work="$(mktemp -d)"
trap 'kill $batch 2>/dev/null || true; wait $batch 2>/dev/null || true; rm -rf "$work"' EXIT
cd "$work"
/usr/bin/python3 - "$REPO/doc/getting-started.md" <<'PY'
import re, sys
for lang, text in re.findall(r'```(\w*)\n(.*?)```', open(sys.argv[1]).read(), re.S):
    if text.startswith('# deposition.py'):
        open('deposition.py', 'w').write(text)
PY
printf 'damping  description\n.05      low\n.2       medium\n.5       high\nnoSuchName  fails-on-purpose\n' > deposition.table
port=$(/usr/bin/python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
"$REPO/yade-batch" -j 2 --port "$port" --plot-update 2 --refresh 0 --http-wait deposition.table deposition.py > batch.out 2>&1 &
batch=$!
sleep 12  # two jobs running, one failed or waiting, plots written
chromium --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=1280,1000 \
    --screenshot="$REPO/doc/images/batch-status.png" "http://localhost:$port/" 2>/dev/null
echo "wrote doc/images/batch-status.png"
