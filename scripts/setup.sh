#!/usr/bin/env bash
# Idempotent set-up: install missing Debian packages, configure and build.
# Usage: bash scripts/setup.sh   (from any directory)
set -euo pipefail

REPO="$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/.." && pwd)"
cd "$REPO"

PACKAGES=(build-essential cmake g++ libeigen3-dev pybind11-dev python3-dev
          python3-numpy python3-pytest ipython3 python3-matplotlib libgtest-dev time ccache
          zlib1g-dev libbz2-dev libzstd-dev pkg-config
          python3-pyqt5 python3-opengl libgl1-mesa-dri xvfb xauth ffmpeg  # the optional GUI, doc/gui.md
          libvtk9-dev python3-vtk9)  # optional VTK output (doc/vtk.md); python3-vtk9: the tests read the files back

missing=()
for p in "${PACKAGES[@]}"; do
    status="$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)"
    if [[ "$status" != "install ok installed" ]]; then
        missing+=("$p")
    fi
done

if (( ${#missing[@]} > 0 )); then
    echo "setup.sh: installing missing packages: ${missing[*]}"
    SUDO=()
    if [[ "$(id -u)" -ne 0 ]]; then
        if command -v sudo >/dev/null 2>&1; then
            SUDO=(sudo)
        else
            echo "setup.sh: not root and sudo is not available; install: ${missing[*]}" >&2
            exit 1
        fi
    fi
    "${SUDO[@]}" apt-get update -qq
    "${SUDO[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}"
fi

start=$(date +%s.%N)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPython_EXECUTABLE=/usr/bin/python3 >/dev/null
cmake --build build -j"$(nproc)"
end=$(date +%s.%N)
LC_ALL=C awk -v s="$start" -v e="$end" 'BEGIN { printf "setup.sh: build finished in %.1f s\n", e - s }'
