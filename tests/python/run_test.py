"""walkers.Run (python/run_binding.cc, docs/python.md): an ask/tell run under a
scaffold writes the run folder `walkers evolve --learner` writes, evaluates as
the program does bit for bit, applies the GA's rules to the proposals, resumes
after a kill to the same files, and answers bad calls with clear errors.

Run as tests/python/walkers_module_test.py is (its docstring says how).
"""
import csv
import json
import os
import pathlib
import random
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import walkers

HERE = pathlib.Path(__file__).resolve().parent
SOURCE_DIR = pathlib.Path(os.environ.get("WALKERS_SOURCE_DIR", HERE.parents[1]))
DRIVER = HERE / "ask_tell_driver.py"
HALF_BODY_X = walkers.gene_names.index("halfBodyX")


def rows(path):
    """A CSV file's rows as dicts, its wall-clock column dropped."""
    with open(path, newline="", encoding="utf-8") as f:
        return [{k: v for k, v in row.items() if k not in ("wall_ms", "evals_per_s")} for row in csv.DictReader(f)]


def same_run(a, b):
    """The two runs' files are the same, wall-clock columns aside."""
    for name in ("evaluations.csv", "generations.csv"):
        assert rows(a / name) == rows(b / name), name
    for name in ("config.json", "archive.json", "best.json"):
        assert (a / name).read_text() == (b / name).read_text(), name


def uniform(run, rng):
    lo, hi = run.bounds()
    return lo + (hi - lo) * rng.random((run.population, 18))


def test_a_run_writes_the_folder_walkers_evolve_writes(tmp_path):
    rng = np.random.default_rng(3)
    evaluated = []
    with walkers.Run(tmp_path / "run", generations=2, population=4, threads=2) as run:
        assert run.state is None and run.completed_generations == 0 and run.progress is None
        while not run.done:
            genomes, results = run.evaluate(uniform(run, rng))
            evaluated.append((genomes, results))
            run.checkpoint(None)
            assert run.progress["generation"] == run.completed_generations - 1
    config = json.loads((tmp_path / "run" / "config.json").read_text())
    assert config["learner"] == "external" and config["case"] == "performance" and config["population"] == 4
    evaluations = rows(tmp_path / "run" / "evaluations.csv")
    assert [r["parents"] for r in evaluations] == ["external"] * 8
    assert len(rows(tmp_path / "run" / "generations.csv")) == 2
    for f in ("archive.json", "best.json", "checkpoint.json"):
        assert (tmp_path / "run" / f).exists(), f
    # the run's evaluations are the program's, bit for bit
    for g, (genomes, results) in enumerate(evaluated):
        batch = walkers.evaluate_batch(genomes, threads=1)
        np.testing.assert_array_equal(results["fitness"], batch["fitness"])
        recorded = [float(r["fitness"]) for r in evaluations if r["generation"] == str(g)]
        assert recorded == list(results["fitness"])
    # the statistics read the run as any other
    sys.path.insert(0, str(SOURCE_DIR / "scripts"))
    from walkers_stats.load import load_generations
    assert len(load_generations(str(tmp_path / "run" / "generations.csv"))["best_fitness"]) == 2


def test_bounds_are_table_1s_with_the_scaffolds_ceiling(tmp_path):
    with walkers.Run(tmp_path / "run", case="time", generations=1, population=2, threads=1) as run:
        lo, hi = run.bounds()
        ceiling = walkers.scaffold_ceiling("time", 0)
        assert hi[HALF_BODY_X] == max(ceiling, walkers.gene_floors[HALF_BODY_X])
        others = [k for k in range(18) if k != HALF_BODY_X]
        np.testing.assert_array_equal(lo[others], walkers.gene_floors[others])
        np.testing.assert_array_equal(hi[others], walkers.gene_ceilings[others])


def test_proposals_are_clamped_into_their_bounds_and_duplicates_drawn_again(tmp_path):
    with walkers.Run(tmp_path / "run", generations=1, population=3, threads=2) as run:
        lo, hi = run.bounds()
        proposal = walkers.gene_defaults.copy()
        proposal[HALF_BODY_X] = hi[HALF_BODY_X] + 0.5  # beyond the scaffold's ceiling
        genomes, results = run.evaluate(np.tile(proposal, (3, 1)))
        run.checkpoint(None)
    assert genomes[0][HALF_BODY_X] == hi[HALF_BODY_X]
    assert results["parents"][0] == "external clamped"
    # the same genome twice more: drawn again, each a new genome within the bounds
    assert all("redrawn" in p for p in results["parents"][1:])
    assert len({tuple(g) for g in genomes}) == 3
    assert np.all(genomes >= lo) and np.all(genomes <= hi)


def driver(out, generations=5, population=4, seed=7):
    return [sys.executable, str(DRIVER), str(out), str(generations), str(population), str(seed)]


def test_killed_at_a_random_moment_and_resumed_ends_identical(tmp_path):
    start = time.monotonic()
    subprocess.run(driver(tmp_path / "whole"), check=True, timeout=600)
    # somewhere in the run, its start and its generations included
    delay = random.uniform(0.1, 0.9) * (time.monotonic() - start)
    job = subprocess.Popen(driver(tmp_path / "killed"))
    time.sleep(delay)
    job.send_signal(signal.SIGKILL)
    job.wait()
    print(f"killed after {delay:.2f} s")
    subprocess.run(driver(tmp_path / "killed"), check=True, timeout=600)
    same_run(tmp_path / "whole", tmp_path / "killed")


def test_a_closed_run_resumes_with_the_state_it_checkpointed(tmp_path):
    rng = np.random.default_rng(5)
    with walkers.Run(tmp_path / "run", generations=3, population=2, threads=1) as run:
        run.evaluate(uniform(run, rng))
        run.checkpoint({"told": 1, "note": "after generation 0"})
        run.evaluate(uniform(run, rng))  # generation 1 evaluated, never checkpointed
    with walkers.Run(tmp_path / "run", generations=3, population=2, threads=1, resume=True) as run:
        assert run.state == {"told": 1, "note": "after generation 0"}
        assert run.completed_generations == 1
        while not run.done:
            run.evaluate(uniform(run, rng))
            run.checkpoint(None)
    assert [r["generation"] for r in rows(tmp_path / "run" / "generations.csv")] == ["0", "1", "2"]


def test_a_run_checkpointed_with_no_state_resumes_with_none(tmp_path):
    with walkers.Run(tmp_path / "run", generations=2, population=2, threads=1) as run:
        run.evaluate(np.tile(walkers.gene_defaults, (2, 1)))
        run.checkpoint(None)
    with walkers.Run(tmp_path / "run", generations=2, population=2, threads=1, resume=True) as run:
        assert run.state is None and run.completed_generations == 1


def test_bad_calls_are_clear_errors(tmp_path):
    with pytest.raises(ValueError, match="unknown"):
        walkers.Run(tmp_path / "a", case="none")
    with pytest.raises(ValueError, match="population = 1 is outside its allowed range"):
        walkers.Run(tmp_path / "a", population=1)
    with pytest.raises(ValueError, match="resume and force"):
        walkers.Run(tmp_path / "a", resume=True, force=True)
    with pytest.raises(RuntimeError, match="no run to resume"):
        walkers.Run(tmp_path / "none", resume=True)
    with walkers.Run(tmp_path / "a", generations=1, population=2, threads=1) as run:
        with pytest.raises(RuntimeError):  # the folder is this run's
            walkers.Run(tmp_path / "a", generations=1, population=2, resume=True)
        with pytest.raises(RuntimeError, match="call evaluate"):
            run.checkpoint(None)
        with pytest.raises(ValueError, match=r"shape \(2, 18\).*got shape \(3, 18\)"):
            run.evaluate(np.zeros((3, 18)))
        bad = np.tile(walkers.gene_defaults, (2, 1))
        bad[1, 4] = np.nan
        with pytest.raises(ValueError, match=r"genomes\[1\]: gene 'halfFootY' is nan"):
            run.evaluate(bad)
        run.evaluate(np.tile(walkers.gene_defaults, (2, 1)))
        with pytest.raises(RuntimeError, match="call checkpoint"):
            run.bounds()
        with pytest.raises(ValueError, match="state must be a JSON value"):
            run.checkpoint({"x": object()})
        with pytest.raises(ValueError, match="does not come back from JSON"):
            run.checkpoint({"x": 2 ** 70})
        run.checkpoint({"x": 1})
        assert run.done
        with pytest.raises(RuntimeError, match="the run is done"):
            run.bounds()


def test_the_gil_is_released_while_a_generation_is_evaluated(tmp_path):
    ticks = []
    stop = threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.001)

    with walkers.Run(tmp_path / "run", generations=1, population=4, threads=1) as run:
        proposals = np.tile(walkers.gene_defaults, (4, 1))  # the initial individual stalls: 15 s simulated
        ticker = threading.Thread(target=tick)
        ticker.start()
        start = time.monotonic()
        run.evaluate(proposals)
        end = time.monotonic()
        stop.set()
        ticker.join()
        run.checkpoint(None)
    during = [t for t in ticks if start < t < end]
    assert len(during) >= 10, f"{len(during)} ticks in {end - start:.2f} s of evaluation"


def test_the_scipy_example_runs_and_draws_the_learners_figure(tmp_path):
    program = os.environ.get("WALKERS_PROGRAM", str(SOURCE_DIR / "build" / "app" / "walkers"))
    out = subprocess.run([sys.executable, str(SOURCE_DIR / "examples" / "scipy_de.py"), "--out", str(tmp_path),
                          "--generations", "2", "--population", "5", "--ensemble", "2", "--threads", "2",
                          "--walkers", program], check=True, capture_output=True, text=True, timeout=600).stdout
    assert "SciPy differential evolution: final best" in out
    assert (tmp_path / "figures" / "learners.png").stat().st_size > 0
    assert json.loads((tmp_path / "de" / "config.json").read_text())["learner"] == "external"
    assert len(rows(tmp_path / "de" / "generations.csv")) == 2
