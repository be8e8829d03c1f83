#!/usr/bin/env bash
# Configures the project (Release) in build/ and builds every target, or only
# the TARGETs named: `build.sh walkers` builds the program alone, without the
# tests, benchmarks and fuzz targets.
#   build.sh [TARGET...]
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
targets=()
for target in "$@"; do targets+=(--target "$target"); done
cmake --build build -j"$(nproc)" "${targets[@]}"
