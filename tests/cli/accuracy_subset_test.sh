#!/usr/bin/env bash
# The accuracy criterion (docs/performance.md, "Accuracy") at the production
# settings, on a small subset of the benchmark set: a regular biped of the
# authors' and a faller, ensembles of 25 against 100x tighter tolerances.
#   accuracy_subset_test.sh ACCURACY_PROGRAM SOURCE_DIR PYTHON
set -euo pipefail
accuracy=$1 source=$2 python=$3
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$accuracy" --ensemble 25 --threads 2 --json "$out/accuracy.json" \
  "$source/data/genomes/bench/authors_case1_biped.json" "$source/data/genomes/bench/evolved_faller.json"
"$python" "$source/scripts/accuracy.py" "$out/accuracy.json"
