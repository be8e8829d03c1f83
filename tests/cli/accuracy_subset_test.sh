#!/usr/bin/env bash
# The accuracy criterion (docs/performance.md, "Accuracy") at the production
# settings, on a small subset of its wider set judged as one set: a regular
# biped of the authors' (benchmark set), a faller (benchmark set) and a walker
# of our free run that stalls near fitness 1 (data/genomes/sampled/),
# ensembles of 25 with the start perturbed (control/accuracy.h) against 100x
# tighter tolerances; then its saved reference reused.
#   accuracy_subset_test.sh ACCURACY_PROGRAM SOURCE_DIR PYTHON
set -euo pipefail
accuracy=$1 source=$2 python=$3
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$accuracy" --ensemble 25 --threads 2 --json "$out/accuracy.json" \
  "$source/data/genomes/bench/authors_case1_biped.json" "$source/data/genomes/bench/evolved_faller.json" \
  "$source/data/genomes/sampled/sample_free_g11_c9.json"
"$python" "$source/scripts/accuracy.py" "$out/accuracy.json"
# the reference saved by that run, reused (--reference): the faller's
# production ensemble evaluated again and its reference taken from the file
# are the run's, bit for bit
"$accuracy" --ensemble 25 --threads 2 --reference "$out/accuracy.json" --json "$out/again.json" \
  "$source/data/genomes/bench/evolved_faller.json"
"$python" - "$out/accuracy.json" "$out/again.json" <<'PY'
import json, sys
first, again = (json.load(open(path)) for path in sys.argv[1:])
faller = next(g for g in first["genomes"] if g["genome"] == "evolved_faller")
(reused,) = again["genomes"]
for side in ("production", "tight"):
    for key in ("fitness", "bipeds", "tripods", "falls"):
        assert reused[side][key] == faller[side][key], f"{side}.{key}: {reused[side][key]} != {faller[side][key]}"
assert again["reference"]["files"] == [sys.argv[1]], again["reference"]
PY
