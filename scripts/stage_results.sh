#!/usr/bin/env bash
# Stages the finished runs of a reproduction as results to commit
# (docs/results/), leaving out the per-evaluation data (each run's
# evaluations.csv; its finals.json keeps what the statistics need):
#  - the runs of replicates 1..R, with the reproduction's files, statistics and
#    figures remade over them (n = R runs a case), so that
#    `walkers reproduce --replicates R --resume` on the staged folder remakes
#    the same files;
#  - every other finished run, kept as it is, so that it is not lost before
#    its replicate is complete in every case: the experiment continues from the
#    committed runs on another machine (docs/cli.md, `reproduce`: the run
#    folders copied into a new folder and resumed there).
#
#   scripts/stage_results.sh FROM R TO [reproduce options: --authors-checkout PATH ...]
#
# FROM is a reproduction's folder (the paper's experiment, runs/paper); every
# run of replicates 1..R must have finished (R = 0: no statistics, the finished
# runs only). In TO, the staged files and run folders replace their namesakes;
# nothing else of TO is touched. WALKERS names the program (build/app/walkers
# by default), WALKERS_PYTHON the Python of the statistics (as the program
# picks it: /usr/bin/python3 where there is one, else python3). Under a
# cut-off, each run's cut-offs per generation are kept in its cut_offs.csv
# (`walkers_stats cut-offs`) before its evaluations.csv is left out.
set -euo pipefail
from=${1:?the reproduction folder} replicates=${2:?how many replicates} to=${3:?the folder to stage into}
shift 3
walkers=${WALKERS:-build/app/walkers}
python=${WALKERS_PYTHON:-$([ -x /usr/bin/python3 ] && echo /usr/bin/python3 || echo python3)}

staging=$(mktemp -d "${to%/}.staging.XXXXXX")
trap 'rm -rf "$staging"' EXIT
# copy_run RUN FILE...: the run's folder in the staging area, with those files
copy_run() {
  local run=$1
  shift
  mkdir "$staging/$(basename "$run")"
  for f in "$@"; do cp -p "$run/$f" "$staging/$(basename "$run")/"; done
}
generations=
kept=()  # finished runs beyond replicate R
for run in "$from"/*-[0-9]*/; do
  run=${run%/}
  replicate=${run##*-}
  if [ "$replicate" -gt "$replicates" ]; then
    [ -f "$run/best.json" ] && kept+=("$run")
    continue
  fi
  if [ ! -f "$run/best.json" ]; then
    echo "stage_results: $run has not finished; stage whole runs only" >&2
    exit 1
  fi
  g=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["generations"])' "$run/config.json")
  if [ -n "$generations" ] && [ "$g" != "$generations" ]; then
    echo "stage_results: $run has $g generations, another run $generations" >&2
    exit 1
  fi
  generations=$g
  # a run continued from committed results has its finals.json but no evaluations.csv
  files=(config.json checkpoint.json generations.csv archive.json best.json)
  for f in evaluations.csv finals.json cut_offs.csv; do [ -f "$run/$f" ] && files+=("$f"); done
  if [ ! -f "$run/evaluations.csv" ] && [ ! -f "$run/finals.json" ]; then
    echo "stage_results: $run has neither evaluations.csv nor finals.json; its finals cannot be read" >&2
    exit 1
  fi
  copy_run "$run" "${files[@]}"
done
if [ "$replicates" -gt 0 ] && [ -z "$generations" ]; then
  echo "stage_results: no runs of replicates 1..$replicates in $from" >&2
  exit 1
fi
for run in "${kept[@]}"; do
  if [ ! -f "$run/finals.json" ]; then
    echo "stage_results: $run has finished but has no finals.json; resume the reproduction to write it" >&2
    exit 1
  fi
  files=(config.json checkpoint.json generations.csv archive.json best.json finals.json)
  for f in evaluations.csv cut_offs.csv; do [ -f "$run/$f" ] && files+=("$f"); done
  copy_run "$run" "${files[@]}"
done
[ "$replicates" -gt 0 ] || [ ${#kept[@]} -gt 0 ] || { echo "stage_results: no finished runs in $from" >&2; exit 1; }

# an earlier staging's re-scores are kept: ensembles already made are not made again
[ -f "$to/rescores.json" ] && cp -p "$to/rescores.json" "$staging/"

# every run has finished: --resume makes no generation, only the finals' re-scores,
# reproduction.json, the statistics and the figures
if [ "$replicates" -gt 0 ]; then
  "$walkers" reproduce --replicates "$replicates" --generations "$generations" --resume --out "$staging" "$@"
fi
# the cut-offs outlive the per-evaluation data (runs without a cut-off have none to keep)
with_evaluations=()
for run in "$staging"/*/; do [ -f "$run/evaluations.csv" ] && with_evaluations+=("${run%/}"); done
if [ ${#with_evaluations[@]} -gt 0 ]; then
  "$python" "$(dirname "$0")/walkers_stats" cut-offs "${with_evaluations[@]}" >/dev/null
fi
rm -f "$staging"/*/evaluations.csv "$staging"/*/walkers.lock "$staging"/walkers.lock
# into TO, each staged file or run folder replacing its namesake; TO's other contents stay
mkdir -p "$to"
for item in "$staging"/*; do
  rm -rf "${to:?}/$(basename "$item")"
  mv "$item" "$to/"
done
echo "staged ${replicates} replicates a case of $from in $to, and ${#kept[@]} finished runs beyond them"
