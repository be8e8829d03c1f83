#!/usr/bin/env bash
# Installs the Debian 12 packages this project needs, when they are missing.
# Run as root (or with sudo available). Nothing is downloaded at build or run time.
#   setup.sh            what building and running need
#   setup.sh --test     and what the tests need: Chromium, to check the replay page;
#                       clang and its libFuzzer runtime, for the loaders' fuzz targets;
#                       Open MPI, for the runs shared over MPI ranks (docs/cluster.md);
#                       pybind11, NumPy and pytest, for the Python module and its tests (docs/python.md);
#                       valgrind, for the instruction guard (scripts/instruction_guard.py)
#   setup.sh --authors  and what building the authors' program for scripts/compare_authors.py needs
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libeigen3-dev libsundials-dev libgtest-dev libbenchmark-dev libcli11-dev nlohmann-json3-dev libpagmo-dev
  python3 python3-matplotlib python3-scipy
)
case "${1:-}" in
  --test) packages+=(chromium clang libclang-rt-14-dev libopenmpi-dev openmpi-bin
                   pybind11-dev python3-numpy python3-pytest valgrind) ;;
  --authors) packages+=(libsimbody-dev libarmadillo-dev) ;;
esac

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
