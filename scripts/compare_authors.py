#!/usr/bin/python3
"""Compare this simulator with the authors' own Simbody program, genome by genome.

The authors' repository (github.com/jhuizhu/bipedalism-scaffolded-learning) is not part of
this project: the user provides a checkout of it. This script builds their walker program
from that checkout into a build folder outside this repository (against Debian's
libsimbody-dev and libarmadillo-dev), runs it and `walkers evaluate --ensemble N` on a
folder of genome files, and prints both side by side with the summary statistics of
docs/fidelity.md.

  compare_authors.py extract --authors REPO --out DIR [--top 4]
      genome files of the top N of every run's final archive in REPO/CaseData
  compare_authors.py finals --results DIR --out DIR
      genome files of every run's best biped and best tripod in a reproduction's folder
      (DIR/<run>/finals.json, as `walkers reproduce` writes it): our finals in their program
  compare_authors.py run --authors REPO --genomes DIR [--ensemble 25] [--jobs 2] [--json OUT] [--markdown OUT]
                         [--integrator cvode|rk-merson ...] [--accuracy A]
      build their program if needed, evaluate every genome in both, print the table (ours under each
      --integrator given, side by side; cvode by default)
      (--authors-binary PROGRAM instead of --authors: their program, already built;
      --timeout S: how long to wait for their fitness of one genome, 300 s by default)

Their program reads its genes as 32-bit floats from the command line, as their evolver gave
them (Python 2's str(), 12 significant digits); we pass them the same way.
"""

import argparse
import ast
import concurrent.futures
import csv
import json
import math
import os
import pathlib
import re
import shutil
import statistics
import subprocess
import sys
import time

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent

# Our gene names (genome files) and the authors' (their evolver's dictionaries), in the order
# of their program's command line.
AUTHORS_ARGUMENTS = [
    ("halfBodyX", "halfBodyX"),
    ("halfBodyY", "halfBodyY"),
    ("halfBodyZ", "halfBodyZ"),
    ("halfFootX", "halfFootBodyX"),
    ("halfFootY", "halfFootBodyY"),
    ("halfFootZ", "halfFootBodyZ"),
    ("kx", "k1"),
    ("ky", "k2"),
    ("lambdaX", "lambda1"),
    ("lambdaY", "lambda2"),
    ("kTheta", "bodyStraightK"),
    ("lambdaTheta", "bodyStraightL"),
    ("kneeMass", "kneeMass"),
    ("ankleMass", "ankleMass"),
    ("hipMass", "hipMass"),
    ("kStep", "stepK"),
    ("stableTolerance", "stableTolerance"),
    ("tibiaLength", "tibiaLength"),
    ("femurLength", "femurLength"),
    ("standOffset", "standOffset"),
    ("stepOffset", "stepOffset"),
]
OURS_FROM_AUTHORS = {theirs: ours for ours, theirs in AUTHORS_ARGUMENTS}

# Their evolver killed an evaluation after 25 s of wall time (fitness -124); we wait
# for their fitness up to this long by default (`run --timeout`).
AUTHORS_TIMEOUT_S = 300.0
# Their program's fitness for a fall or a Simbody exception.
AUTHORS_FALL = -1.0
CASES = {"case1": "free", "case2": "time", "case3": "performance"}


class ToolError(Exception):
    pass


# ---- genome files from the authors' run data ----

def natural_key(path):
    """free-2 before free-10: a name's digit runs compare as numbers."""
    return [int(part) if part.isdigit() else part for part in re.split(r"(\d+)", pathlib.Path(path).name)]


def final_archive(summary_path):
    """The last 'all time fittest' archive their evolver wrote: [(genes, fitness), ...]."""
    text = pathlib.Path(summary_path).read_text()
    start = text.rfind("[[{")
    end = text.rfind("]]")
    if start < 0 or end < start:
        raise ToolError(f"{summary_path}: no final archive (a list of [genes, fitness]) found")
    archive = ast.literal_eval(text[start:end + 2])
    return [(genes, float(fitness)) for genes, fitness in archive]


def genome_from_authors(genes, source):
    try:
        return {ours: float(genes[theirs]) for ours, theirs in AUTHORS_ARGUMENTS}
    except KeyError as e:
        raise ToolError(f"{source}: gene {e} missing") from None


def write_genome_folder(out, genomes, origins, force):
    """Genome files [(file name, genome), ...] and their origin.csv (its lines, the header
    first) into the folder out; nothing is written when any of them exists, unless force."""
    out = pathlib.Path(out)
    for path in [out / name for name, _ in genomes] + [out / "origin.csv"]:
        if path.exists() and not force:
            raise ToolError(f"{path} exists (use --force to replace it)")
    out.mkdir(parents=True, exist_ok=True)
    for name, genome in genomes:
        (out / name).write_text(json.dumps(genome, indent=2) + "\n")
    (out / "origin.csv").write_text("\n".join(origins) + "\n")
    print(f"wrote {len(genomes)} genome files and origin.csv to {out}")


def extract(args):
    case_data = pathlib.Path(args.authors) / "CaseData"
    summaries = sorted(case_data.glob("case*/summarisedOutput-*"))
    if not summaries:
        raise ToolError(f"{case_data}: no case*/summarisedOutput-* files (is --authors their repository?)")
    origins = ["file,case,run,rank,authors_recorded_fitness"]
    genomes = []
    for summary in summaries:
        case = summary.parent.name
        run = summary.name.split("-", 1)[1]
        for rank, (genes, fitness) in enumerate(final_archive(summary)[: args.top]):
            name = f"archive_{case}_{run}_{rank}.json"
            genomes.append((name, genome_from_authors(genes, f"{summary} entry {rank}")))
            origins.append(f"{name},{CASES.get(case, case)},{run},{rank},{fitness!r}")
    write_genome_folder(args.out, genomes, origins, args.force)


# ---- genome files from our runs ----

def finals(args):
    results = pathlib.Path(args.results)
    runs = sorted((f.parent for f in results.glob("*/finals.json")), key=natural_key)
    if not runs:
        raise ToolError(f"{results}: no */finals.json (is --results a reproduction's folder?)")
    origins = ["file,case,run,gait,final_best,recorded_fitness"]
    genomes = []
    for run in runs:
        try:
            record = json.loads((run / "finals.json").read_text())
            case = json.loads((run / "config.json").read_text())["case"]
            best = json.loads((run / "best.json").read_text())
        except (OSError, ValueError, KeyError) as e:
            raise ToolError(f"{run}: unreadable run record ({e})") from None
        for gait in ("biped", "tripod"):
            final = record.get(f"best_{gait}")
            if not final:
                continue  # the run never had one
            name = f"{run.name}-{gait}.json"
            genomes.append((name, final["genome"]))
            final_best = "yes" if final["genome"] == best else "no"
            origins.append(f"{name},{case},{run.name},{gait},{final_best},{final['fitness']!r}")
    write_genome_folder(args.out, genomes, origins, args.force)


# ---- the authors' program ----

# As the authors built it: no build type, so no optimisation and no NDEBUG.
# Both matter: Debian's Simbody headers change a structure's layout under
# NDEBUG, and at -O2 GCC 12 evaluates the program's float half-sizes in
# double precision in places, which changes its results.
BUILD_CMAKE = """cmake_minimum_required(VERSION 3.13)
project(authors_walker CXX)
find_package(Simbody REQUIRED)
add_executable(walker "{source}")
target_include_directories(walker PRIVATE ${{Simbody_INCLUDE_DIR}})
target_link_libraries(walker ${{Simbody_LIBRARIES}} armadillo)
"""


def build_authors(authors, build_dir):
    build_dir = pathlib.Path(build_dir).resolve()
    if ROOT in build_dir.parents or build_dir == ROOT:
        raise ToolError(f"--build-dir {build_dir} is inside this repository; their program is built outside it")
    source = pathlib.Path(authors).resolve() / "simbody" / "twoLegVar" / "walker.cpp"
    if not source.is_file():
        raise ToolError(f"{source}: not found (is --authors a checkout of their repository?)")
    binary = build_dir / "build" / "walker"
    if binary.exists() and binary.stat().st_mtime >= source.stat().st_mtime:
        return binary
    for tool in ("cmake", "c++"):
        if shutil.which(tool) is None:
            raise ToolError(f"{tool} not found: run scripts/setup.sh --authors first")
    build_dir.mkdir(parents=True, exist_ok=True)
    (build_dir / "CMakeLists.txt").write_text(BUILD_CMAKE.format(source=source.as_posix()))
    log = build_dir / "build.log"
    with open(log, "w") as f:
        ok = (subprocess.run(["cmake", "-S", str(build_dir), "-B", str(build_dir / "build"),
                              "-DCMAKE_BUILD_TYPE="], stdout=f, stderr=f).returncode == 0
              and subprocess.run(["cmake", "--build", str(build_dir / "build")], stdout=f,
                                 stderr=f).returncode == 0)
    if not ok:
        raise ToolError(f"building their program failed (libsimbody-dev and libarmadillo-dev installed? "
                        f"scripts/setup.sh --authors installs them); see {log}")
    return binary


def authors_arguments(genome):
    # Python 2's str() of a float: 12 significant digits
    return ["%.12g" % genome[ours] for ours, _ in AUTHORS_ARGUMENTS]


def run_authors(binary, genome, timeout_s):
    """Their fitness, or None with a reason, and the wall time their program took."""
    start = time.monotonic()
    fitness, note = run_authors_once(binary, genome, timeout_s)
    return fitness, note, time.monotonic() - start


def run_authors_once(binary, genome, timeout_s):
    try:
        p = subprocess.run([str(binary)] + authors_arguments(genome), capture_output=True, text=True,
                           timeout=timeout_s)
    except subprocess.TimeoutExpired:
        return None, "timeout"
    if p.returncode != 0:
        return AUTHORS_FALL, "fell" if p.returncode == 254 else f"exit {p.returncode}"
    try:
        return float(p.stdout.strip().split()[-1]), ""
    except (ValueError, IndexError):
        return None, f"unreadable output {p.stdout!r}"


# ---- ours ----

def run_ours(walkers, genome_path, ensemble, preset, integrator="cvode", accuracy=None):
    """`walkers evaluate --ensemble N --json` under one of our integrators, without the cut-off:
    their program is waited for as long as --timeout says."""
    command = [str(walkers), "evaluate", "--genome", str(genome_path), "--ensemble", str(ensemble),
               "--preset", preset, "--json", "--integrator", integrator, "--cut-off", "none"]
    if accuracy is not None and integrator == "rk-merson":
        command += ["--accuracy", repr(accuracy)]
    p = subprocess.run(command, capture_output=True, text=True)
    if p.returncode != 0:
        raise ToolError(f"walkers evaluate on {genome_path} failed: {p.stderr.strip()}")
    return json.loads(p.stdout)


# ---- statistics ----

def spearman(xs, ys):
    from scipy import stats  # python3-scipy, installed by scripts/setup.sh
    return float(stats.spearmanr(xs, ys).statistic)


# A genome whose fitness differs by more than this factor between the programs, or that walks
# (fitness above 0) in one and not in the other, is an outlier.
OUTLIER_FACTOR = 1.5


def outlier(ours, theirs):
    if ours > 0 and theirs > 0:
        return max(ours / theirs, theirs / ours) > OUTLIER_FACTOR
    return (ours > 0) != (theirs > 0)


def ours_under(row, integrator):
    """A row's results under one of our integrators (the first one's are the row's own fields)."""
    return row["by_integrator"][integrator] if integrator else row


def summarise(rows, integrator=None):
    both = [r for r in rows if r["authors"] is not None]
    ours = {r["genome"]: ours_under(r, integrator) for r in rows}
    ratios = [ours[r["genome"]]["ours_median"] / r["authors"] for r in both if r["authors"] > 0]
    tripods = [r for r in both if ours[r["genome"]]["ours_tripods"] * 2 > r["ensemble"]]
    # how many times faster ours is, per genome: one evaluation of each, the
    # same machine and run (theirs includes their process's start-up)
    speedups = [r["authors_ms"] / ours[r["genome"]]["ours_ms"] for r in both
                if r.get("authors_ms") and ours[r["genome"]].get("ours_ms")]
    medians = [ours[r["genome"]]["ours_median"] for r in both]
    return {
        "genomes": len(rows),
        "compared": len(both),
        "spearman": spearman([r["authors"] for r in both], medians) if len(both) > 2 else None,
        "median_ratio": statistics.median(ratios) if ratios else None,
        "median_abs_difference": statistics.median(abs(m - r["authors"]) for m, r in zip(medians, both)) if both else None,
        "beyond_factor": sum(outlier(m, r["authors"]) for m, r in zip(medians, both)),
        "tripods": len(tripods),
        "median_speedup": statistics.median(speedups) if speedups else None,
    }


def summarise_final_bests(rows, origins, integrator=None):
    """The summary over the runs' final bests alone (what the claims use), and by case the
    mean fitness of those compared in both programs; None unless origin.csv is `finals`'."""
    final = {o["file"][:-5]: o["case"] for o in origins if o.get("final_best") == "yes"}
    if not final:
        return None
    finals = [r for r in rows if r["genome"] in final]
    by_case = {}
    cases = [c for c in CASES.values() if c in final.values()]  # the paper's order of the cases
    cases += sorted(set(final.values()) - set(cases))
    for case in cases:
        both = [r for r in finals if final[r["genome"]] == case and r["authors"] is not None]
        by_case[case] = {"compared": len(both),
                         "theirs_mean": statistics.mean(r["authors"] for r in both) if both else None,
                         "ours_mean": statistics.mean(ours_under(r, integrator)["ours_median"] for r in both)
                         if both else None}
    return dict(summarise(finals, integrator), by_case=by_case)


def origin_rows(genome_dir):
    """The rows of the folder's origin.csv (which run each genome file comes from), if any."""
    origin = pathlib.Path(genome_dir) / "origin.csv"
    if not origin.is_file():
        return []
    with open(origin) as f:
        return list(csv.DictReader(f))


def recorded_fitness(origins):
    """What a run recorded for each genome, from the folder's origin.csv rows if any: whose runs
    ('their runs' for `extract`'s files, 'our runs' for `finals`') and the fitness by genome."""
    for column, whose in (("authors_recorded_fitness", "their runs"), ("recorded_fitness", "our runs")):
        if origins and column in origins[0]:
            return whose, {r["file"][:-5]: float(r[column]) for r in origins}
    return "their runs", {}


def markdown_table(rows, recorded_by, timeout_s):
    whose, recorded = recorded_by
    lines = [f"| genome | recorded by {whose} | theirs | ours: median [min, max] | ours / theirs | gait (ours) |",
             "|---|---|---|---|---|---|"]
    notes = {"timeout": f"> {timeout_s:g} s", "exit 255": "fails (−1)"}
    for r in rows:
        theirs = notes.get(r["authors_note"], "—" if r["authors"] is None else f"{r['authors']:.2f}")
        ratio = f"{r['ours_median'] / r['authors']:.2f}" if r["authors"] and r["authors"] > 0 else "—"
        rec = f"{recorded[r['genome']]:.2f}" if r["genome"] in recorded else "—"
        gait = "tripod" if 2 * r["ours_tripods"] > r["ensemble"] else "biped"
        lines.append(f"| `{r['genome']}` | {rec} | {theirs} | {r['ours_median']:.2f} [{r['ours_min']:.2f}, "
                     f"{r['ours_max']:.2f}] | {ratio} | {gait} |")
    return "\n".join(lines) + "\n"


def write_new(path, text, force):
    path = pathlib.Path(path)
    if path.exists() and not force:
        raise ToolError(f"{path} exists (use --force to replace it)")
    path.write_text(text)


def run(args):
    genomes = sorted(pathlib.Path(args.genomes).glob("*.json"), key=natural_key)
    if not genomes:
        raise ToolError(f"{args.genomes}: no genome files (*.json)")
    if not args.timeout > 0:
        raise ToolError(f"--timeout {args.timeout}: must be a number of seconds above 0")
    if args.accuracy is not None and not 0 < args.accuracy <= 1:
        raise ToolError(f"--accuracy {args.accuracy}: must lie in (0, 1]")
    walkers = pathlib.Path(args.walkers)
    if not walkers.is_file():
        raise ToolError(f"{walkers}: not found (build the project first: scripts/build.sh)")
    if args.authors_binary:
        binary = pathlib.Path(args.authors_binary)
        if not binary.is_file():
            raise ToolError(f"--authors-binary {binary}: not found")
    else:
        if not args.authors:
            raise ToolError("give --authors (a checkout of their repository) or --authors-binary")
        binary = build_authors(args.authors, args.build_dir)

    integrators = list(dict.fromkeys(args.integrator or ["cvode"]))

    def ours_fields(path, integrator):
        ours = run_ours(walkers, path, args.ensemble, args.preset, integrator, args.accuracy)
        e = ours["ensemble"]
        return {
            "ours": ours["fitness"],
            "ours_median": e["fitness_median"],
            "ours_min": e["fitness_min"],
            "ours_max": e["fitness_max"],
            "ours_tripods": e["tripods"],
            "ours_falls": e["falls"],
            "ensemble": e["size"],
            "ours_ms": ours["wall_ms"],
        }

    def one(path):
        genome = json.loads(path.read_text())
        authors, note, seconds = run_authors(binary, genome, args.timeout)
        by_integrator = {integrator: ours_fields(path, integrator) for integrator in integrators}
        # the first integrator's results are the row's own
        return dict(by_integrator[integrators[0]], genome=path.stem, authors=authors, authors_note=note,
                    authors_ms=1000.0 * seconds, integrator=integrators[0], by_integrator=by_integrator)

    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        rows = list(pool.map(one, genomes))

    name_width = max(len(r["genome"]) for r in rows)
    print(f"{'genome':<{name_width}}  {'theirs':>7}  {'ours':>7}  {'ratio':>6}  {'min':>6}  {'max':>6}  "
          f"{'tripod':>6}  {'fell':>4}")
    for r in rows:
        theirs = "—" if r["authors"] is None else f"{r['authors']:.2f}"
        ratio = f"{r['ours_median'] / r['authors']:.2f}" if r["authors"] and r["authors"] > 0 else "—"
        print(f"{r['genome']:<{name_width}}  {theirs:>7}  {r['ours_median']:>7.2f}  {ratio:>6}  "
              f"{r['ours_min']:>6.2f}  {r['ours_max']:>6.2f}  {r['ours_tripods']:>3}/{r['ensemble']:<2}  "
              f"{r['ours_falls']:>4}  {r['authors_note']}")
    fmt = lambda v: "—" if v is None else f"{v:.3f}"
    origins = origin_rows(args.genomes)
    summaries, finals = {}, {}
    for integrator in integrators:
        s = summaries[integrator] = summarise(rows, integrator)
        print(f"\n{integrator}: {s['compared']} of {s['genomes']} compared: Spearman {fmt(s['spearman'])}, median "
              f"ratio ours/theirs {fmt(s['median_ratio'])}, median |ours - theirs| {fmt(s['median_abs_difference'])}, "
              f"{s['beyond_factor']} beyond a factor {OUTLIER_FACTOR:g}, {s['tripods']} classed tripods (ensemble "
              f"majority); ours a median {fmt(s['median_speedup'])} times faster per evaluation")
        final = finals[integrator] = summarise_final_bests(rows, origins, integrator)
        if final:
            print(f"{integrator}: the runs' final bests: {final['compared']} of {final['genomes']} compared: Spearman "
                  f"{fmt(final['spearman'])}, median ratio ours/theirs {fmt(final['median_ratio'])}, "
                  f"{final['beyond_factor']} beyond a factor {OUTLIER_FACTOR:g}; mean fitness of those compared, "
                  "theirs against ours: " + ", ".join(
                      f"{case} {fmt(c['theirs_mean'])} against {fmt(c['ours_mean'])} ({c['compared']})"
                      for case, c in final["by_case"].items()))
    if args.markdown:
        write_new(args.markdown, markdown_table(rows, recorded_fitness(origins), args.timeout), args.force)
    if args.json:
        first = integrators[0]
        write_new(args.json, json.dumps({"summary": summaries[first], "final_bests": finals[first],
                                         "summaries": summaries, "final_bests_by_integrator": finals,
                                         "rows": rows, "ensemble": args.ensemble, "preset": args.preset,
                                         "integrators": integrators, "accuracy": args.accuracy},
                                        indent=1) + "\n", args.force)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = parser.add_subparsers(dest="command", required=True)
    e = sub.add_parser("extract", help="genome files from their run data")
    e.add_argument("--authors", required=True, help="a checkout of their repository")
    e.add_argument("--out", required=True)
    e.add_argument("--top", type=int, default=4, help="the N fittest of each run's final archive")
    e.add_argument("--force", action="store_true")
    f = sub.add_parser("finals", help="genome files of our runs' best bipeds and tripods")
    f.add_argument("--results", required=True, help="a reproduction's folder (docs/results, runs/paper)")
    f.add_argument("--out", required=True)
    f.add_argument("--force", action="store_true")
    r = sub.add_parser("run", help="evaluate a folder of genomes in both programs")
    r.add_argument("--authors", help="a checkout of their repository (their program is built from it)")
    r.add_argument("--authors-binary", help="their program, already built (instead of --authors)")
    r.add_argument("--genomes", required=True)
    r.add_argument("--build-dir", default=os.path.expanduser("~/.cache/walkers/authors-build"))
    r.add_argument("--walkers", default=str(ROOT / "build" / "app" / "walkers"))
    r.add_argument("--ensemble", type=int, default=25)
    r.add_argument("--integrator", action="append", choices=["cvode", "rk-merson"],
                   help="our integrator (again for another, side by side; default cvode); ours run "
                        "without the cut-off")
    r.add_argument("--accuracy", type=float, help="rk-merson's accuracy (default 0.05, the authors')")
    r.add_argument("--preset", default="original")
    r.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    r.add_argument("--timeout", type=float, default=AUTHORS_TIMEOUT_S,
                   help="seconds to wait for their program's fitness of one genome (default %(default)g)")
    r.add_argument("--json", help="write every row and the summary here")
    r.add_argument("--markdown", help="write the table here, as docs/fidelity.md shows it")
    r.add_argument("--force", action="store_true")
    args = parser.parse_args()
    try:
        {"extract": extract, "finals": finals, "run": run}[args.command](args)
    except ToolError as err:
        print(f"compare_authors: {err}", file=sys.stderr)
        sys.exit(2)


if __name__ == "__main__":
    main()
