#!/usr/bin/env bash
# Command-line checks: each case runs `walkers` and asserts its exit code and
# what it prints. Usage: cli_test.sh WALKERS_BINARY SOURCE_DIR
set -u
walkers=$1
src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# expect CODE PATTERN -- ARGS...: exit code CODE (or "nonzero") and output matching PATTERN
expect() {
  local code=$1 pattern=$2
  shift 3
  local out rc
  out=$("$walkers" "$@" 2>&1)
  rc=$?
  if [[ $code == nonzero && $rc -eq 0 ]] || [[ $code != nonzero && $rc -ne $code ]]; then
    echo "FAIL: walkers $* exited $rc, expected $code"; echo "$out" | head -5; failures=$((failures + 1)); return
  fi
  if ! grep -Eq -- "$pattern" <<<"$out"; then
    echo "FAIL: walkers $* printed no match for /$pattern/:"; echo "$out" | head -5; failures=$((failures + 1)); return
  fi
  echo "ok: walkers $*"
}

genome=$src/data/genomes/default.json

# the commit the program was built from (or "unknown" outside a git checkout)
expect 0 '^walkers, commit ([0-9a-f]{12}(-dirty)?|unknown)$' -- --version

# simulate: the JSON summary line and a trajectory with the documented columns
expect 0 '^\{"cvode_steps":[0-9]+,"failure":null,"rhs_evals":[0-9]+,"sim_time":0\.5,"wall_ms":' -- \
  simulate --genome "$genome" --duration 0.5 --trajectory "$tmp/t.csv"
header=$(head -1 "$tmp/t.csv")
[[ $header == t,x,y,pitch,hip_l,knee_l,ankle_l,hip_r,knee_r,ankle_r,x_dot,*,ankle_r_dot,kinetic,potential,trunk_contact ]] ||
  { echo "FAIL: trajectory header: $header"; failures=$((failures + 1)); }
rows=$(($(wc -l <"$tmp/t.csv") - 1))
[[ $rows -eq 16 ]] || { echo "FAIL: 0.5 s at 30 Hz should give 16 rows (t=0 .. 0.5), got $rows"; failures=$((failures + 1)); }
expect 0 '"failure":null' -- simulate --genome "$genome" --duration 0.1 --passive

# evaluate: the JSON keys of the issue, and a trajectory with the controller's columns
expect 0 '^\{"cut_off":false,"cvode_steps":[0-9]+,"distance":[-0-9.e]+,"failure":null,"fell":false,"fitness":[-0-9.e]+,"footsteps":[0-9]+,"gait":"(biped|tripod)","integrator":"cvode","leg_length":[0-9.]+,"preset":"original","rhs_evals":[0-9]+,"sim_time":15(\.0)?,"trunk_contact_fraction":[0-9.e-]+,"wall_ms":[0-9.e+-]+\}$' -- \
  evaluate --genome "$genome" --json --trajectory "$tmp/e.csv"
# the authors' integrator, and their cut-off set low enough to cut the initial individual off
expect 0 '"integrator":"rk-merson"' -- evaluate --genome "$genome" --json --integrator rk-merson --accuracy 0.04
expect 0 '"cut_off":true,.*"fitness":-124' -- evaluate --genome "$genome" --json --integrator rk-merson --cut-off 2000
header=$(head -1 "$tmp/e.csv")
[[ $header == t,x,y,*,kinetic,potential,trunk_contact,state,x_target ]] ||
  { echo "FAIL: evaluate trajectory header: $header"; failures=$((failures + 1)); }
grep -q ',DS,' "$tmp/e.csv" && grep -Eq ',(LS|RS),' "$tmp/e.csv" ||
  { echo "FAIL: evaluate trajectory has no DS and LS/RS states"; failures=$((failures + 1)); }
expect 0 '^fitness [-0-9.]+ +\(distance' -- evaluate --genome "$genome" --preset paper
# evaluate --profile: a row per tick, the same evaluation as without it; its summary per walking state
plain=$("$walkers" evaluate --genome "$genome" --json | sed 's/"wall_ms":[^}]*//')
profiled=$("$walkers" evaluate --genome "$genome" --json --profile "$tmp/p.csv" --profile-summary "$tmp/p.json" |
  sed 's/"wall_ms":[^}]*//')
[[ $plain == "$profiled" ]] || fail "profiling changed the evaluation: $plain / $profiled"
[[ $(head -1 "$tmp/p.csv") == t,state,steps,error_test_failures,nonlinear_failures,*,switch_stop_ankle_r ]] ||
  fail "profile header: $(head -1 "$tmp/p.csv")"
[[ $(($(wc -l <"$tmp/p.csv") - 1)) -eq 450 ]] || fail "profile: 15 s at 30 Hz should give 450 rows"
grep -q '"DS": {' "$tmp/p.json" && grep -q '"limiting": {' "$tmp/p.json" || fail "profile summary: $(head -c 200 "$tmp/p.json")"
expect nonzero '--profile and --profile-summary name the same file' -- \
  evaluate --genome "$genome" --profile "$tmp/same" --profile-summary "$tmp/same"
# evaluate --ensemble: the spread under perturbations of the relative tolerance
expect 0 '"ensemble":\{"bipeds":[0-9]+,"falls":[0-9]+,"fitness":\[[-0-9.e]+,[-0-9.e]+,[-0-9.e]+\],"fitness_max":' -- \
  evaluate --genome "$genome" --ensemble 3 --json
expect 0 '^ensemble of 3 .*fitness median [-0-9.]+, min [-0-9.]+, max [-0-9.]+; [0-3] bipeds, [0-3] tripods, [0-3] falls' -- \
  evaluate --genome "$genome" --ensemble 3
expect nonzero 'ensemble: value 0 is outside the allowed range \[1, 1000\]' -- evaluate --genome "$genome" --ensemble 0

# evolve: an uninterrupted run, and the same run killed (SIGKILL) at random
# moments and resumed each time, end with the same files (but for the
# wall-clock columns, the last of each CSV row)
common=(--case performance --population 8 --archive 8 --mutation-children 5 --seed 3 --threads 2)
small=("${common[@]}" --generations 6)
expect 0 'best fitness' -- evolve "${small[@]}" --out "$tmp/whole"
# evolve_killed DIR ARGS...: the run killed (SIGKILL) at random moments and
# resumed each time until it finishes
evolve_killed() {
  local dir=$1 mode pid
  shift
  "$walkers" evolve "$@" --out "$dir" >/dev/null 2>&1 &
  pid=$!
  sleep 0.$((RANDOM % 9 + 1))
  kill -9 $pid 2>/dev/null
  wait $pid 2>/dev/null
  for attempt in 1 2 3 4 5 6 7 8 9 10; do
    [ -f "$dir/best.json" ] && break
    if [ -f "$dir/config.json" ]; then mode=--resume; else mode=--force; fi
    "$walkers" evolve "$@" --out "$dir" $mode >/dev/null 2>&1 &
    pid=$!
    sleep 0.$((RANDOM % 9 + 1))
    kill -9 $pid 2>/dev/null
    wait $pid 2>/dev/null
  done
  [ -f "$dir/best.json" ] || "$walkers" evolve "$@" --out "$dir" --resume >/dev/null 2>&1
}
# expect_same_run A B: the same files but for the wall-clock columns
expect_same_run() {
  local f
  for f in evaluations.csv generations.csv; do
    if ! cmp -s <(sed 's/,[^,]*$//' "$1/$f") <(sed 's/,[^,]*$//' "$2/$f"); then
      echo "FAIL: $2 differs from $1 in $f"; failures=$((failures + 1))
    fi
  done
  for f in archive.json best.json config.json; do
    cmp -s "$1/$f" "$2/$f" || { echo "FAIL: $2 differs from $1 in $f"; failures=$((failures + 1)); }
  done
}
evolve_killed "$tmp/killed" "${small[@]}"
expect_same_run "$tmp/whole" "$tmp/killed"
echo "ok: SIGKILLed run resumed to the same files"
expect 0 '^fitness' -- evaluate --genome "$tmp/whole/best.json"
# every other learner: on one thread uninterrupted, and on two killed and
# resumed, the same files
for learner in cmaes sade pso; do
  run=(--case time --learner $learner --population 8 --archive 8 --mutation-children 5 --seed 4 --generations 4)
  expect 0 'best fitness' -- evolve "${run[@]}" --threads 1 --out "$tmp/$learner-whole"
  grep -q "\"learner\": \"$learner\"" "$tmp/$learner-whole/config.json" || fail "config.json does not name $learner"
  evolve_killed "$tmp/$learner-killed" "${run[@]}" --threads 2
  expect_same_run "$tmp/$learner-whole" "$tmp/$learner-killed"
  echo "ok: $learner: SIGKILLed run on two threads resumed to the one-thread run's files"
done
expect nonzero "--learner: nsga2 not in \{ga,cmaes,sade,pso\}" -- evolve --case free --learner nsga2 --out "$tmp/x"
# the external learner's runs are driven from Python (walkers.Run)
expect nonzero "--learner: external not in \{ga,cmaes,sade,pso\}" -- evolve --case free --learner external --out "$tmp/x"
expect nonzero "external not in \{ga,cmaes,sade,pso\}" -- reproduce --learners ga,external --out "$tmp/x"
expect nonzero 'population = 6 is outside its allowed range \[7, 100000\] for the learner sade' -- \
  evolve --case free --learner sade --population 6 --mutation-children 3 --out "$tmp/x"
expect nonzero "learners: 'cmaes' is given twice" -- reproduce --learners cmaes,ga,cmaes --out "$tmp/x"
[ ! -e "$tmp/x" ] || fail "a refused command created its --out folder"


# bad input: a clear message and a non-zero exit
sed 's/"kStep": [0-9.]*/"kStep": 900/' "$genome" >"$tmp/bad.json"
expect nonzero "bad.json: gene 'kStep' = 900 is outside its allowed range \[0, 800\]" -- \
  simulate --genome "$tmp/bad.json" --duration 1
expect nonzero 'duration' -- simulate --genome "$genome" --duration -1
expect nonzero 'duration' -- simulate --genome "$genome" --duration nan
expect nonzero 'genome' -- simulate --genome "$tmp/absent.json" --duration 1
expect nonzero 'cannot write the trajectory' -- simulate --genome "$genome" --duration 0.1 --trajectory "$tmp/no/such/dir/t.csv"
expect nonzero 'preset.*(paper|original)' -- evaluate --genome "$genome" --preset authors
expect nonzero 'integrator.*(cvode|rk-merson)' -- evaluate --genome "$genome" --integrator euler
expect nonzero 'accuracy applies to the rk-merson integrator only' -- evaluate --genome "$genome" --accuracy 0.01
expect nonzero 'accuracy' -- evaluate --genome "$genome" --integrator rk-merson --accuracy 2
expect nonzero 'cut-off' -- evaluate --genome "$genome" --integrator rk-merson --cut-off soon
expect nonzero 'accuracy applies to the rk-merson integrator only' -- evolve --case free --accuracy 0.01 --out "$tmp/acc"
expect nonzero "bad.json: gene 'kStep'" -- evaluate --genome "$tmp/bad.json"
expect nonzero 'case.*free.*time.*performance' -- evolve --case scaffolded --out "$tmp/x"
expect nonzero 'generations' -- evolve --case free --generations 0 --out "$tmp/x"
expect nonzero 'holds a run already; pass --resume' -- evolve "${small[@]}" --out "$tmp/whole"
expect nonzero 'cannot create the run directory' -- evolve --case free --out "$tmp/t.csv/run"
expect nonzero 'no run to resume' -- evolve --case free --out "$tmp/empty" --resume
expect nonzero 'seed = 3 but 4' -- evolve --case performance --generations 6 --population 8 --archive 8 --mutation-children 5 --seed 4 --out "$tmp/whole" --resume
expect nonzero 'simulate|Usage|subcommand' --

# nothing lost, ever
# same_run A B: the same files but for the wall-clock columns
same_run() {
  for f in evaluations.csv generations.csv; do
    cmp -s <(sed 's/,[^,]*$//' "$1/$f") <(sed 's/,[^,]*$//' "$2/$f") || fail "$2/$f differs from $1/$f"
  done
  for f in archive.json best.json config.json; do cmp -s "$1/$f" "$2/$f" || fail "$2/$f differs from $1/$f"; done
}

# 1. two processes on one run folder: the second is refused at once, naming
# the folder and the first's pid, and the run ends as an uninterrupted one
"$walkers" evolve "${common[@]}" --generations 3 --out "$tmp/shared" >/dev/null 2>&1 || fail "evolve 3 generations"
"$walkers" evolve "${small[@]}" --out "$tmp/shared" --resume >"$tmp/first.txt" 2>&1 &
first=$!
for _ in $(seq 100); do grep -q resuming "$tmp/first.txt" && break; sleep 0.1; done
expect nonzero "shared: another walkers process \(pid $first\) is writing this run" -- \
  evolve "${small[@]}" --out "$tmp/shared" --resume
wait $first || { cat "$tmp/first.txt"; fail "the first of two resumes failed"; }
same_run "$tmp/whole" "$tmp/shared"

# 2. outputs are never replaced silently, and never when they are an input
cp "$genome" "$tmp/g.json"
expect nonzero 'trajectory .*g.json is the --genome file' -- evaluate --genome "$tmp/g.json" --trajectory "$tmp/g.json"
expect nonzero 'is the --genome file' -- evaluate --genome "$tmp/g.json" --trajectory "$tmp/g.json" --force
expect nonzero 'is the --genome file' -- simulate --genome "$tmp/g.json" --duration 0.1 --trajectory "$tmp/g.json" --force
cmp -s "$genome" "$tmp/g.json" || fail "a trajectory replaced the genome"
for command in "evaluate --genome $genome" "simulate --genome $genome --duration 0.1"; do
  echo mine >"$tmp/old.csv"
  # shellcheck disable=SC2086
  expect nonzero 'old.csv exists; pass --force to replace it' -- $command --trajectory "$tmp/old.csv"
  [[ $(cat "$tmp/old.csv") == mine ]] || fail "$command replaced an existing trajectory"
  # shellcheck disable=SC2086
  expect 0 '.' -- $command --trajectory "$tmp/old.csv" --force
  [[ $(head -c 4 "$tmp/old.csv") == t,x, ]] || fail "$command --force did not write the trajectory"
done
echo mine >"$tmp/old.html"
expect nonzero 'old.html exists; pass --force' -- replay --genome "$genome" --out "$tmp/old.html"
[[ $(cat "$tmp/old.html") == mine ]] || fail "replay replaced an existing page"
cp "$genome" "$tmp/g.svg"
expect nonzero 'is the --genome file' -- replay --genome "$tmp/g.svg" --out "$tmp/g.svg" --force
cmp -s "$genome" "$tmp/g.svg" || fail "replay replaced its genome"

# 3. --force with a configuration that cannot run leaves the old run intact
cp -a "$tmp/whole" "$tmp/whole.before"
expect nonzero 'population: value 1 is outside the allowed range \[2, 100000\]' -- \
  evolve --case performance --population 1 --mutation-children 1 --out "$tmp/whole" --force
expect nonzero 'mutation_children = 9 is outside its allowed range \[0, 8\]' -- \
  evolve --case performance --population 8 --mutation-children 9 --out "$tmp/whole" --force
diff -r "$tmp/whole.before" "$tmp/whole" >/dev/null || fail "a refused --force changed the run"

# 4. a checkpoint is checked before it is trusted
cp -a "$tmp/whole" "$tmp/cp"
sed -i 's/"completed_generations":6/"completed_generations":-3/' "$tmp/cp/checkpoint.json"
cp -a "$tmp/cp" "$tmp/cp.before"
expect nonzero "cp/checkpoint.json: field 'completed_generations' = -3 is outside its allowed range \[1, 6\]" -- \
  evolve "${common[@]}" --generations 8 --out "$tmp/cp" --resume
diff -r -x walkers.lock "$tmp/cp.before" "$tmp/cp" >/dev/null || fail "a refused resume changed the run"
cp "$tmp/whole/checkpoint.json" "$tmp/cp/checkpoint.json"
sed -i 's/"format":1,//' "$tmp/cp/checkpoint.json"
expect nonzero "cp/checkpoint.json: missing field 'format'" -- evolve "${common[@]}" --generations 8 --out "$tmp/cp" --resume
rm "$tmp/cp/checkpoint.json"
expect nonzero "cp/checkpoint.json: missing, but the run has results \(generations.csv has 6 rows\).*--force" -- \
  evolve "${common[@]}" --generations 8 --out "$tmp/cp" --resume
cmp -s "$tmp/whole/generations.csv" "$tmp/cp/generations.csv" || fail "a resume without checkpoint restarted the run"

# 5. smaller ones
expect nonzero 'seed: value -1 is outside the allowed range \[0, 4294967295\]' -- \
  evolve --case free --generations 1 --population 2 --mutation-children 1 --seed -1 --out "$tmp/seeded"
expect nonzero 'no run to resume \(no such directory\)' -- evolve --case free --out "$tmp/missing" --resume
[ ! -e "$tmp/missing" ] || fail "--resume created the directory it could not resume"
sed 's/^{/{"kStep": 900, /' "$genome" >"$tmp/twice.json"
expect nonzero "twice.json: key 'kStep' appears twice" -- evaluate --genome "$tmp/twice.json"
expect nonzero 'not expected: bogus; the commands are simulate, evaluate, evolve, replay, reproduce' -- bogus
expect nonzero 'not expected: evolv .*; did you mean evolve\?' -- evolv --case free
expect nonzero 'generations: value 1.5 is not an integer in \[1, 10000000\]' -- evolve --case free --generations 1.5 --out "$tmp/x"
expect nonzero 'not expected: --genom .*default.json; did you mean --genome\?' -- evaluate --genom "$genome"
sed 's/"femurLength": [0-9.]*/"femurLength": 2.5/' "$genome" >"$tmp/long.json"
expect nonzero "gene 'femurLength' = 2.5 is outside its allowed range \[0.1, 1.9\]$" -- evaluate --genome "$tmp/long.json"

[[ $failures -eq 0 ]] || { echo "$failures CLI check(s) failed"; exit 1; }
echo "all CLI checks passed"
