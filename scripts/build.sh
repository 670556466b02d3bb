#!/usr/bin/env bash
# Configures and builds dockgrammar into the folder given first; further arguments go to CMake.
# Example: scripts/build.sh build -DCMAKE_BUILD_TYPE=Release
set -euo pipefail
dir=${1:?usage: scripts/build.sh BUILD_DIR [cmake options]}
shift
root=$(cd "$(dirname "$0")/.." && pwd)
cmake -S "$root" -B "$dir" -G Ninja "$@" >/dev/null
cmake --build "$dir" -j "$(nproc)"
