"""Synthetic inputs of the statistics package, written as the `walkers` program writes
them: a reproduction folder (reproduction.json, every run's generations.csv, walks.json,
gallery.json) and a stand-in for a checkout of the authors' repository (their
fitness-data, bump-data and summarisedOutput files). Nothing here comes from real runs."""
import csv
import json
import math
import os
import subprocess
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
SCRIPTS = os.path.join(ROOT, "scripts")
PACKAGE = os.path.join(SCRIPTS, "walkers_stats")
sys.path.insert(0, SCRIPTS)

from walkers_stats import load  # noqa: E402

# a reproduction.json's list of scaffolds: names, labels, colours and the paper's
# tripods of three, in the paper's order
SCAFFOLDS = [{"name": "free", "label": "free", "colour": "tab:green", "paper_tripod_finals": 0},
             {"name": "time", "label": "time-constrained", "colour": "tab:orange",
              "paper_tripod_finals": 2},
             {"name": "performance", "label": "performance-based", "colour": "tab:purple",
              "paper_tripod_finals": 0}]
CASES = tuple(s["name"] for s in SCAFFOLDS)
LEARNERS = {"ga": {"name": "ga", "label": "genetic algorithm", "colour": "tab:blue"},
            "cmaes": {"name": "cmaes", "label": "CMA-ES", "colour": "tab:red"},
            "pso": {"name": "pso", "label": "particle swarm", "colour": "tab:brown"}}
POPULATION = 16


def run_statistics(*args):
    """`python3 scripts/walkers_stats ARGS` as `walkers reproduce` runs it: (exit
    status, stdout, stderr)."""
    proc = subprocess.run([sys.executable, PACKAGE, *args], capture_output=True, text=True,
                          timeout=600)
    return proc.returncode, proc.stdout, proc.stderr


def write_json(path, obj):
    """Dump obj as JSON to path."""
    with open(path, "w", encoding="utf-8") as f:
        json.dump(obj, f)


def edit_json(path, change):
    """Load a JSON file, apply change(obj) in place and write it back."""
    with open(path, encoding="utf-8") as f:
        obj = json.load(f)
    change(obj)
    write_json(path, obj)


def write_generations(path, fitness, gaits, half_body_x=None, falls=3, evals_per_s=40.0):
    """A generations.csv with the given best fitness and gait per generation."""
    n = len(fitness)
    half_body_x = [0.5] * n if half_body_x is None else half_body_x
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(load.GEN_COLUMNS)
        for g in range(n):
            w.writerow([g, repr(float(fitness[g])), fitness[g] - 0.5, fitness[g] - 2, 0.9,
                        half_body_x[g], 0.53 + 0.001 * g, 0.68 + 0.002 * g, gaits[g], falls,
                        evals_per_s])


def rescore(median, size=1, low=None, high=None):
    """A re-score of `size` members with the given median (and range)."""
    low, high = median if low is None else low, median if high is None else high
    members = sorted([low, high] + [median] * (size - 2)) if size > 2 else [median] * size
    return {"fitness": members, "median": median, "min": low, "max": high, "bipeds": size,
            "tripods": 0, "falls": 0, "recorded_reproduced": True}


def finalist(ident, fitness, gait, median=None, size=1):
    """A finalist of reproduction.json: recorded fitness, gait and re-score."""
    return {"id": ident, "fitness": fitness, "gait": gait,
            "rescore": rescore(fitness if median is None else median, size)}


def run(case, replicate, fitness, gaits, best_biped=None, best_tripod=None, medians=None,
        learner="ga", half_body_x=None, cut_offs=None):
    """One run: its curve and gaits per generation, its best biped's and best tripod's
    recorded fitness (None: none), the re-scored medians of its finals
    (medians: {"final_best"|"best_biped"|"best_tripod": median}, else the recorded), and
    with cut_offs ({generation: children cut off}) an evaluations.csv."""
    return {"learner": learner, "case": case, "replicate": replicate,
            "fitness": np.asarray(fitness, float), "gaits": list(gaits), "best_biped": best_biped,
            "best_tripod": best_tripod, "medians": medians or {}, "half_body_x": half_body_x,
            "cut_offs": cut_offs}


# a reproduction.json's program.evaluation under the authors' integrator and cut-off
RK_MERSON = {"relative_tolerance": 1e-7, "integrator": "rk-merson", "accuracy": 0.05,
             "constraint_tolerance": 0.01, "cut_off_rhs": 128000}


def write_evaluations(path, generations, cut_offs, population=POPULATION):
    """An evaluations.csv of `generations` x `population` children, cut_offs[g] of
    generation g's scoring -124; a child of each generation failed with a reason that
    holds commas."""
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["generation", "child", "parents", "halfBodyX", "fitness", "distance", "fell",
                    "gait", "footsteps", "trunk_contact_fraction", "cvode_steps", "failure",
                    "wall_ms"])
        for g in range(generations):
            k = cut_offs.get(g, 0)
            for c in range(population):
                cut = c < k
                failed = c == population - 1 and not cut
                w.writerow([g, c, "" if g == 0 else f"{g - 1}/0", 0.5, -124 if cut else -1 if failed
                            else 2.5, 1.0, 0, "none" if cut or failed else "biped", 3, 0.0, 500,
                            "the step size fell, at t=7.9, to 0" if failed else "", 1.5])


def write_reproduction(root, runs, generations=None, learners=("ga",), ensemble=1,
                       scaffolds=SCAFFOLDS, walks=None, gallery=None, evaluation=None, folder="rep"):
    """A reproduction folder ROOT/FOLDER of `runs` (run()'s), made under `evaluation`
    (program.evaluation; CVODE's by default); returns its path."""
    rep = os.path.join(root, folder)
    os.makedirs(rep)
    listed = []
    for r in runs:
        prefix = "" if r["learner"] == learners[0] else r["learner"] + "-"
        name = f"{prefix}{r['case']}-{r['replicate']}"
        os.makedirs(os.path.join(rep, name))
        write_generations(os.path.join(rep, name, "generations.csv"), r["fitness"], r["gaits"],
                          r["half_body_x"])
        write_json(os.path.join(rep, name, "config.json"),
                   {"case": r["case"], "seed": r["replicate"],
                    "evaluation": evaluation or {"relative_tolerance": 1e-7}})
        if r["cut_offs"] is not None:
            write_evaluations(os.path.join(rep, name, "evaluations.csv"), len(r["fitness"]),
                              r["cut_offs"])
        last = len(r["fitness"]) - 1
        final = float(r["fitness"][-1])
        gait = r["gaits"][-1] if r["gaits"][-1] != "none" else "biped"
        entry = {"learner": r["learner"], "case": r["case"], "replicate": r["replicate"],
                 "dir": name, "seed": r["replicate"],
                 "final_best": finalist(f"{last}/0", final, gait,
                                        r["medians"].get("final_best"), ensemble)}
        for key, g in (("best_biped", "biped"), ("best_tripod", "tripod")):
            entry[key] = None if r[key] is None else \
                finalist(f"{last}/1", float(r[key]), g, r["medians"].get(key), ensemble)
        listed.append(entry)

    def pick(gait):
        """The first learner's best of a gait by re-scored median, as the program picks it."""
        best = None
        for e in listed:
            f = e[f"best_{gait}"]
            if e["learner"] == learners[0] and f is not None and \
                    (best is None or f["rescore"]["median"] > best[1]["rescore"]["median"]):
                best = (e["dir"], f)
        return None if best is None else {"run": best[0], "id": best[1]["id"]}

    write_json(os.path.join(rep, "reproduction.json"), {
        "preset": "original",
        "generations": generations or max(len(r["fitness"]) for r in runs),
        "replicates": max(r["replicate"] for r in runs), "seed": 1, "population": POPULATION,
        "ensemble": ensemble,
        "program": {"commit": "0123456789ab",
                    "evaluation": evaluation or {"relative_tolerance": 1e-7}},
        "scaffolds": scaffolds, "learners": [LEARNERS[l] for l in learners],
        "runs": listed, "best_biped": pick("biped"), "best_tripod": pick("tripod")})
    if walks is not None:
        write_json(os.path.join(rep, "walks.json"), walks)
    if gallery is not None:
        write_json(os.path.join(rep, "gallery.json"), gallery)
    return rep


def claims_runs(spec, generations=20, learner="ga"):
    """The runs of {case: [(final, biped from generation or None, best biped, best
    tripod[, {medians}])]}: each run's best fitness rises linearly from 1 to its final,
    a tripod until its biped generation."""
    runs = []
    for case, items in spec.items():
        for r, item in enumerate(items, 1):
            final, biped_from, best_biped, best_tripod = item[:4]
            gaits = ["tripod" if biped_from is None or g < biped_from else "biped"
                     for g in range(generations)]
            runs.append(run(case, r, np.linspace(1.0, final, generations), gaits, best_biped,
                            best_tripod, item[4] if len(item) > 4 else None, learner=learner))
    return runs


def claims_reproduction(root, spec, generations=20, **kwargs):
    """A reproduction folder of claims_runs(spec); returns its path."""
    return write_reproduction(root, claims_runs(spec, generations), generations, **kwargs)


# ----------------------------------------------------------------------------- walks, gallery

FRAMES = 451


def body(half_body_x, femur, tibia, half_foot_x):
    """A body dict in the walks.json / gallery.json format."""
    return {"half_body_x": half_body_x, "half_body_y": 0.12, "half_foot_x": half_foot_x,
            "half_foot_y": 0.04, "femur_length": femur, "tibia_length": tibia,
            "knee_radius": 0.1}


def knee(hip, ankle, femur, tibia):
    """Two-link inverse kinematics: the knee point, bent forward."""
    hip, ankle = np.asarray(hip, float), np.asarray(ankle, float)
    d = ankle - hip
    dist = min(np.linalg.norm(d), 0.999 * (femur + tibia))
    a = (femur ** 2 - tibia ** 2 + dist ** 2) / (2 * dist)
    h = math.sqrt(max(femur ** 2 - a ** 2, 0.0))
    u = d / np.linalg.norm(d)
    normal = np.array([-u[1], u[0]])            # left of hip->ankle = forward when down
    return hip + a * u + h * normal


def pose(b, hip, ankle_l, ankle_r, pitch, trunk_dx):
    """A pose dict (lists) with the trunk centred trunk_dx behind the hip."""
    c, s = math.cos(pitch), math.sin(pitch)
    trunk = [hip[0] - trunk_dx * c, hip[1] - trunk_dx * s, pitch]
    f, t = b["femur_length"], b["tibia_length"]
    return {"trunk": trunk, "hip": list(hip),
            "knee_l": knee(hip, ankle_l, f, t).tolist(), "ankle_l": list(ankle_l),
            "foot_l": 0.0,
            "knee_r": knee(hip, ankle_r, f, t).tolist(), "ankle_r": list(ankle_r),
            "foot_r": 0.0}


def walk(gait, run_name, speed, b, fitness):
    """A synthetic 15-s walk (451 frames at 30 Hz) in the walks.json format."""
    leg = b["femur_length"] + b["tibia_length"]
    t = np.linspace(0.0, 15.0, FRAMES)
    hip_x = speed * t + 0.02 * np.sin(4 * t)
    hip_y = 0.9 * leg + 0.03 * np.cos(8 * t)
    ank_l_x = hip_x + 0.25 * np.sin(4 * t)
    ank_r_x = hip_x - 0.25 * np.sin(4 * t)
    ank_l_y = b["half_foot_y"] + np.maximum(0.0, 0.08 * np.sin(4 * t))
    ank_r_y = b["half_foot_y"] + np.maximum(0.0, -0.08 * np.sin(4 * t))
    pitch = 0.3 if gait == "tripod" else 0.0
    trunk_dx = b["half_body_x"] * 0.9 if gait == "tripod" else 0.0
    frames = {k: [] for k in ("trunk", "hip", "knee_l", "ankle_l", "foot_l", "knee_r",
                              "ankle_r", "foot_r")}
    for i in range(FRAMES):
        p = pose(b, (hip_x[i], hip_y[i]), (ank_l_x[i], ank_l_y[i]),
                 (ank_r_x[i], ank_r_y[i]), pitch, trunk_dx)
        for k in frames:
            frames[k].append(p[k])
    com = np.column_stack([hip_x - 0.1, hip_y - 0.2])
    vel = np.gradient(com, t, axis=0)
    frames.update({
        "t": t.tolist(), "state": ["DS"] * FRAMES, "x_target": (hip_x + 0.1).tolist(),
        "planted_l": (ank_l_y <= b["half_foot_y"]).tolist(),
        "planted_r": (ank_r_y <= b["half_foot_y"]).tolist(),
        "distance": np.minimum(ank_l_x, ank_r_x).tolist(),
        "com": com.tolist(), "com_velocity": vel.tolist()})
    return {"title": f"best {gait}", "run": run_name, "id": "50/3", "fitness": fitness,
            "gait": gait, "leg_length": leg, "preset": "original", "body": b,
            "frames": frames}


def gallery():
    """Six individuals (three bipeds, three tripods) standing at x = 0."""
    people = []
    for k, (gait, hbx) in enumerate([("biped", 0.5), ("biped", 0.2), ("biped", 0.04),
                                     ("tripod", 0.9), ("tripod", 0.7), ("tripod", 0.5)]):
        b = body(hbx, 0.45 + 0.02 * k, 0.6 + 0.03 * k, 0.25 - 0.03 * (k % 3))
        leg = b["femur_length"] + b["tibia_length"]
        hip = (0.05, 0.93 * leg)
        trunk_dx = 0.9 * hbx if gait == "tripod" else 0.0
        people.append({"label": f"performance-{k % 2 + 1} gen {20 * k}",
                       "run": f"performance-{k % 2 + 1}", "id": f"{20 * k}/1",
                       "gait": gait, "fitness": 5.0 + k, "body": b,
                       "pose": pose(b, hip, (0.0, 0.04), (0.0, 0.04),
                                    0.3 if gait == "tripod" else 0.0, trunk_dx)})
    return {"individuals": people}


def evolving_runs(replicates, generations, learner="ga"):
    """Plausible evolution: fitness rising by random steps, the body shrinking, each
    run a tripod for a while (performance-2 to the end), its finals re-scored a little
    lower than recorded."""
    runs = []
    for c, case in enumerate(CASES):
        for r in range(1, replicates + 1):
            gen = np.random.default_rng(10 * c + r)
            fitness = 4.0 + np.maximum.accumulate(np.cumsum(gen.uniform(0, 0.3, generations)))
            tripod_until = 15 * (c + r)
            gaits = ["tripod" if g < tripod_until else "biped" for g in range(generations)]
            hbx = [0.9 * math.exp(-g / 25) + 0.035 for g in range(generations)]
            runs.append(run(case, r, fitness, gaits, best_biped=fitness[-1] * 0.9,
                            best_tripod=fitness[-1] * 0.6,
                            medians={"final_best": fitness[-1] - 0.2}, learner=learner,
                            half_body_x=hbx))
    return runs


# ----------------------------------------------------------------------------- the authors

def write_authors_run(path, improvements):
    """One run's file in the authors' format from [(generation, best fitness)]."""
    generations = [str(g) for g, _ in improvements]
    fitness = [repr(float(f)) for _, f in improvements]
    with open(path, "w", encoding="utf-8") as f:
        f.write(",\n".join(generations) + f"\ncount: {len(generations)}\n")
        f.write(",\n".join(fitness) + f"\ncount: {len(fitness)}\n")


def write_authors_labels(path, improvements, gaits):
    """One run's gait labels in the authors' bump-data layout (bump, generation_child,
    fitness, a genome line): [(generation, best fitness)] with a gait each."""
    with open(path, "w", encoding="utf-8") as f:
        f.write("$ their script\n")
        for k, ((g, fitness), gait) in enumerate(zip(improvements, gaits), 1):
            f.write(f"bump {k} >>> {gait}\ncurrentGen:\n{g}_{k % 16}\nmaxFitness:\n{fitness!r}\n"
                    "walkerVis.o 0.5 0.1\n\n")
        f.write(f"count: {len(improvements)}\n\n2400\n>>>\n")


def write_authors_children(path, cut_offs, population=POPULATION):
    """One run's summarisedOutput: paper's generations of `population` children each,
    cut_offs[g] of them (0 where absent) scoring -124, the others 1.5."""
    with open(path, "w", encoding="utf-8") as f:
        for g in range(4000):
            k = cut_offs.get(g, 0)
            fitness = ", ".join(["-124"] * k + ["1.5"] * (population - k))
            f.write(f"Generation: {g}\nCurrent Fitness:\n[{fitness}]\n\nAll time fittest:\n"
                    f"[1.5]\n\n")
        f.write("[[{'halfBodyX': 0.05}, 1.5]]Done at 06_14\n")


def authors_checkout(root, runs_by_case, gaits=None, cut_offs=None):
    """A stand-in checkout of the authors' repository: {case number: [improvements of
    run 1, of run 2, ...]} as their fitness-data, their gait labels (gaits: {case:
    [[gait of each improvement] of each run]}, every best a biped where not given) in
    files numbered in the reverse order of the runs (theirs are not always in order),
    and every child's fitness (cut_offs: {case: [{generation: children cut off} of
    each run]}, none where not given); returns its path."""
    checkout = os.path.join(root, "authors")
    folder = os.path.join(checkout, "CaseData", "image", "fitness-data")
    labels = os.path.join(checkout, "CaseData", "image", "bump-data")
    os.makedirs(folder)
    os.makedirs(labels)
    for case, runs in runs_by_case.items():
        children = os.path.join(checkout, "CaseData", f"case{case}")
        os.makedirs(children)
        for m, improvements in enumerate(runs, 1):
            write_authors_run(os.path.join(folder, f"case{case}-{m}.txt"), improvements)
            run_gaits = (gaits or {}).get(case, [["biped"] * len(improvements)] * len(runs))[m - 1]
            write_authors_labels(os.path.join(labels, f"c{case}_{len(runs) + 1 - m}.txt"),
                                 improvements, run_gaits)
            write_authors_children(os.path.join(children, f"summarisedOutput-{m:02d}"),
                                   (cut_offs or {}).get(case, [{}] * len(runs))[m - 1])
    return checkout
