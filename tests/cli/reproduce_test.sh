#!/usr/bin/env bash
# A tiny reproduction (3 generations, 1 replicate, finals re-scored by ensembles
# of 3) must write every file and the claims' verdicts, the same when redone, and
# set the authors' runs (a stand-in checkout) beside ours; the replay command's
# HTML must load in headless Chromium without console errors and draw its canvas,
# and its SVG must parse.
# Usage: reproduce_test.sh WALKERS_BINARY SOURCE_DIR PYTHON
set -u
walkers=$1
src=$2
python=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

WALKERS_PYTHON=$python "$walkers" reproduce --generations 3 --replicates 1 --threads 2 --ensemble 3 --out "$tmp/rep" \
  >"$tmp/out.txt" 2>&1 ||
  { cat "$tmp/out.txt"; fail "walkers reproduce exited non-zero"; }
# progress: each run's time left and that of all runs
grep -Eq '^free-1 gen 1/3 .* [0-9hms]+ left, all runs [0-9hms]+$' "$tmp/out.txt" ||
  { cat "$tmp/out.txt"; fail "no progress line with the time left for all runs"; }
grep -q '^re-scored [0-9]* of [0-9]* finals (ensembles of 3)$' "$tmp/out.txt" || fail "no progress line of the re-scores"
for f in reproduction.json rescores.json summary.json summary.md walks.json gallery.json; do
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
for key in ("claims", "beside_authors", "rescores", "runs", "best_biped", "evals_per_s"):
    assert key in s, key
assert set(s["claims"]["cases"]) == {"free", "time", "performance"}, s["claims"]["cases"].keys()
assert len(s["runs"]) == 3
assert s["beside_authors"]["checkout"] is None and "no checkout" in s["beside_authors"]["note"]
# what made them: the program's commit and the evaluation settings the runs used
assert s["program"]["commit"], s["program"]
assert s["program"]["evaluation"]["restart_at_ticks"] in (True, False), s["program"]
PY
# the finals re-scored by this build: the unperturbed member scores what the run
# recorded, and the claims' final bests are the ensembles' medians
"$python" - "$tmp/rep" <<'PY' || fail "the re-scores do not hold or do not match"
import json, statistics, sys
rep = sys.argv[1]
m = json.load(open(rep + "/reproduction.json"))
s = json.load(open(rep + "/summary.json"))
assert m["ensemble"] == 3
for run in m["runs"]:
    archive = json.load(open(f"{rep}/{run['dir']}/archive.json"))["archive"][0]
    assert run["final_best"]["id"] == archive["id"] and run["final_best"]["fitness"] == archive["fitness"], run
    for key in ("final_best", "best_biped", "best_tripod"):
        f = run[key]
        if f is None:
            continue
        assert len(f["rescore"]["fitness"]) == 3 and f["rescore"]["fitness"][1] == f["fitness"], (run["dir"], key)
        assert f["rescore"]["recorded_reproduced"] is True, (run["dir"], key)
        assert f["rescore"]["median"] == statistics.median(f["rescore"]["fitness"]), (run["dir"], key)
for case, c in s["claims"]["cases"].items():
    medians = [r["final_best"]["rescore"]["median"] for r in m["runs"] if r["case"] == case]
    assert abs(c["final_best"]["mean"] - sum(medians) / len(medians)) <= 1e-12, case
assert s["rescores"]["not_reproduced"] == []
PY
# the claims: a verdict line each, in summary.json and summary.md; at one
# replicate nothing can be reproduced
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
assert findings["case3_leads_generations"]["effect"]["value"] == s["beside_authors"]["case3_leads_share"]["ours"]
for case, c in s["claims"]["cases"].items():
    tripods = sum(r["final_best"]["gait"] == "tripod" for r in s["runs"] if r["case"] == case)
    assert c["tripod_finals"]["tripods"] == tripods, case
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
# resuming a finished reproduction redoes only the statistics and figures (the
# re-scores come from the cache); a second process on the folder meanwhile is
# refused at once
WALKERS_PYTHON=$python "$walkers" reproduce --generations 3 --replicates 1 --ensemble 3 --out "$tmp/rep" --resume \
  >"$tmp/again.txt" 2>&1 &
again=$!
for _ in $(seq 100); do grep -q "done already" "$tmp/again.txt" && break; sleep 0.1; done
second=$(WALKERS_PYTHON=$python "$walkers" reproduce --generations 3 --replicates 1 --out "$tmp/rep" --resume 2>&1) &&
  fail "a second reproduce ran beside the first"
grep -q "rep: another walkers process (pid $again) is writing this reproduction" <<<"$second" ||
  fail "the second reproduce was not refused naming the first: $second"
wait $again || { cat "$tmp/again.txt"; fail "resuming the finished reproduction failed"; }
grep -q "done already" "$tmp/again.txt" || fail "resume did not find the runs done"
grep -q "^re-scored" "$tmp/again.txt" && fail "resume re-scored the finals again"
# the statistics and claims again: the same bits (the bootstrap is seeded)
cmp -s "$tmp/summary.first.json" "$tmp/rep/summary.json" || fail "summary.json changed when redone"
cmp -s "$tmp/summary.first.md" "$tmp/rep/summary.md" || fail "summary.md changed when redone"
grep -q "inconclusive at n = 1" "$tmp/again.txt" || fail "reproduce did not print the verdicts"
"$walkers" reproduce --generations 3 --replicates 1 --out "$tmp/rep" >/dev/null 2>&1 && fail "overwrote a reproduction without --resume"
# committed results: the finished runs staged without their evaluations.csv,
# whose statistics `reproduce --resume` makes again, the same
WALKERS=$walkers WALKERS_PYTHON=$python "$src/scripts/stage_results.sh" "$tmp/rep" 1 "$tmp/staged" --ensemble 3 \
  >"$tmp/stage.txt" 2>&1 || { cat "$tmp/stage.txt"; fail "stage_results.sh"; }
ls "$tmp"/staged/*/evaluations.csv >/dev/null 2>&1 && fail "the staged runs kept their evaluations.csv"
cp "$tmp/staged/summary.json" "$tmp/staged.summary.json"
WALKERS_PYTHON=$python "$walkers" reproduce --generations 3 --replicates 1 --ensemble 3 --out "$tmp/staged" --resume \
  >"$tmp/staged.txt" 2>&1 || { cat "$tmp/staged.txt"; fail "reproduce --resume on staged results"; }
cmp -s "$tmp/staged.summary.json" "$tmp/staged/summary.json" || fail "summary.json changed when remade from staged results"
# finished runs beyond the replicates staged (here all of them, R = 0) are kept
# as they are; an experiment continues from them in a new folder
WALKERS=$walkers "$src/scripts/stage_results.sh" "$tmp/rep" 0 "$tmp/kept" >"$tmp/kept.txt" 2>&1 ||
  { cat "$tmp/kept.txt"; fail "stage_results.sh with R = 0"; }
[ -e "$tmp/kept/summary.json" ] && fail "stage_results.sh with R = 0 made statistics"
for run in free-1 time-1 performance-1; do
  [ -s "$tmp/kept/$run/finals.json" ] || fail "the kept $run has no finals.json"
  [ -e "$tmp/kept/$run/evaluations.csv" ] && fail "the kept $run kept its evaluations.csv"
done
WALKERS_PYTHON=$python "$walkers" reproduce --generations 3 --replicates 1 --ensemble 3 --out "$tmp/kept" --resume \
  >"$tmp/continued.txt" 2>&1 || { cat "$tmp/continued.txt"; fail "reproduce --resume on kept runs"; }
grep -q "done already" "$tmp/continued.txt" || fail "the kept runs were not found done"
cmp -s "$tmp/staged.summary.json" "$tmp/kept/summary.json" || fail "the kept runs' statistics differ from the staged ones"
# runs continued from committed results (finals.json, no evaluations.csv) are staged again, the same
WALKERS=$walkers WALKERS_PYTHON=$python "$src/scripts/stage_results.sh" "$tmp/kept" 1 "$tmp/restaged" --ensemble 3 \
  >"$tmp/restage.txt" 2>&1 || { cat "$tmp/restage.txt"; fail "stage_results.sh on runs continued from committed results"; }
cmp -s "$tmp/staged.summary.json" "$tmp/restaged/summary.json" || fail "the restaged runs' statistics differ from the staged ones"
# a failing summary is reported, the figures are drawn all the same, the exit status is 1
mkdir "$tmp/failing_stats"
cat >"$tmp/failing_stats/__main__.py" <<PY
import runpy, sys
if sys.argv[1] == "summary":
    sys.exit(3)
runpy.run_path("$src/scripts/walkers_stats", run_name="__main__")
PY
rm -f "$tmp/rep/figures/fig9.png"
out=$(WALKERS_PYTHON=$python WALKERS_STATS="$tmp/failing_stats" "$walkers" reproduce --generations 3 --replicates 1 \
      --ensemble 3 --out "$tmp/rep" --resume 2>&1) && fail "reproduce succeeded with a failing summary"
grep -q "the statistics failed (exit status 3)" <<<"$out" || fail "no message for the failing summary: $out"
[ -s "$tmp/rep/figures/fig9.png" ] || fail "the figures were not drawn after the summary failed"

# the authors' runs beside ours, from a checkout named (a stand-in: their
# fitness-data, bump-data and summarisedOutput formats, three runs a case); a
# folder without them is refused before any run starts
data="$tmp/authors/CaseData/image/fitness-data"
labels="$tmp/authors/CaseData/image/bump-data"
mkdir -p "$data" "$labels"
for c in 1 2 3; do
  mkdir -p "$tmp/authors/CaseData/case$c"
  for m in 1 2 3; do
    printf '0,\n%d\ncount: 2\n1.5,\n%d.25\ncount: 2\n' "$m" "$((c + m))" >"$data/case$c-$m.txt"
    printf 'bump 1 >>> tripod\ncurrentGen:\n0_0\nmaxFitness:\n1.5\n\nbump 2 >>> biped\ncurrentGen:\n%d_3\nmaxFitness:\n%d.25\n\ncount: 2\n' \
      "$m" "$((c + m))" >"$labels/c${c}_$m.txt"
    "$python" -c 'import sys
with open(sys.argv[1], "w") as f:
    for g in range(4000):
        f.write(f"Generation: {g}\nCurrent Fitness:\n[1.5, -124, 2.0]\n\n")' "$tmp/authors/CaseData/case$c/summarisedOutput-$m"
  done
done
WALKERS_PYTHON=$python "$walkers" reproduce --generations 3 --replicates 1 --ensemble 3 --out "$tmp/rep" --resume \
  --authors-checkout "$tmp/authors" >"$tmp/authors.txt" 2>&1 || { cat "$tmp/authors.txt"; fail "reproduce --authors-checkout failed"; }
grep -q "^9 runs of the authors: case 1: 3, case 2: 3, case 3: 3$" "$tmp/authors.txt" || fail "the authors' runs were not counted"
"$python" - "$tmp/rep" "$tmp/authors" <<'PY' || fail "the authors' runs are not beside ours"
import json, sys
s = json.load(open(sys.argv[1] + "/summary.json"))
b = s["beside_authors"]
assert b["checkout"] == sys.argv[2] and b["note"] is None, b
# generation 2 of case 1: run 1 improved to 2.25 at generation 1, run 2 to 3.25
# at 2, run 3 not yet (1.5)
row = next(r for r in b["at_generations"] if r["case"] == "free" and r["generation"] == 2)
assert row["authors"] == {"mean": (2.25 + 3.25 + 1.5) / 3, "runs": 3}, row
assert row["ours"]["runs"] == 1
# their labels and their children: where the tripods go, the cut-offs (one of three a generation)
assert [e["experiment"] for e in s["tripods"]["experiments"]] == ["authors", "cvode"], s["tripods"]
free = s["tripods"]["experiments"][0]["cases"]["free"]
assert free["biped_for_good"]["runs"] == [1, 2, 3], free
whole = s["cut_offs"]["experiments"][0]["cases"]["free"]["blocks"][-1]
assert whole == {"first": 0, "last": 3999, "cut_offs": 12000, "evaluations": 36000}, whole
PY
grep -q "the authors" "$tmp/rep/figures/fig9.svg" || fail "fig9 does not show the authors' runs"
out=$("$walkers" reproduce --generations 3 --replicates 1 --out "$tmp/new" --authors-checkout "$tmp/rep" 2>&1) &&
  fail "reproduce accepted a checkout without the authors' runs"
grep -q "fitness-data/" <<<"$out" && grep -q -- "--authors-checkout $tmp/rep: the statistics cannot read" <<<"$out" ||
  fail "no message naming the checkout: $out"
[ ! -e "$tmp/new" ] || fail "a refused checkout still started the reproduction"

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
