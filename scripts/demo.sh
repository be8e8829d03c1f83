#!/usr/bin/env bash
# The main job: set up, build, and run the walker. Writes its results to runs/demo/.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
./scripts/build.sh
mkdir -p runs/demo
./build/app/walkers simulate --genome data/genomes/default.json --duration 5 --trajectory runs/demo/planted.csv
echo "trajectory written to runs/demo/planted.csv"
