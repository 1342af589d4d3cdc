#!/usr/bin/env bash
# Installs the Debian 12 packages ctab needs, only those that are missing.
#   scripts/install_deps.sh          what `make`, `make test` and `make sanitize` need
#   scripts/install_deps.sh --fuzz   that and clang with its sanitizer, libFuzzer and OpenMP runtimes (`make fuzz-ci`)
set -euo pipefail
packages=(cmake ninja-build g++ make pkg-config libeigen3-dev libhdf5-dev zlib1g-dev libgtest-dev googletest
          libbenchmark-dev libcli11-dev ccache libtomlplusplus-dev nlohmann-json3-dev
          python3-matplotlib python3-h5py python3-numpy openmpi-bin libopenmpi-dev)
if [ "${1:-}" = "--fuzz" ]; then
  packages+=(clang libclang-rt-14-dev libomp-14-dev)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "ctab: installing missing Debian packages: ${missing[*]}"
if [ "$(id -u)" -ne 0 ]; then
  echo "ctab: need root to install packages (run as root, or install them by hand): ${missing[*]}" >&2
  exit 1
fi
export DEBIAN_FRONTEND=noninteractive
apt-get update -q
apt-get install -y -q --no-install-recommends "${missing[@]}"
