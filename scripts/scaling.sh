#!/usr/bin/env bash
# Wall time per evaluation of a small reproduction (3 cases x 2 replicates x
# G generations, 96·G evaluations), from the command's start to the last
# run's archive.json (the finals are re-scored by ensembles of one, the
# statistics and figures skipped), in one session:
#   scaling.sh side-by-side [G] [ROUNDS]   --runs-at-once 2 against 1 on 2 threads, alternating
#   scaling.sh ranks [G]                    1 and 2 threads, mpirun -n 1, 2 and 3
#   scaling.sh idle DIR                     of a reproduction made one run at a time on 2 threads:
#                                           how much of the threads' time its generations filled
# Prints one line per reproduction; docs/cluster.md quotes the medians.
set -euo pipefail
mode=${1:?side-by-side, ranks or idle}
if [ "$mode" = idle ]; then
  exec python3 - "${2:?a reproduction folder}" <<'PY'
import csv, glob, sys
# per generation: its children's own times (wall_ms) against 2 threads x the
# generation's evaluation span (children / evals_per_s)
busy = span = 0.0
for gens in sorted(glob.glob(sys.argv[1] + "/*/generations.csv")):
    own, count = {}, {}
    for row in csv.DictReader(open(gens.replace("generations.csv", "evaluations.csv"))):
        g = row["generation"]
        own[g] = own.get(g, 0.0) + float(row["wall_ms"]) / 1000
        count[g] = count.get(g, 0) + 1
    for row in csv.DictReader(open(gens)):
        g = row["generation"]
        busy += own[g]
        span += 2 * count[g] / float(row["evals_per_s"])
print(f"the children filled {100 * busy / span:.1f} % of the 2 threads' time while their generations evaluated "
      f"({span / 2:.1f} s of evaluation)")
PY
fi
cd "$(dirname "$0")/.."
walkers=$PWD/build/app/walkers
generations=${2:-8}
rounds=${3:-3}
# the reproductions go to $SCALING_OUT if set (kept, for `idle`), else to a temporary folder
if [ -n "${SCALING_OUT:-}" ]; then
  out=$SCALING_OUT
  mkdir -p "$out"
else
  out=$(mktemp -d)
  trap 'rm -rf "$out"' EXIT
fi
export WALKERS_PYTHON=/bin/true OMPI_MCA_plm_rsh_agent=
mpirun="mpirun --oversubscribe --allow-run-as-root"

# measure LABEL LAUNCHER OPTIONS: the wall time per evaluation of the
# reproduction with OPTIONS, started by LAUNCHER (mpirun, or none)
measure() {
  local label=$1 dir start end launcher options
  dir=$out/$(echo "$label" | tr -c 'a-z0-9\n' '-')
  read -ra launcher <<<"$2"
  read -ra options <<<"$3"
  start=$(date +%s.%N)
  "${launcher[@]}" "$walkers" reproduce --generations "$generations" --replicates 2 --ensemble 1 "${options[@]}" --out "$dir" \
    >"$dir.log" 2>&1 </dev/null
  end=$(stat -c %.9Y "$dir"/*/archive.json | sort -n | tail -1)
  python3 -c "print(f'$label: {($end - $start) / (96 * $generations) * 1000:.1f} ms per evaluation ({$end - $start:.1f} s), $dir')"
}

case $mode in
  side-by-side)
    for round in $(seq "$rounds"); do
      measure "round $round, 2 runs at once" "" "--threads 2 --runs-at-once 2"
      measure "round $round, 1 run at a time" "" "--threads 2 --runs-at-once 1"
    done ;;
  ranks)
    measure "1 thread" "" "--threads 1"
    measure "2 threads" "" "--threads 2"
    measure "mpirun -n 1" "$mpirun -n 1" "--threads 1"
    measure "mpirun -n 2" "$mpirun -n 2" ""
    measure "mpirun -n 3" "$mpirun -n 3" "" ;;
  *) echo "usage: scaling.sh side-by-side|ranks [GENERATIONS] [ROUNDS]" >&2; exit 2 ;;
esac
