#!/usr/bin/env bash
# walkers under mpirun with 3 ranks: a tiny evolve and a tiny reproduction
# write the files one process writes; the whole job killed (SIGKILL) at a
# random moment and resumed ends with the same files; a rank killed mid-run
# ends the job with an error naming the rank, and the job then resumes to the
# same files; a rank that hangs, mid-run or after the last evaluation, ends it
# after --rank-timeout. No check waits unbounded: a job that does not end is a
# failure, and is killed.
# Usage: mpi_test.sh WALKERS_BINARY MPIEXEC PYTHON
set -u
walkers=$1
mpiexec=$2
python=$3
tmp=$(mktemp -d)
cleanup() {
  # a job left running by a failed check (its own process group)
  [ -n "${job:-}" ] && kill_job
  rm -rf "$tmp"
}
trap cleanup EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# ok CHECK: "ok" if nothing failed since the last check
reported=0
ok() {
  if [ $failures -eq $reported ]; then echo "ok: $*"; else echo "not ok: $*"; fi
  reported=$failures
}
# in a container as root, with no ssh: every rank on this machine
export OMPI_MCA_plm_rsh_agent=
# no cross-memory attach in containers without ptrace
export OMPI_MCA_btl_vader_single_copy_mechanism=none
export WALKERS_PYTHON=$python
mpi=("$mpiexec" --oversubscribe --allow-run-as-root -n 3)
# a job in the foreground, ended if it hangs
fg=(timeout 300 "${mpi[@]}")

# same_files A B: every file but checkpoints, locks and figures, the CSV
# files without their wall-clock column and summary.* without the times
same_files() {
  local f rel
  while IFS= read -r f; do
    rel=${f#"$1"/}
    case $rel in
      *checkpoint.json | *walkers.lock | figures/* | summary.md) continue ;;
      *.csv) cmp -s <(sed 's/,[^,]*$//' "$f") <(sed 's/,[^,]*$//' "$2/$rel") || fail "$2/$rel differs from $f" ;;
      summary.json) cmp -s <(grep -v 'seconds\|evals_per_s' "$f") <(grep -v 'seconds\|evals_per_s' "$2/$rel") ||
        fail "$2/$rel differs from $f" ;;
      *) cmp -s "$f" "$2/$rel" || fail "$2/$rel differs from $f" ;;
    esac
  done < <(find "$1" -type f | sort)
  [ "$(cd "$1" && find . -type f | grep -v 'figures/' | sort)" = "$(cd "$2" && find . -type f | grep -v 'figures/' | sort)" ] ||
    fail "$2 does not hold the files $1 holds"
}

# SIGKILL to the job whose mpirun is $job: mpirun and its ranks
kill_job() {
  kill -9 "$job" $(pgrep -P "$job") 2>/dev/null
}

# the pid of rank R of the job whose mpirun is $job
rank_pid() {
  local p
  for p in $(pgrep -P "$job"); do
    if tr '\0' '\n' <"/proc/$p/environ" 2>/dev/null | grep -qx "OMPI_COMM_WORLD_RANK=$1"; then
      echo "$p"
      return
    fi
  done
}

# wait_job LIMIT: the exit status of the job $job, killed (and a failure) if
# it has not ended within LIMIT s
wait_job() {
  local tenths=0
  while kill -0 "$job" 2>/dev/null; do
    if [ $tenths -ge $(($1 * 10)) ]; then
      fail "the job has not ended within $1 s"
      kill_job
      break
    fi
    sleep 0.1
    tenths=$((tenths + 1))
  done
  wait "$job"
}

# await_line FILE TEXT: waits up to 60 s for TEXT in FILE and for rank 1 and 2
await_line() {
  for _ in $(seq 300); do
    [ -n "$(rank_pid 1)" ] && [ -n "$(rank_pid 2)" ] && grep -q -- "$2" "$1" && return
    sleep 0.2
  done
  fail "no '$2' in $1 within 60 s"
}

# ends_naming OUT PATTERN WHAT: the job $job, just disturbed, ends within
# 60 s with a non-zero status and PATTERN in its output OUT
ends_naming() {
  local start=$SECONDS status
  wait_job 120
  status=$?
  job=
  [ $status -ne 0 ] || fail "$3: exit status 0"
  [ $((SECONDS - start)) -le 60 ] || fail "$3: the job took $((SECONDS - start)) s to end"
  grep -q -- "$2" "$1" || { cat "$1"; fail "$3: no error matching '$2'"; }
}

# start_job OUT ARGS...: mpirun in the background ($job)
start_job() {
  local out=$1
  shift
  "${mpi[@]}" "$walkers" "$@" >"$out" 2>&1 &
  job=$!
}

# a tiny evolve
run=(evolve --case time --population 6 --archive 6 --mutation-children 3 --seed 4)
"$walkers" "${run[@]}" --generations 4 --threads 1 --out "$tmp/one" >"$tmp/one.txt" 2>&1 || { cat "$tmp/one.txt"; fail "evolve in one process"; }
"${fg[@]}" "$walkers" "${run[@]}" --generations 4 --out "$tmp/mpi" >"$tmp/mpi.txt" 2>&1 || { cat "$tmp/mpi.txt"; fail "evolve under mpirun"; }
same_files "$tmp/one" "$tmp/mpi"
ok "evolve on 3 ranks writes the files of one process"

# bad arguments are refused on rank 0, with the usual message, and no rank waits
timeout 60 "${mpi[@]}" "$walkers" evolve --case bogus --out "$tmp/bad" >"$tmp/bad.txt" 2>&1
status=$?
[ $status -ne 0 ] && [ $status -ne 124 ] || fail "bad arguments under mpirun: exit status $status"
grep -q -- '--case: bogus not in {free,time,performance}' "$tmp/bad.txt" || { cat "$tmp/bad.txt"; fail "no message for --case bogus"; }
[ "$(grep -c 'bogus not in' "$tmp/bad.txt")" = 1 ] || fail "the message is printed by more than rank 0"
ok "bad arguments refused by rank 0"

# a tiny reproduction (two replicates, so ranks share whole runs)
rep=(reproduce --generations 2 --replicates 2 --seed 2 --ensemble 3)
"$walkers" "${rep[@]}" --threads 1 --runs-at-once 1 --out "$tmp/rep-one" >"$tmp/rep-one.txt" 2>&1 ||
  { cat "$tmp/rep-one.txt"; fail "reproduce in one process"; }
"${fg[@]}" "$walkers" "${rep[@]}" --out "$tmp/rep-mpi" >"$tmp/rep-mpi.txt" 2>&1 ||
  { cat "$tmp/rep-mpi.txt"; fail "reproduce under mpirun"; }
grep -q '6 runs, 3 at once, on 3 MPI ranks' "$tmp/rep-mpi.txt" || { cat "$tmp/rep-mpi.txt"; fail "no line saying the ranks"; }
same_files "$tmp/rep-one" "$tmp/rep-mpi"
ok "reproduce on 3 ranks writes the files of one process"

# the whole job killed with SIGKILL at a random moment, then resumed
long=("${run[@]}" --generations 8)
"$walkers" "${long[@]}" --threads 2 --out "$tmp/whole" >/dev/null 2>&1 || fail "evolve in one process"
start_job "$tmp/killed.txt" "${long[@]}" --out "$tmp/killed"
sleep $((RANDOM % 4 + 2)).$((RANDOM % 10))
kill_job
wait "$job" 2>/dev/null
job=
mode=--resume
[ -f "$tmp/killed/config.json" ] || mode=--force
"${fg[@]}" "$walkers" "${long[@]}" --out "$tmp/killed" $mode >"$tmp/resumed.txt" 2>&1 || { cat "$tmp/resumed.txt"; fail "the resume"; }
same_files "$tmp/whole" "$tmp/killed"
ok "a job SIGKILLed and resumed ends with the same files"

# a rank killed mid-run: the job ends, naming it; resumed, the same files
start_job "$tmp/dead.txt" "${long[@]}" --out "$tmp/dead"
await_line "$tmp/dead.txt" 'gen 1/'
kill -9 "$(rank_pid 2)"
ends_naming "$tmp/dead.txt" 'rank 2' "a killed rank"
"${fg[@]}" "$walkers" "${long[@]}" --out "$tmp/dead" --resume >"$tmp/dead-resumed.txt" 2>&1 ||
  { cat "$tmp/dead-resumed.txt"; fail "the resume after a dead rank"; }
same_files "$tmp/whole" "$tmp/dead"
ok "a killed rank ends the job naming it; resumed, the same files"

# a rank that hangs (stopped) mid-run: the job ends after --rank-timeout,
# naming it. One thread on rank 0 and 40 generations of 3 children: rank 1 is
# sent more work after it stops.
start_job "$tmp/hung.txt" "${run[@]}" --generations 40 --threads 1 --rank-timeout 10 --out "$tmp/hung"
await_line "$tmp/hung.txt" 'gen 1/'
kill -STOP "$(rank_pid 1)"
ends_naming "$tmp/hung.txt" 'MPI rank 1 has not answered for 10 s (--rank-timeout).*the job ends' "a hung rank"
ok "a rank that hangs mid-run ends the job naming it"

# a rank that hangs after the last evaluation, while rank 0 writes the
# statistics and figures: it does not answer the stop, and the job ends,
# naming it, with every file written
start_job "$tmp/late.txt" "${rep[@]}" --rank-timeout 5 --out "$tmp/late"
await_line "$tmp/late.txt" 'this session'
kill -STOP "$(rank_pid 1)"
ends_naming "$tmp/late.txt" 'MPI rank 1 has not answered for 5 s (--rank-timeout).*when told to stop (the work is done' "a rank hung at the end"
same_files "$tmp/rep-one" "$tmp/late"
ok "a rank that hangs after the work ends the job naming it, its files complete"

[ $failures -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all MPI checks passed"
