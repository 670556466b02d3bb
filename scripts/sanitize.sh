#!/usr/bin/env bash
# Installs what is needed, builds the test suite with AddressSanitizer + UndefinedBehaviorSanitizer
# and runs it: the check for memory errors, leaks and undefined behaviour run before each landing
# (about 70 minutes on 2 cores from an empty ccache, too long for CI; scripts/test.sh is CI's).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
bash scripts/install-deps.sh

echo "== sanitizer build (ASan + UBSan) and tests" >&2
# -O1 without debug info keeps the sanitizer build fast on 2 cores; reports still name functions.
bash scripts/build.sh build-asan -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O1" -DDOCKGRAMMAR_SANITIZE=ON -DDOCKGRAMMAR_BENCH=OFF -DDOCKGRAMMAR_TESTS=ON
(cd build-asan && ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 ctest --output-on-failure -j "$(nproc)")
