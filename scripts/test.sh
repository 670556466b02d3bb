#!/usr/bin/env bash
# Installs what is needed, builds dockgrammar, its tests and benchmark programs optimized, and
# runs the test suite (CI's command; scripts/sanitize.sh runs the same tests under ASan + UBSan).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
bash scripts/install-deps.sh

echo "== optimized build and tests" >&2
bash scripts/build.sh build -DCMAKE_BUILD_TYPE=Release -DDOCKGRAMMAR_BENCH=ON -DDOCKGRAMMAR_TESTS=ON
(cd build && ctest --output-on-failure -j "$(nproc)")
