#!/usr/bin/env bash
# Configures and builds dockgrammar into the folder given first; further arguments go to CMake.
# Example: scripts/build.sh build -DCMAKE_BUILD_TYPE=Release
set -euo pipefail
dir=${1:?usage: scripts/build.sh BUILD_DIR [cmake options]}
shift
root=$(cd "$(dirname "$0")/.." && pwd)
# ccache (when present): hits across clones in different folders, and files compiled with a
# precompiled header cached (it needs these sloppiness settings for them).
export CCACHE_BASEDIR="$root"
export CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
cmake -S "$root" -B "$dir" -G Ninja "$@" >/dev/null
cmake --build "$dir" -j "$(nproc)"
