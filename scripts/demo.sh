#!/usr/bin/env bash
# The main job, short: set up, build the program (only what the demo runs),
# evolve the three scaffolds for 30 generations (one replicate each) with
# progress on the terminal, re-score their finals, then write the statistics
# and the paper's figures to runs/demo/.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
./scripts/build.sh walkers
# run again, the demo continues (or only redraws) what an earlier one left
again=()
[ -d runs/demo ] && again=(--resume)
./build/app/walkers reproduce --generations 30 --replicates 1 --out runs/demo "${again[@]}"
./build/app/walkers replay --genome runs/demo/performance-1/best.json --out runs/demo/walk.html --force
echo
echo "statistics: runs/demo/summary.md (with the claims' verdicts)"
echo "figures:    runs/demo/figures/ (fig4a ... fig9, finals; PNG and SVG)"
echo "animation:  runs/demo/walk.html (open it in a browser)"
