"""SciPy's differential evolution under the performance-based scaffold, beside
the paper's genetic algorithm, with the learners figure.

The GA's run is `walkers evolve`'s; differential evolution's is a walkers.Run
whose children scipy.optimize.differential_evolution proposes: one call of its
vectorised objective is one generation of the run (its population is the run's,
16 by default). Both runs' finals are re-scored with an ensemble, and the
learners figure (scripts/walkers_stats/figures.py) sets them side by side.

    PYTHONPATH=build/python /usr/bin/python3 examples/scipy_de.py --out runs/scipy_de

writes OUT/ga/ and OUT/de/ (run folders, as `walkers evolve` writes them) and
OUT/figures/learners.png and .svg. A finished run is kept and not made again;
an unfinished GA run is resumed. SciPy's differential evolution cannot hand
out its state, so an unfinished DE run is started again (--force).
"""
import argparse
import os
import pathlib
import subprocess
import sys

import numpy as np
from scipy.optimize import differential_evolution

import walkers

SOURCE_DIR = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(SOURCE_DIR / "scripts"))
from walkers_stats import figures  # noqa: E402
from walkers_stats.load import load_generations  # noqa: E402

CASE = "performance"


def finished(run_dir):
    return (run_dir / "best.json").exists()


def ga_run(args, run_dir):
    """The paper's GA under the scaffold, by the program itself."""
    if finished(run_dir):
        return
    command = [args.walkers, "evolve", "--case", CASE, "--generations", str(args.generations),
               "--population", str(args.population), "--seed", str(args.seed),
               # the paper's share of mutation children: 10 of 16
               "--mutation-children", str(args.population * 10 // 16),
               "--threads", str(args.threads), "--out", str(run_dir)]
    if (run_dir / "config.json").exists():
        command.append("--resume")
    subprocess.run(command, check=True)


def de_run(args, run_dir):
    """SciPy's differential evolution under the scaffold, through walkers.Run."""
    if finished(run_dir):
        return
    force = (run_dir / "config.json").exists()
    with walkers.Run(run_dir, case=CASE, generations=args.generations, population=args.population,
                     seed=args.seed, threads=args.threads, force=force) as run:
        def objective(x):
            # x: (18, population), one column a trial genome; one call, one generation
            _, results = run.evaluate(x.T)
            run.checkpoint(None)  # SciPy keeps its state to itself
            p = run.progress
            print(f"de/{CASE} gen {p['generation']}/{args.generations}  best {p['best_fitness']:.3f}  "
                  f"ceiling {p['ceiling']:.3f}", flush=True)
            return -results["fitness"]

        # the initial population: the initial individual, the rest uniform in Table 1's bounds
        rng = np.random.default_rng(args.seed)
        init = walkers.gene_floors + (walkers.gene_ceilings - walkers.gene_floors) * rng.random(
            (args.population, 18))
        init[0] = walkers.gene_defaults
        # Table 1's bounds; the scaffold's ceiling on halfBodyX is the run's clamp
        bounds = list(zip(walkers.gene_floors, walkers.gene_ceilings))
        differential_evolution(objective, bounds, init=init, maxiter=args.generations - 1, seed=args.seed,
                               vectorized=True, updating="deferred", polish=False, tol=0, atol=0)
        if not run.done:
            sys.exit(f"{run_dir}: differential evolution stopped after {run.completed_generations} generations")


def rescored(run_dir, ensemble):
    """The run's final best, re-scored with an ensemble: its median, as reproduce re-scores."""
    result = walkers.evaluate(str(run_dir / "best.json"), ensemble=ensemble)
    return {"rescore": {"median": result["ensemble"]["fitness_median"]}}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", required=True, type=pathlib.Path)
    parser.add_argument("--generations", type=int, default=300)
    parser.add_argument("--population", type=int, default=16)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--threads", type=int, default=os.cpu_count())
    parser.add_argument("--ensemble", type=int, default=25, help="re-scores of each final best")
    parser.add_argument("--walkers", default=str(SOURCE_DIR / "build" / "app" / "walkers"),
                        help="the walkers program, for the GA's run")
    args = parser.parse_args()
    if args.generations < 2:
        parser.error("--generations must be at least 2 (differential evolution's first population and one step)")

    args.out.mkdir(parents=True, exist_ok=True)
    ga_run(args, args.out / "ga")
    de_run(args, args.out / "de")

    learners = {l["name"]: l for l in walkers.learners()}
    shown = [learners["ga"], {**learners["external"], "label": "SciPy differential evolution"}]
    scaffold = next(s for s in walkers.scaffolds() if s["name"] == CASE)
    scaffold["number"] = walkers.scaffold_cases().index(CASE) + 1
    runs = [{"learner": learner["name"], "case": CASE, "final_best": rescored(args.out / folder, args.ensemble),
             "data": load_generations(str(args.out / folder / "generations.csv"))}
            for learner, folder in zip(shown, ("ga", "de"))]
    for learner, run in zip(shown, runs):
        print(f"{learner['label']}: final best {run['data']['best_fitness'][-1]:.3f}, "
              f"re-scored median {run['final_best']['rescore']['median']:.3f}")
    out_dir = args.out / "figures"
    out_dir.mkdir(exist_ok=True)
    figures.learners_figure(shown, runs, [scaffold], args.generations, str(out_dir))


if __name__ == "__main__":
    main()
