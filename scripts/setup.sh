#!/usr/bin/env bash
# Installs everything sphslope needs on a fresh Debian 12 machine. Safe to run more than once.
set -euo pipefail
packages=(g++ cmake make ninja-build python3 python3-jsonschema libeigen3-dev libcgal-dev nlohmann-json3-dev libvalijson-dev libgsl-dev libgdal-dev libdxflib-dev catch2 libcli11-dev
          libomp-dev clang libclang-rt-14-dev pmccabe universal-ctags libxml2-utils chromium poppler-utils fonts-dejavu-core)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all packages present"
  exit 0
fi
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
echo "setup: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
