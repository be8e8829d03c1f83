"""A small optimiser driving walkers.Run, for tests/python/run_test.py: each
generation's children are normal draws about a mean, from a stream of the
generation's own; the mean then moves to the fittest child evaluated. The mean
is the optimiser's whole state, so a run resumed from its checkpoint proposes
what the uninterrupted run proposes.

usage: ask_tell_driver.py OUT GENERATIONS POPULATION SEED
(resumes the run in OUT if it has one)
"""
import os
import sys

import numpy as np

import walkers


def main(out, generations, population, seed):
    resume = os.path.exists(os.path.join(out, "config.json"))
    with walkers.Run(out, case="performance", generations=generations, population=population, seed=seed,
                     threads=2, resume=resume) as run:
        mean = np.array(run.state["mean"]) if run.state else walkers.gene_defaults.copy()
        while not run.done:
            lo, hi = run.bounds()
            rng = np.random.default_rng([seed, run.completed_generations])
            proposals = np.clip(mean + 0.2 * (hi - lo) * rng.standard_normal((run.population, 18)), lo, hi)
            genomes, results = run.evaluate(proposals)
            mean = genomes[np.argmax(results["fitness"])]
            run.checkpoint({"mean": mean.tolist()})


if __name__ == "__main__":
    main(sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), int(sys.argv[4]))
