"""The Python module walkers (python/walkers_module.cc, docs/python.md): the
gene table and genome conversions, evaluations equal to the program's bit for
bit, batches identical on 1 and 2 threads, bad input as ValueError naming the
field, and the GIL released while the walkers walk.

ctest runs it with PYTHONPATH at the module, WALKERS_PROGRAM the walkers
program and WALKERS_SOURCE_DIR the repository; by hand, from the repository
after a build: PYTHONPATH=build/python python3 -m pytest tests/python
"""
import csv
import json
import os
import pathlib
import subprocess
import threading
import time

import numpy as np
import pytest

import walkers

SOURCE_DIR = pathlib.Path(os.environ.get("WALKERS_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
PROGRAM = os.environ.get("WALKERS_PROGRAM", str(SOURCE_DIR / "build" / "app" / "walkers"))
GENOMES = SOURCE_DIR / "data" / "genomes"
# cheap to evaluate: the initial individual stalls, the faller falls
DEFAULT = GENOMES / "default.json"
FALLER = GENOMES / "bench" / "evolved_faller.json"
MASSES = ("kneeMass", "ankleMass", "hipMass")


def cli_evaluate(path, *args):
    """`walkers evaluate --json` of a genome file, parsed."""
    out = subprocess.run([PROGRAM, "evaluate", "--genome", str(path), "--json", *args],
                         check=True, capture_output=True, text=True).stdout
    return json.loads(out)


def test_gene_table_is_the_programs():
    assert len(walkers.gene_names) == 18
    assert walkers.gene_names[0] == "halfBodyX" and walkers.gene_names[-1] == "stepOffset"
    default = walkers.default_genome()
    # the genes in the table's order, then the fixed masses
    assert tuple(default)[:18] == walkers.gene_names and set(tuple(default)[18:]) == set(MASSES)
    np.testing.assert_array_equal(walkers.gene_defaults, [default[n] for n in walkers.gene_names])
    # the initial individual inside its bounds, which are not empty
    assert np.all(walkers.gene_floors < walkers.gene_ceilings)
    assert np.all(walkers.gene_floors <= walkers.gene_defaults)
    assert np.all(walkers.gene_defaults <= walkers.gene_ceilings)
    # the mutation widths: the default over a divisor (stepOffset's default, and so its sigma, is negative)
    assert np.all(walkers.gene_sigmas != 0)
    assert np.all(np.abs(walkers.gene_sigmas) < np.abs(walkers.gene_defaults))
    assert walkers.file_floor_half_body_x < walkers.gene_floors[0]
    # the initial individual's file holds the same genome
    assert walkers.load_genome(DEFAULT) == default


def test_genome_converts_between_files_dicts_and_arrays(tmp_path):
    genome = walkers.load_genome(str(FALLER))
    genes = walkers.genome_array(genome)
    assert genes.shape == (18,) and genes.dtype == np.float64
    assert list(genes) == [genome[n] for n in walkers.gene_names]
    # an array carries the genes only: the masses are the fixed defaults
    assert all(genome[m] == walkers.default_genome()[m] for m in MASSES)
    assert walkers.genome_dict(genes) == genome
    assert walkers.genome_dict(list(genes)) == genome
    path = tmp_path / "saved.json"
    walkers.save_genome(genes, str(path))
    assert walkers.load_genome(path) == genome
    assert json.loads(path.read_text()) == genome


@pytest.mark.parametrize("path", [DEFAULT, FALLER], ids=["default", "faller"])
def test_evaluate_equals_the_program_bit_for_bit(path):
    cli = cli_evaluate(path)
    for genome in (str(path), walkers.load_genome(path), walkers.genome_array(walkers.load_genome(path))):
        ours = walkers.evaluate(genome)
        assert set(ours) == set(cli)
        for key in cli:
            if key != "wall_ms":  # the only field that is not deterministic
                assert ours[key] == cli[key], key
    assert cli["fitness"] != -1 or cli["fell"]  # a real evaluation, not a default


def test_evaluate_ensemble_equals_the_programs():
    cli = cli_evaluate(FALLER, "--ensemble", "3")["ensemble"]
    ours = walkers.evaluate(str(FALLER), ensemble=3)["ensemble"]
    assert ours == cli
    assert ours["size"] == 3 and len(ours["fitness"]) == 3


def test_the_integrator_and_its_cut_off_are_passed_on():
    # rk-merson bit for bit as the program evaluates it, its ensemble too
    cli = cli_evaluate(FALLER, "--integrator", "rk-merson", "--ensemble", "3")
    ours = walkers.evaluate(str(FALLER), integrator="rk-merson", ensemble=3)
    assert ours["integrator"] == "rk-merson"
    for key in cli:
        if key != "wall_ms":
            assert ours[key] == cli[key], key
    assert ours["cvode_steps"] != walkers.evaluate(str(FALLER))["cvode_steps"]
    # a cut-off below what the initial individual takes: -124, as the authors' evolver scored it
    cut = walkers.evaluate(str(DEFAULT), integrator="rk-merson", cut_off=2000)
    assert cut["cut_off"] and cut["fitness"] == -124.0
    assert cli_evaluate(DEFAULT, "--integrator", "rk-merson", "--cut-off", "2000")["fitness"] == -124.0
    assert not walkers.evaluate(str(FALLER), integrator="rk-merson", cut_off="none")["cut_off"]
    batch = walkers.evaluate_batch(batch_genomes()[:2], threads=1, integrator="rk-merson", cut_off=2000)
    assert list(batch["fitness"]) == [walkers.evaluate(g, integrator="rk-merson", cut_off=2000)["fitness"]
                                      for g in batch_genomes()[:2]]


def test_paper_preset_is_passed_on():
    cli = cli_evaluate(DEFAULT, "--preset", "paper")
    ours = walkers.evaluate(str(DEFAULT), preset="paper")
    assert ours["preset"] == "paper"
    assert (ours["fitness"], ours["cvode_steps"]) == (cli["fitness"], cli["cvode_steps"])


def test_recorded_walk_is_the_evaluation_frame_by_frame():
    walk = walkers.record_walk(str(FALLER))
    result = walkers.evaluate(str(FALLER))
    for key in ("fitness", "gait", "leg_length", "preset"):
        assert walk[key] == result[key], key
    frames = walk["frames"]
    t = frames["t"]
    assert t[0] == 0 and np.all(np.diff(t) > 0) and t[-1] <= 15
    assert frames["trunk"].shape == (len(t), 3)  # x, y, pitch
    assert all(len(v) == len(t) for v in frames.values())
    assert frames["planted_l"].dtype == bool
    assert set(walk["body"]) >= {"half_body_x", "femur_length"}


def batch_genomes():
    """Four cheap genomes, two of them perturbed so that the rows differ."""
    default = walkers.genome_array(walkers.default_genome())
    faller = walkers.genome_array(walkers.load_genome(FALLER))
    longer = default.copy()
    longer[walkers.gene_names.index("tibiaLength")] *= 1.05
    return np.stack([default, faller, longer, faller])


def test_batch_is_identical_on_1_and_2_threads_and_equals_evaluate():
    genomes = batch_genomes()
    one = walkers.evaluate_batch(genomes, threads=1)
    two = walkers.evaluate_batch(genomes, threads=2)
    assert set(one) == {"fitness", "gait", "fell", "footsteps", "cvode_steps"}
    for key in one:
        assert one[key].shape == (4,), key
        np.testing.assert_array_equal(one[key], two[key], err_msg=key)
    singles = [walkers.evaluate(g) for g in genomes]
    assert list(one["fitness"]) == [s["fitness"] for s in singles]
    assert list(one["gait"]) == [s["gait"] for s in singles]
    assert list(one["fell"]) == [s["fell"] for s in singles]
    assert list(one["footsteps"]) == [s["footsteps"] for s in singles]
    assert list(one["cvode_steps"]) == [s["cvode_steps"] for s in singles]
    assert one["fell"][1] and not one["fell"][0]  # the faller falls, the initial individual stands
    assert one["fitness"][0] != one["fitness"][2]  # the rows are evaluated as given


def test_batch_equals_a_runs_recorded_evaluations(tmp_path):
    # a generation of `walkers evolve`, evaluated on the same evaluator: its
    # recorded genes (written exactly) give its recorded results again
    subprocess.run([PROGRAM, "evolve", "--case", "performance", "--generations", "1", "--seed", "3", "--threads",
                    "2", "--population", "6", "--archive", "6", "--mutation-children", "6", "--out",
                    str(tmp_path / "run")], check=True, capture_output=True)
    with open(tmp_path / "run" / "evaluations.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == 6
    genomes = np.array([[float(row[name]) for name in walkers.gene_names] for row in rows])
    out = walkers.evaluate_batch(genomes, threads=2)
    assert list(out["fitness"]) == [float(row["fitness"]) for row in rows]
    assert list(out["cvode_steps"]) == [int(row["cvode_steps"]) for row in rows]
    assert list(out["gait"]) == [row["gait"] for row in rows]
    assert list(out["fell"]) == [row["fell"] == "1" for row in rows]
    assert list(out["footsteps"]) == [int(row["footsteps"]) for row in rows]


def test_empty_batch():
    out = walkers.evaluate_batch(np.empty((0, 18)), threads=1)
    assert all(v.shape == (0,) for v in out.values())


def out_of_range(name, value):
    genome = walkers.default_genome()
    genome[name] = value
    return genome


@pytest.mark.parametrize("call, words", [
    (lambda: walkers.evaluate(out_of_range("kStep", 900.0)), ["kStep", "900", "[0, 800]"]),
    (lambda: walkers.evaluate(out_of_range("halfBodyX", 0.001)), ["halfBodyX", "[0.01, 0.9]"]),
    (lambda: walkers.evaluate(out_of_range("femurLength", float("nan"))), ["femurLength"]),
    (lambda: walkers.evaluate(out_of_range("ky", "hard")), ["ky", "hard"]),
    (lambda: walkers.evaluate(out_of_range("ky", np.ones(2))), ["ky"]),
    (lambda: walkers.evaluate(out_of_range("ky", 10**400)), ["ky", "1000"]),
    (lambda: walkers.evaluate({**walkers.default_genome(), "tailLength": 1.0}), ["tailLength"]),
    (lambda: walkers.evaluate({k: v for k, v in walkers.default_genome().items() if k != "hipMass"}),
     ["hipMass"]),
    (lambda: walkers.evaluate(np.zeros(17)), ["(18,)", "(17,)"]),
    (lambda: walkers.evaluate("no/such/genome.json"), ["no/such/genome.json"]),
    (lambda: walkers.evaluate(walkers.default_genome(), preset="fast"), ["fast", "original"]),
    (lambda: walkers.evaluate(walkers.default_genome(), ensemble=0), ["ensemble", "[1, 1000]"]),
    (lambda: walkers.evaluate_batch(np.zeros((3, 17))), ["(n, 18)", "(3, 17)"]),
    (lambda: walkers.evaluate_batch(np.zeros(18)), ["(n, 18)", "(18,)"]),
    (lambda: walkers.evaluate_batch(batch_genomes(), threads=0), ["threads", "[1, 1024]"]),
    (lambda: walkers.evaluate_batch(np.vstack([batch_genomes()[:2], walkers.gene_ceilings * 2])),
     ["genomes[2]", "halfBodyX"]),
    (lambda: walkers.scaffold_ceiling("slow", 0), ["slow", "performance"]),
    (lambda: walkers.evaluate(walkers.default_genome(), integrator="euler"), ["euler", "cvode, rk-merson"]),
    (lambda: walkers.evaluate(walkers.default_genome(), accuracy=0.01), ["accuracy", "rk-merson"]),
    (lambda: walkers.evaluate(walkers.default_genome(), integrator="rk-merson", accuracy=2.0), ["accuracy", "(0, 1]"]),
    (lambda: walkers.evaluate(walkers.default_genome(), integrator="rk-merson", cut_off="never"), ["cut_off", "never"]),
    (lambda: walkers.evaluate(walkers.default_genome(), integrator="rk-merson", cut_off=-5), ["cut_off", "[0"]),
], ids=["above", "below", "nan", "text", "array", "huge", "unknown", "missing", "gene count", "no file", "preset", "ensemble",
        "columns", "rows", "threads", "row", "scaffold", "integrator", "accuracy alone", "accuracy", "cut-off word",
        "cut-off"])
def test_bad_input_is_a_value_error_naming_the_field(call, words):
    with pytest.raises(ValueError) as error:
        call()
    for word in words:
        assert word in str(error.value)


@pytest.mark.parametrize("evaluation", [
    lambda: walkers.evaluate_batch(batch_genomes()[:2], threads=1),
    lambda: walkers.evaluate(str(DEFAULT)),
], ids=["evaluate_batch", "evaluate"])
def test_the_gil_is_released(evaluation):
    # another Python thread ticks through the evaluation: with the GIL held it
    # could not tick at all between the call's start and its end
    ticks, stop = [], threading.Event()

    def tick():
        while not stop.is_set():
            ticks.append(time.perf_counter())
            sum(range(100))

    ticker = threading.Thread(target=tick)
    ticker.start()
    while not ticks:
        time.sleep(0.001)
    start = time.perf_counter()
    evaluation()
    end = time.perf_counter()
    stop.set()
    ticker.join()
    middle = [t for t in ticks if start + 0.25 * (end - start) < t < start + 0.75 * (end - start)]
    assert end - start > 0.05  # long enough to tell
    assert len(middle) > 100


def test_scaffold_ceilings():
    assert walkers.scaffold_cases() == ["free", "time", "performance"]
    # case 1 keeps halfBodyX's own ceiling; the others start there and lower it
    for generation in (0, 1000, 3999):
        assert walkers.scaffold_ceiling("free", generation) == walkers.gene_ceilings[0]
    assert walkers.scaffold_ceiling("time", 3999) < walkers.scaffold_ceiling("time", 0)
    assert walkers.scaffold_ceiling("performance", 100, ave_best3=40.0) < \
        walkers.scaffold_ceiling("performance", 100, ave_best3=5.0)
