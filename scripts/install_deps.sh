#!/usr/bin/env bash
# Installs tessbench's build and run dependencies from Debian 12 packages.
# Idempotent: apt skips what is already installed. Run as root (or with sudo).
set -euo pipefail

packages=(
  build-essential cmake git pkg-config python3 python3-scipy
  libosd-dev libembree-dev libopenexr-dev
  glslang-tools glslang-dev spirv-tools
  mesa-vulkan-drivers libvulkan-dev vulkan-tools vulkan-validationlayers
  libbenchmark-dev libbenchmark-tools libgtest-dev
  libtinyobjloader-dev nlohmann-json3-dev libcli11-dev libfmt-dev
  libmeshoptimizer-dev libtbb-dev libpng-dev
  valgrind
  chromium libjs-chart.js
  clang-14 libfuzzer-14-dev
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#packages[@]} packages already installed"
  exit 0
fi
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
echo "install_deps: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
