#!/usr/bin/env bash
# Installs tessbench's dependencies from Debian 12 packages. Idempotent: apt skips what is
# already installed. Run as root (or with sudo).
#   scripts/install_deps.sh          everything: build, run, tests, sanitizers, fuzzing, benchmarks
#   scripts/install_deps.sh --run    only what building and running `tessbench` needs
#                                    (README command 1; scripts/test.sh installs the rest)
set -euo pipefail

run_packages=(
  build-essential cmake git pkg-config python3 ccache
  libosd-dev libembree-dev libopenexr-dev
  glslang-tools glslang-dev spirv-tools
  mesa-vulkan-drivers libvulkan-dev vulkan-tools
  libtinyobjloader-dev libtinygltf-dev nlohmann-json3-dev libcli11-dev libfmt-dev
  libmeshoptimizer-dev libtbb-dev libpng-dev libsqlite3-dev
  libjs-chart.js
)
test_packages=(
  python3-scipy vulkan-validationlayers
  libbenchmark-dev libbenchmark-tools libgtest-dev
  valgrind chromium
  clang-14 libfuzzer-14-dev clang-format-14
)

packages=("${run_packages[@]}")
case "${1:-}" in
  --run) ;;
  "") packages+=("${test_packages[@]}") ;;
  *) echo "install_deps: unknown option '$1' (use --run, or nothing for every package)" >&2; exit 2 ;;
esac

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
