#!/usr/bin/env bash
# A tiny reproduction (3 generations, 1 replicate) must write every file and the
# claims' verdicts, the same when redone; the
# replay command's HTML must load in headless Chromium without console errors
# and draw its canvas, and its SVG must parse.
# Usage: reproduce_test.sh WALKERS_BINARY SOURCE_DIR PYTHON
set -u
walkers=$1
src=$2
python=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

WALKERS_PYTHON=$python "$walkers" reproduce --generations 3 --replicates 1 --threads 2 --out "$tmp/rep" >"$tmp/out.txt" 2>&1 ||
  { cat "$tmp/out.txt"; fail "walkers reproduce exited non-zero"; }
# progress: each run's time left and that of all runs
grep -Eq '^free-1 gen 1/3 .* [0-9hms]+ left, all runs [0-9hms]+$' "$tmp/out.txt" ||
  { cat "$tmp/out.txt"; fail "no progress line with the time left for all runs"; }
for f in summary.json summary.md walks.json gallery.json; do
  [ -s "$tmp/rep/$f" ] || fail "no $f"
done
for run in free-1 time-1 performance-1; do
  for f in config.json generations.csv evaluations.csv archive.json best.json; do
    [ -s "$tmp/rep/$run/$f" ] || fail "no $run/$f"
  done
done
for fig in fig4a fig4b fig5 fig6 fig7 fig8 fig9 finals; do
  for ext in png svg; do
    [ -s "$tmp/rep/figures/$fig.$ext" ] || fail "no figures/$fig.$ext"
  done
done
"$python" - "$tmp/rep" <<'PY' || fail "summary.json lacks a statistic"
import json, sys
s = json.load(open(sys.argv[1] + "/summary.json"))
for key in ("cases", "case3_over_case1_share", "case2_over_case1_final", "biped_over_tripod", "runs", "evals_per_s"):
    assert key in s, key
assert set(s["cases"]) == {"free", "time", "performance"}, s["cases"].keys()
assert len(s["runs"]) == 3
PY
# the claims: a verdict line each, in summary.json and summary.md, whose numbers agree
# with the program's own statistics; at one replicate nothing can be reproduced
"$python" - "$tmp/rep" <<'PY' || fail "the claims block does not hold or does not match"
import json, sys
rep = sys.argv[1]
s = json.load(open(rep + "/summary.json"))
md = open(rep + "/summary.md", encoding="utf-8").read()
findings = {f["id"]: f for f in s["claims"]["findings"]}
assert len(findings) == 6, findings.keys()
for f in findings.values():
    assert f["verdict"] in ("reproduced", "not reproduced", "inconclusive at n = 1"), f
    assert f"- {f['line']}\n" in md, f["line"]
assert findings["case3_above_case1"]["verdict"] == "inconclusive at n = 1"
assert md.index("## Claims") < md.index("## Figures"), "no Claims section before the figures"
def close(a, b):
    return abs(a - b) <= 1e-12 * max(1.0, abs(b))
assert close(findings["case3_leads_generations"]["effect"]["value"], s["case3_over_case1_share"]["value"])
assert close(findings["case2_below_case1"]["effect"]["value"], s["case2_over_case1_final"]["value"])
if s["biped_over_tripod"]["value"] is not None:
    assert close(findings["biped_above_tripod"]["effect"]["value"], s["biped_over_tripod"]["value"] - 1)
for case, c in s["claims"]["cases"].items():
    assert c["tripod_finals"]["tripods"] == s["cases"][case]["tripod_finals"], case
for run in s["runs"]:
    for gait in ("biped", "tripod"):
        assert f"best_{gait}_fitness" in run, run
PY
cp "$tmp/rep/summary.json" "$tmp/summary.first.json"
cp "$tmp/rep/summary.md" "$tmp/summary.first.md"
# the gallery: every run's final best, and its best tripod when the final best is a biped
"$python" - "$tmp/rep" <<'PY' || fail "gallery.json does not match the runs"
import csv, json, sys
rep = sys.argv[1]
people = json.load(open(rep + "/gallery.json"))["individuals"]
for run in ("free-1", "time-1", "performance-1"):
    best = json.load(open(f"{rep}/{run}/archive.json"))["archive"][0]
    mine = [p for p in people if p["run"] == run]
    assert mine[0]["id"] == best["id"] and mine[0]["fitness"] == best["fitness"], (run, mine[0], best["id"])
    rows = list(csv.DictReader(open(f"{rep}/{run}/evaluations.csv")))
    tripods = [r for r in rows if r["gait"] == "tripod"]
    if best["gait"] == "biped" and tripods:
        top = max(float(r["fitness"]) for r in tripods)
        assert len(mine) == 2 and mine[1]["gait"] == "tripod", (run, mine)
        assert abs(mine[1]["fitness"] - top) <= 1e-12 * max(1.0, abs(top)), (run, mine[1]["fitness"], top)
    else:
        assert len(mine) == 1, (run, mine)
PY
# resuming a finished reproduction redoes only the statistics and figures;
# a second process on the folder meanwhile is refused at once
WALKERS_PYTHON=$python "$walkers" reproduce --generations 3 --replicates 1 --out "$tmp/rep" --resume >"$tmp/again.txt" 2>&1 &
again=$!
for _ in $(seq 100); do grep -q "done already" "$tmp/again.txt" && break; sleep 0.1; done
second=$(WALKERS_PYTHON=$python "$walkers" reproduce --generations 3 --replicates 1 --out "$tmp/rep" --resume 2>&1) &&
  fail "a second reproduce ran beside the first"
grep -q "rep: another walkers process (pid $again) is writing this reproduction" <<<"$second" ||
  fail "the second reproduce was not refused naming the first: $second"
wait $again || { cat "$tmp/again.txt"; fail "resuming the finished reproduction failed"; }
grep -q "done already" "$tmp/again.txt" || fail "resume did not find the runs done"
# the statistics and claims again: the same bits (the bootstrap is seeded)
cmp -s "$tmp/summary.first.json" "$tmp/rep/summary.json" || fail "summary.json changed when redone"
cmp -s "$tmp/summary.first.md" "$tmp/rep/summary.md" || fail "summary.md changed when redone"
grep -q "inconclusive at n = 1" "$tmp/again.txt" || fail "reproduce did not print the verdicts"
"$walkers" reproduce --generations 3 --replicates 1 --out "$tmp/rep" >/dev/null 2>&1 && fail "overwrote a reproduction without --resume"
# a failing claims script is reported, the figures are drawn all the same, the exit status is 1
printf 'import sys\nsys.exit(3)\n' >"$tmp/failing_claims.py"
rm -f "$tmp/rep/figures/fig9.png"
out=$(WALKERS_PYTHON=$python WALKERS_CLAIMS_SCRIPT="$tmp/failing_claims.py" "$walkers" reproduce --generations 3 \
      --replicates 1 --out "$tmp/rep" --resume 2>&1) && fail "reproduce succeeded with a failing claims script"
grep -q "the claims script failed (exit status 3)" <<<"$out" || fail "no message for the failing claims script: $out"
[ -s "$tmp/rep/figures/fig9.png" ] || fail "the figures were not drawn after the claims script failed"

# --force: an impossible configuration leaves the reproduction intact; a
# possible one replaces it, and keeps nothing of the old once it has begun
cp -a "$tmp/rep" "$tmp/rep.before"
out=$("$walkers" reproduce --generations 3 --replicates 2 --seed 4294967295 --out "$tmp/rep" --force 2>&1) &&
  fail "reproduce --force accepted seeds beyond the range"
grep -q 'seed = 4294967295 is outside its allowed range \[0, 4294967294\]' <<<"$out" || fail "no seed range in: $out"
diff -r -x walkers.lock "$tmp/rep.before" "$tmp/rep" >/dev/null || fail "a refused --force changed the reproduction"
WALKERS_PYTHON=$python "$walkers" reproduce --generations 2 --replicates 1 --threads 2 --out "$tmp/rep" --force >"$tmp/force.txt" 2>&1 ||
  { cat "$tmp/force.txt"; fail "reproduce --force failed"; }
[ ! -e "$tmp/rep/replaced" ] || fail "reproduce --force kept the old reproduction after its first run"
"$python" -c "import json, sys; assert json.load(open(sys.argv[1]))['generations'] == 2" "$tmp/rep/summary.json" ||
  fail "reproduce --force did not replace the summary"

# learners compared: every learner under every scaffold, the table and the figure
WALKERS_PYTHON=$python "$walkers" reproduce --learners ga,cmaes --generations 2 --replicates 1 --threads 2 \
  --out "$tmp/learners" >"$tmp/learners.txt" 2>&1 || { cat "$tmp/learners.txt"; fail "reproduce --learners failed"; }
grep -q '^6 runs,' "$tmp/learners.txt" || { cat "$tmp/learners.txt"; fail "reproduce --learners ga,cmaes did not make 6 runs"; }
for run in free-1 time-1 performance-1 cmaes-free-1 cmaes-time-1 cmaes-performance-1; do
  [ -s "$tmp/learners/$run/best.json" ] || fail "no $run/best.json"
done
grep -q '^| CMA-ES (cmaes) |' "$tmp/learners/summary.md" || fail "summary.md has no row for CMA-ES"
# runs side by side (--threads 2: two at once) write the files of runs one at
# a time on one thread, but for the wall-clock columns
grep -q '^6 runs, 2 at once, on 2 threads' "$tmp/learners.txt" || fail "reproduce --threads 2 did not run 2 runs at once"
WALKERS_PYTHON=/bin/true "$walkers" reproduce --learners ga,cmaes --generations 2 --replicates 1 --threads 1 \
  --out "$tmp/one-at-a-time" >"$tmp/one.txt" 2>&1 || { cat "$tmp/one.txt"; fail "reproduce --threads 1 failed"; }
for run in free-1 time-1 performance-1 cmaes-free-1 cmaes-time-1 cmaes-performance-1; do
  for f in evaluations.csv generations.csv; do
    cmp -s <(sed 's/,[^,]*$//' "$tmp/learners/$run/$f") <(sed 's/,[^,]*$//' "$tmp/one-at-a-time/$run/$f") ||
      fail "$run/$f differs between runs side by side and one at a time"
  done
  for f in config.json archive.json best.json; do
    cmp -s "$tmp/learners/$run/$f" "$tmp/one-at-a-time/$run/$f" ||
      fail "$run/$f differs between runs side by side and one at a time"
  done
done
for f in walks.json gallery.json; do
  cmp -s "$tmp/learners/$f" "$tmp/one-at-a-time/$f" || fail "$f differs between runs side by side and one at a time"
done
for ext in png svg; do
  [ -s "$tmp/learners/figures/learners.$ext" ] || fail "no figures/learners.$ext"
done
[ ! -e "$tmp/rep/figures/learners.png" ] || fail "a reproduction of one learner drew the learners figure"

# replay: the animation in a real browser, the filmstrip as XML
genome=$src/data/genomes/default.json
"$walkers" replay --genome "$genome" --out "$tmp/walk.html" >/dev/null || fail "replay to HTML"
"$walkers" replay --genome "$genome" --out "$tmp/walk.svg" >/dev/null || fail "replay to SVG"
"$python" -c "import sys, xml.dom.minidom; xml.dom.minidom.parse(sys.argv[1])" "$tmp/walk.svg" || fail "the SVG does not parse"
# the filmstrip says which leg is which colour, in the colours its legs are drawn in
for leg in "#1f77b4:left leg" "#d62728:right leg"; do
  grep -q "<tspan fill=\"${leg%%:*}\"[^>]*>${leg#*:}</tspan>" "$tmp/walk.svg" &&
    grep -q "<polyline [^>]*stroke=\"${leg%%:*}\"" "$tmp/walk.svg" || fail "the filmstrip does not say which leg is ${leg#*:}"
done
cp "$genome" "$tmp/a&b<c>.json"
"$walkers" replay --genome "$tmp/a&b<c>.json" --out "$tmp/odd.svg" >/dev/null || fail "replay of a genome with & and < in its name"
"$python" -c "import sys, xml.dom.minidom; xml.dom.minidom.parse(sys.argv[1])" "$tmp/odd.svg" ||
  fail "the SVG of a genome named with & and < does not parse"
"$python" "$src/tests/replay/check_replay.py" "$tmp/walk.html" || fail "the replay page in headless Chromium"
"$walkers" replay --genome "$genome" --out "$tmp/walk.png" >/dev/null 2>&1 && fail "accepted an unknown replay format"

[ $failures -eq 0 ] || { echo "$failures check(s) failed"; exit 1; }
echo "reproduce and replay checks passed"
