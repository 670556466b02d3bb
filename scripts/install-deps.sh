#!/usr/bin/env bash
# Installs the Debian 12 packages dockgrammar builds with (needs root; skips apt when all are present).
set -euo pipefail
packages=(build-essential cmake ninja-build ccache pkg-config libcgal-dev libopenmesh-dev libembree-dev
  libeigen3-dev libopenvdb-dev libtbb-dev libboost-iostreams-dev catch2 libcli11-dev nlohmann-json3-dev
  libfmt-dev libpng-dev)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "installing: ${missing[*]}" >&2
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
