#!/usr/bin/env bash
# Wall time per evaluation of a small reproduction (3 cases x 2 replicates x
# G generations, 96·G evaluations), from the command's start to the last
# run's archive.json (the claims and figures are skipped), in one session:
#   scaling.sh side-by-side [G] [ROUNDS]   --runs-at-once 2 against 1 on 2 threads, alternating
#   scaling.sh ranks [G]                    1 and 2 threads, mpirun -n 1, 2 and 3
# Prints one line per reproduction; docs/cluster.md quotes the medians.
set -euo pipefail
cd "$(dirname "$0")/.."
walkers=$PWD/build/app/walkers
mode=${1:?side-by-side or ranks}
generations=${2:-8}
rounds=${3:-3}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
export WALKERS_PYTHON=/bin/true OMPI_MCA_plm_rsh_agent=
mpirun="mpirun --oversubscribe --allow-run-as-root"

# measure LABEL LAUNCHER OPTIONS: the wall time per evaluation of the
# reproduction with OPTIONS, started by LAUNCHER (mpirun, or none)
measure() {
  local label=$1 dir=$out/$RANDOM$RANDOM start end launcher options
  read -ra launcher <<<"$2"
  read -ra options <<<"$3"
  start=$(date +%s.%N)
  "${launcher[@]}" "$walkers" reproduce --generations "$generations" --replicates 2 "${options[@]}" --out "$dir" \
    >"$dir.log" 2>&1 </dev/null
  end=$(stat -c %.9Y "$dir"/*/archive.json | sort -n | tail -1)
  python3 -c "print(f'$label: {($end - $start) / (96 * $generations) * 1000:.1f} ms per evaluation ({$end - $start:.1f} s)')"
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
