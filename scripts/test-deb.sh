#!/usr/bin/env bash
# Build the Debian package, check it with lintian, install it, use it, remove it (debian/README.md).
# Needs root (apt-get install/remove); not part of ./yade --test.
#
#   sudo bash scripts/test-deb.sh [WORKDIR]
#
# The package is built from a clone of the repository's HEAD (commit first what should be tested) in
# WORKDIR/src (default: a new folder under /tmp, kept: the .deb, the build log and lintian's output
# stay there). Environment: JOBS (parallel compile jobs, default 2), KEEP=1 (leave the package
# installed at the end). Exit status: 0 when every step passed, 1 otherwise.
set -euo pipefail

REPO="$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/.." && pwd)"
WORK="${1:-$(mktemp -d /tmp/yade-deb-test.XXXXXX)}"
JOBS="${JOBS:-2}"
PKG=yade-fast

say() { printf 'test-deb: %s\n' "$*"; }
fail() { say "FAILED: $*"; exit 1; }

[[ "$(id -u)" -eq 0 ]] || fail "run as root (apt-get install and remove): sudo bash $0"
export DEBIAN_FRONTEND=noninteractive

is_installed() { [[ "$(dpkg-query -W -f='${Status}' "$PKG" 2>/dev/null || true)" == *" installed" ]]; }
installed_here=0
cleanup() {
    if [[ "$installed_here" -eq 1 && "${KEEP:-0}" != 1 ]]; then
        say "removing $PKG after a failure"
        apt-get remove -y -qq "$PKG" >/dev/null 2>&1 || dpkg --remove "$PKG" >/dev/null 2>&1 || true
    fi
}
trap cleanup EXIT

if is_installed; then
    fail "$PKG is installed already (apt-get remove $PKG first): this test installs and removes it"
fi

mkdir -p "$WORK"
rm -rf "$WORK/src"
git clone -q "$REPO" "$WORK/src"
say "building $(git -C "$WORK/src" log --oneline -1) in $WORK/src"
cd "$WORK/src"

# build dependencies from debian/control
if ! dpkg-checkbuilddeps >/dev/null 2>&1; then
    say "installing the build dependencies (apt-get build-dep)"
    apt-get update -qq
    apt-get build-dep -y -qq ./ >"$WORK/build-dep.log" 2>&1 || fail "apt-get build-dep (see $WORK/build-dep.log)"
fi
command -v lintian >/dev/null || apt-get install -y -qq lintian >/dev/null

# build: the binary package only, no tests (the suite runs from the source tree), JOBS compile jobs
start=$(date +%s.%N)
DEB_BUILD_OPTIONS="nocheck parallel=$JOBS" dpkg-buildpackage -us -uc -b >"$WORK/build.log" 2>&1 \
    || { tail -30 "$WORK/build.log"; fail "dpkg-buildpackage (see $WORK/build.log)"; }
end=$(date +%s.%N)
build_s=$(LC_ALL=C awk -v s="$start" -v e="$end" 'BEGIN { printf "%.0f", e - s }')
deb=$(ls "$WORK"/${PKG}_*.deb | head -1)
changes=$(ls "$WORK"/${PKG}_*.changes | head -1)
say "built $(basename "$deb") in ${build_s} s: $(du -k "$deb" | cut -f1) KiB ($(stat -c %s "$deb") bytes)"

# lintian: errors fail the test; warnings are listed
lintian "$changes" >"$WORK/lintian.txt" 2>&1 || true
lintian -I -E --pedantic "$changes" >"$WORK/lintian-all.txt" 2>&1 || true
lintian_e=$(grep -c '^E: ' "$WORK/lintian.txt" || true)
lintian_w=$(grep -c '^W: ' "$WORK/lintian.txt" || true)
say "lintian: $lintian_e errors, $lintian_w warnings ($WORK/lintian.txt; with info and pedantic tags: $WORK/lintian-all.txt)"
grep -E '^[EW]: ' "$WORK/lintian.txt" | sed 's/^/  /' || true
[[ "$lintian_e" -eq 0 ]] || fail "lintian reports errors"

# install
installed_here=1
apt-get install -y -qq "$deb" >"$WORK/install.log" 2>&1 || { cat "$WORK/install.log"; fail "apt-get install $deb"; }
say "installed: $(dpkg-query -W -f='${Package} ${Version}, ${Installed-Size} KiB installed' "$PKG")"

# use it, from a folder outside the source tree, with the system's interpreter
run_dir="$WORK/run"
rm -rf "$run_dir"
mkdir -p "$run_dir"
cd "$run_dir"
# the package in a folder of its own (python3-yade, the reference, owns dist-packages/yade), on python3's
# sys.path through a .pth file
PYDIR=/usr/lib/yade-fast
for f in /usr/bin/yade-fast $PYDIR/yade/__init__.py $PYDIR/yade/qt/__init__.py /usr/lib/python3/dist-packages/yade-fast.pth \
         /usr/share/doc/$PKG/copyright /usr/share/man/man1/yade-fast.1.gz; do
    [[ -e "$f" ]] || fail "$f is not installed"
done
ls $PYDIR/yade/_yade*.so >/dev/null || fail "the extension _yade*.so is not installed"
[[ -e /usr/share/doc/$PKG/README.md || -e /usr/share/doc/$PKG/README.md.gz ]] || fail "README.md is not installed"

yade-fast -v | grep -q '^Yade ' || fail "yade-fast -v"
yade-fast -n -x "$WORK/src/examples/bouncing-sphere.py" >"$WORK/example.log" 2>&1 \
    || { cat "$WORK/example.log"; fail "yade-fast -n -x examples/bouncing-sphere.py"; }
grep -q 'first rebound' "$WORK/example.log" || { cat "$WORK/example.log"; fail "the example's output"; }
say "yade-fast -n -x examples/bouncing-sphere.py: ok ($(head -1 "$WORK/example.log"))"

set +e
yade-fast --test >/dev/null 2>"$WORK/test-option.log"
rc=$?
set -e
[[ $rc -eq 2 ]] && grep -q 'source tree' "$WORK/test-option.log" || fail "yade-fast --test should say it needs the source tree (status $rc)"

# plain python3: `import yade` gets this package, unless python3-yade (the reference) is installed too: its
# dist-packages/yade comes before the .pth's folder; then the folder must at least be on sys.path
code='
import yade
from yade import O, utils
O.bodies.append(utils.sphere((0, 0, 0), 1))
O.dt = 1e-4
O.run(10, True)
print(yade.__file__, O.iter, len(O.bodies))
'
expected="$PYDIR/yade/__init__.py 10 1"
if dpkg -s python3-yade >/dev/null 2>&1; then
    env -u PYTHONPATH /usr/bin/python3 -c "import sys; assert '$PYDIR' in sys.path, sys.path" \
        || fail "$PYDIR is not on /usr/bin/python3's sys.path"
    out=$(env -u PYTHONPATH /usr/bin/python3 -c "import sys; sys.path.insert(0, '$PYDIR')
$code") || fail "python3 -c \"import yade ...\""
    [[ "$out" == "$expected" ]] || fail "python3 -c 'import yade': $out"
    say "/usr/bin/python3 -c 'import yade ...': ok ($out; python3-yade is installed too, so $PYDIR was put first)"
else
    out=$(env -u PYTHONPATH /usr/bin/python3 -c "$code") || fail "python3 -c \"import yade ...\""
    [[ "$out" == "$expected" ]] || fail "python3 -c 'import yade': $out"
    say "/usr/bin/python3 -c 'import yade ...': ok ($out)"
fi

if [[ -e /usr/bin/yade-fast-batch ]]; then
    cat >table.txt <<'EOF'
description  radius
small        0.5
large        1.5
EOF
    cat >job.py <<'EOF'
readParamsFromTable(radius=1.0)
from yade.params import table
O.bodies.append(sphere((0, 0, 0), table.radius))
print('radius', O.bodies[0].shape.radius)
EOF
    yade-fast-batch --no-http -j 2 table.txt job.py >"$WORK/batch.log" 2>&1 \
        || { cat "$WORK/batch.log"; fail "yade-fast-batch table.txt job.py"; }
    grep -q 'radius 0.5' job.py.small.log && grep -q 'radius 1.5' job.py.large.log \
        || { cat "$WORK/batch.log" job.py.*.log; fail "yade-fast-batch's job logs"; }
    say "yade-fast-batch --no-http table.txt job.py: ok (2 jobs)"
else
    say "yade-fast-batch is not in the package (the source tree had no yade-batch)"
fi

# remove
if [[ "${KEEP:-0}" == 1 ]]; then
    say "KEEP=1: $PKG stays installed"
else
    apt-get remove -y -qq "$PKG" >"$WORK/remove.log" 2>&1 || { cat "$WORK/remove.log"; fail "apt-get remove $PKG"; }
    is_installed() { [[ "$(dpkg-query -W -f='${Status}' "$PKG" 2>/dev/null || true)" == *" installed" ]]; }
installed_here=0
    [[ ! -e /usr/bin/yade-fast && ! -e $PYDIR && ! -e /usr/lib/python3/dist-packages/yade-fast.pth ]] \
        || fail "files left after apt-get remove: $(ls -d /usr/bin/yade-fast* $PYDIR /usr/lib/python3/dist-packages/yade-fast.pth 2>/dev/null)"
    say "apt-get remove $PKG: ok, nothing left"
fi
say "PASSED (build ${build_s} s, $(stat -c %s "$deb") bytes, lintian $lintian_e E / $lintian_w W; $WORK)"
