#!/usr/bin/env bash
# Installs what is needed, builds dockgrammar, and analyzes a bundled example model.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
bash scripts/install-deps.sh
bash scripts/build.sh build -DCMAKE_BUILD_TYPE=Release -DDOCKGRAMMAR_TESTS=OFF
./build/tools/dockgrammar analyze assets/models/facade_3x4.obj -o out/example
echo "grammar, report and pictures are in out/example/"
