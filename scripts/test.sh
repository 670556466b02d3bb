#!/usr/bin/env bash
# Installs what is needed, builds the test suite with AddressSanitizer + UndefinedBehaviorSanitizer
# and runs it. (Optimized builds are exercised by scripts/example.sh and the benchmarks.)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
bash scripts/install-deps.sh
export CCACHE_DIR=${CCACHE_DIR:-$HOME/.cache/ccache}
export CCACHE_BASEDIR="$root"  # cache hits across clones in different folders

echo "== sanitizer build (ASan + UBSan) and tests" >&2
# -O1 without debug info keeps the sanitizer build fast on 2 cores; reports still name functions.
bash scripts/build.sh build-asan -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O1" -DDOCKGRAMMAR_SANITIZE=ON -DDOCKGRAMMAR_BENCH=ON -DDOCKGRAMMAR_TESTS=ON
(cd build-asan && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j "$(nproc)")
