"""Reading a reproduction's files, every field checked: the only reader of them in the
statistics (formats as the `walkers` program writes them).

  RUN_DIR/reproduction.json          required: the configuration, the scaffolds (name,
                                     label, colour, paper_tripod_finals, in the paper's
                                     order), the learners (name, label, colour; the first is
                                     the paper's), every run (learner, case, replicate, dir,
                                     seed) with its finals (final_best, best_biped,
                                     best_tripod: id, recorded fitness, gait and the
                                     re-score's ensemble, null for none), and the first
                                     learner's best biped and best tripod (run, id)
  RUN_DIR/<run dir>/generations.csv  required for every run: best fitness, gait, falls and
                                     evaluation rate per generation
  RUN_DIR/<run dir>/evaluations.csv  read only under a cut-off (program.evaluation.cut_off_rhs):
    or cut_offs.csv                  the children cut off (CUT_OFF_FITNESS) per generation;
                                     cut_offs.csv keeps them where evaluations.csv is not
                                     kept (cut_offs.py); a run with neither has none recorded
  RUN_DIR/walks.json                 optional: the best biped's and best tripod's walks
  RUN_DIR/gallery.json               optional: every run's final best standing

A required file that is missing, or any file present but malformed, raises InputError
naming the file and the field (or the line and column).
"""
import csv
import json
import math
import os

import numpy as np

GEN_COLUMNS = ("generation", "best_fitness", "ave_best3", "archive_mean",
               "ceiling_half_body_x", "best_half_body_x", "best_femur", "best_tibia",
               "best_gait", "falls", "evals_per_s")
GAITS = ("biped", "tripod")
BEST_GAITS = GAITS + ("none",)     # a generation whose children all fell has no gait class
BODY_KEYS = ("half_body_x", "half_body_y", "half_foot_x", "half_foot_y",
             "femur_length", "tibia_length", "knee_radius")
POINT_KEYS = ("hip", "knee_l", "ankle_l", "knee_r", "ankle_r")
FRAME_KEYS = ("t", "trunk", "hip", "knee_l", "ankle_l", "foot_l", "knee_r", "ankle_r",
              "foot_r", "distance", "com", "com_velocity")
MANIFEST = "reproduction.json"
CUT_OFF_FITNESS = -124.0     # an evaluation cut off: the authors' past 25 s of wall clock, ours
                             # past a budget of right-hand sides (control/evaluation.h)
CUT_OFFS_FILE = "cut_offs.csv"
CUT_OFFS_COLUMNS = ("generation", "cut_offs")
INTEGRATORS = ("cvode", "rk-merson")   # program.evaluation.integrator; files without it are CVODE's


class InputError(Exception):
    """A missing or malformed input file; the message names the file and the field."""


def read_json(path, required):
    """Parse a JSON file; None if it is absent and not required."""
    if not os.path.isfile(path):
        if required:
            raise InputError(f"{path}: file not found")
        return None
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        raise InputError(f"{path}: not valid JSON ({e})") from None


def field(obj, key, path, where, kind=None):
    """obj[key], checking presence and (optionally) type; errors name file and field."""
    if not isinstance(obj, dict) or key not in obj:
        raise InputError(f"{path}: missing field '{where}{key}'")
    value = obj[key]
    if kind is not None and (not isinstance(value, kind) or isinstance(value, bool)
                             and kind is not bool):
        raise InputError(f"{path}: field '{where}{key}' has the wrong type")
    return value


def number(obj, key, path, where, allow_null=False):
    """obj[key], a finite number (or null when allowed); errors name file and field."""
    value = field(obj, key, path, where)
    if value is None and allow_null:
        return None
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise InputError(f"{path}: field '{where}{key}' must be a finite number"
                         + (" or null" if allow_null else ""))
    return float(value)


def count(obj, key, path, where, low, high):
    """obj[key], an integer in [low, high]; errors name file, field and range."""
    value = field(obj, key, path, where, int)
    if not low <= value <= high:
        raise InputError(f"{path}: field '{where}{key}' is {value}, outside [{low}, {high}]")
    return value


def one_of(obj, key, path, where, allowed):
    """obj[key], a string among `allowed`."""
    value = field(obj, key, path, where, str)
    if value not in allowed:
        raise InputError(f"{path}: field '{where}{key}' is '{value}', expected one of "
                         f"{', '.join(allowed)}")
    return value


def named_list(manifest, key, path, extra=()):
    """manifest[key]: a non-empty list of {name, label, colour, *extra} with distinct
    names (the program's one list of scaffolds or learners), each given its place
    ("number", 1..)."""
    import matplotlib.colors   # only here: the statistics need no plotting otherwise
    items = field(manifest, key, path, "", list)
    if not items:
        raise InputError(f"{path}: field '{key}' is empty")
    out = []
    for i, item in enumerate(items):
        where = f"{key}[{i}]."
        entry = {k: field(item, k, path, where, str) for k in ("name", "label", "colour")}
        if not matplotlib.colors.is_color_like(entry["colour"]):
            raise InputError(f"{path}: field '{where}colour' is '{entry['colour']}', not a colour")
        if entry["name"] in [e["name"] for e in out]:
            raise InputError(f"{path}: field '{where}name' repeats '{entry['name']}'")
        for k, low, high in extra:
            entry[k] = count(item, k, path, where, low, high)
        out.append({**entry, "number": i + 1})
    return out


def load_rescore(obj, path, where, size):
    """A finalist's re-score: its ensemble's members, median and gait counts."""
    fitness = field(obj, "fitness", path, where, list)
    if len(fitness) != size:
        raise InputError(f"{path}: field '{where}fitness' has {len(fitness)} members, "
                         f"not the ensemble's {size}")
    for k, f in enumerate(fitness):
        if isinstance(f, bool) or not isinstance(f, (int, float)) or not math.isfinite(f):
            raise InputError(f"{path}: field '{where}fitness[{k}]' must be a finite number")
    out = {"fitness": [float(f) for f in fitness]}
    for key in ("median", "min", "max"):
        out[key] = number(obj, key, path, where)
    for key in ("bipeds", "tripods", "falls"):
        out[key] = count(obj, key, path, where, 0, size)
    reproduced = field(obj, "recorded_reproduced", path, where)
    if reproduced is not None and not isinstance(reproduced, bool):
        raise InputError(f"{path}: field '{where}recorded_reproduced' must be true, false or null")
    out["recorded_reproduced"] = reproduced
    return out


def load_finalist(obj, key, path, where, size, allow_null):
    """One of a run's finals: {id, fitness (recorded), gait, rescore}, or None."""
    finalist = field(obj, key, path, where)
    if finalist is None and allow_null:
        return None
    where = f"{where}{key}."
    return {"id": field(finalist, "id", path, where, str),
            "fitness": number(finalist, "fitness", path, where),
            "gait": one_of(finalist, "gait", path, where, GAITS),
            "rescore": load_rescore(field(finalist, "rescore", path, where, dict), path,
                                    f"{where}rescore.", size)}


def load_generations(path):
    """generations.csv -> dict of numpy arrays (numbers) and a list 'best_gait'."""
    if not os.path.isfile(path):
        raise InputError(f"{path}: file not found")
    with open(path, newline="", encoding="utf-8") as f:
        reader = csv.DictReader(f)
        missing = [c for c in GEN_COLUMNS if c not in (reader.fieldnames or [])]
        if missing:
            raise InputError(f"{path}: header lacks column(s) {', '.join(missing)}")
        cols = {c: [] for c in GEN_COLUMNS}
        for row in reader:
            line = reader.line_num
            for c in GEN_COLUMNS:
                value = row[c]
                if c == "best_gait":
                    if value not in BEST_GAITS:
                        raise InputError(f"{path}: line {line}, column {c}: '{value}' "
                                         "is not 'biped', 'tripod' or 'none'")
                    cols[c].append(value)
                    continue
                try:
                    cols[c].append(float(value))
                except (TypeError, ValueError):
                    raise InputError(f"{path}: line {line}, column {c}: '{value}' "
                                     "is not a number") from None
    if not cols["generation"]:
        raise InputError(f"{path}: no data rows")
    data = {c: np.asarray(v) for c, v in cols.items() if c != "best_gait"}
    data["best_gait"] = cols["best_gait"]
    return data


def count_cut_offs(path, generations):
    """evaluations.csv -> the children per generation whose fitness is CUT_OFF_FITNESS.
    The generation and fitness come before the one quoted column (failure), so each
    line is split only up to them."""
    with open(path, encoding="utf-8") as f:
        header = f.readline().rstrip("\n").split(",")
        if "generation" not in header or "fitness" not in header:
            raise InputError(f"{path}: header lacks column(s) generation, fitness")
        g_at, f_at = header.index("generation"), header.index("fitness")
        counts = np.zeros(generations, dtype=int)
        for line_number, line in enumerate(f, 2):
            cells = line.split(",", max(g_at, f_at) + 1)
            try:
                g, fitness = int(cells[g_at]), float(cells[f_at])
            except (IndexError, ValueError):
                raise InputError(f"{path}: line {line_number}: no generation and fitness") from None
            if not 0 <= g < generations:
                raise InputError(f"{path}: line {line_number}, column generation: {g} is outside "
                                 f"[0, {generations - 1}]")
            counts[g] += fitness == CUT_OFF_FITNESS
    return counts


def load_cut_offs(run_dir, generations):
    """A run's cut-offs per generation (an array of `generations` counts): from its
    evaluations.csv, else its cut_offs.csv; None when it has neither."""
    evaluations = os.path.join(run_dir, "evaluations.csv")
    if os.path.isfile(evaluations):
        return count_cut_offs(evaluations, generations)
    path = os.path.join(run_dir, CUT_OFFS_FILE)
    if not os.path.isfile(path):
        return None
    with open(path, newline="", encoding="utf-8") as f:
        reader = csv.reader(f)
        if tuple(next(reader, ())) != CUT_OFFS_COLUMNS:
            raise InputError(f"{path}: the header is not {','.join(CUT_OFFS_COLUMNS)}")
        counts = []
        for row in reader:
            if len(row) != 2 or row[0] != str(len(counts)) or not row[1].isdigit():
                raise InputError(f"{path}: line {reader.line_num}: '{','.join(row)}' is not "
                                 f"generation {len(counts)} and a count")
            counts.append(int(row[1]))
    if len(counts) != generations:
        raise InputError(f"{path}: {len(counts)} generations, its generations.csv {generations}")
    return np.array(counts)


def load_run(run_dir, run, path, where, scaffolds, learners, size):
    """One run of reproduction.json with its generations.csv."""
    entry = {"learner": one_of(run, "learner", path, where, [l["name"] for l in learners]),
             "case": one_of(run, "case", path, where, [s["name"] for s in scaffolds]),
             "replicate": count(run, "replicate", path, where, 1, 10 ** 9),
             "dir": field(run, "dir", path, where, str),
             "seed": count(run, "seed", path, where, 0, 2 ** 32 - 1)}
    for key in ("final_best", "best_biped", "best_tripod"):
        entry[key] = load_finalist(run, key, path, where, size, allow_null=key != "final_best")
    generations = os.path.join(run_dir, entry["dir"], "generations.csv")
    entry["data"] = load_generations(generations)
    # the last generation's best is the archive's: a run continued after
    # reproduction.json was written disagrees
    last = float(entry["data"]["best_fitness"][-1])
    if last != entry["final_best"]["fitness"]:
        raise InputError(f"{generations}: the last best fitness {last!r} is not "
                         f"{path}'s {where}final_best.fitness {entry['final_best']['fitness']!r}: "
                         "the run changed since; `walkers reproduce --resume` writes both again")
    return entry


def load_pick(manifest, key, path, runs):
    """The first learner's best biped or tripod as reproduction.json names it (run,
    id): that run's finalist, with the run's name; None when there is none."""
    pick = field(manifest, key, path, "")
    if pick is None:
        return None
    run, ident = (field(pick, k, path, f"{key}.", str) for k in ("run", "id"))
    gait = key.split("_")[1]
    for r in runs:
        finalist = r[key] if r["dir"] == run else None
        if finalist is not None and finalist["id"] == ident:
            return {**finalist, "run": run, "gait": gait}
    raise InputError(f"{path}: field '{key}' names {run} {ident}, which is not that run's {key}")


def load_reproduction(run_dir):
    """reproduction.json with every run's generations.csv: {preset, generations,
    replicates, seed, population, ensemble, scaffolds, learners, runs (every
    learner's), primary (the first learner's runs), best_biped, best_tripod}."""
    if not os.path.isdir(run_dir):
        raise InputError(f"{run_dir}: not a directory")
    path = os.path.join(run_dir, MANIFEST)
    manifest = read_json(path, required=True)
    if not isinstance(manifest, dict):
        raise InputError(f"{path}: expected a JSON object")
    rep = {"dir": run_dir, "preset": field(manifest, "preset", path, "", str)}
    for key, high in (("generations", 10 ** 7), ("replicates", 1000), ("population", 10 ** 5),
                      ("ensemble", 1000)):
        rep[key] = count(manifest, key, path, "", 1, high)
    rep["seed"] = count(manifest, "seed", path, "", 0, 2 ** 32 - 1)
    program = field(manifest, "program", path, "", dict)
    rep["program"] = {"commit": field(program, "commit", path, "program.", str),
                      "evaluation": field(program, "evaluation", path, "program.", dict)}
    evaluation = rep["program"]["evaluation"]
    rep["integrator"] = one_of(evaluation, "integrator", path, "program.evaluation.",
                               INTEGRATORS) if "integrator" in evaluation else "cvode"
    rep["cut_off_rhs"] = count(evaluation, "cut_off_rhs", path, "program.evaluation.", 0,
                               2 ** 62) if "cut_off_rhs" in evaluation else 0
    rep["scaffolds"] = named_list(manifest, "scaffolds", path, (("paper_tripod_finals", 0, 3),))
    rep["learners"] = named_list(manifest, "learners", path)
    rep["runs"] = [load_run(run_dir, run, path, f"runs[{i}].", rep["scaffolds"], rep["learners"],
                            rep["ensemble"])
                   for i, run in enumerate(field(manifest, "runs", path, "", list))]
    for r in rep["runs"]:
        r["cut_offs"] = load_cut_offs(os.path.join(run_dir, r["dir"]),
                                      len(r["data"]["generation"])) if rep["cut_off_rhs"] else None
    rep["primary"] = [r for r in rep["runs"] if r["learner"] == rep["learners"][0]["name"]]
    for key in ("best_biped", "best_tripod"):
        rep[key] = load_pick(manifest, key, path, rep["primary"])
    return rep


def check_walk(walk, path, name):
    """Validate one walks.json entry (frames of equal length, numeric body)."""
    where = f"{name}."
    for key in ("run", "gait"):
        field(walk, key, path, where, str)
    for key in ("fitness", "leg_length"):
        field(walk, key, path, where, (int, float))
    if walk["leg_length"] <= 0:
        raise InputError(f"{path}: field '{where}leg_length' must be positive")
    body = field(walk, "body", path, where, dict)
    for key in BODY_KEYS:
        field(body, key, path, where + "body.", (int, float))
    frames = field(walk, "frames", path, where, dict)
    n = len(field(frames, "t", path, where + "frames.", list))
    if n < 1:
        raise InputError(f"{path}: '{where}frames.t' is empty")
    for key in FRAME_KEYS:
        value = field(frames, key, path, where + "frames.", list)
        if len(value) != n:
            raise InputError(f"{path}: '{where}frames.{key}' has {len(value)} entries, "
                             f"'{where}frames.t' has {n}")
        try:
            np.asarray(value, dtype=float)
        except (TypeError, ValueError):
            raise InputError(f"{path}: '{where}frames.{key}' is not numeric") from None
    return walk


def load_walks(run_dir):
    """walks.json -> {'biped': walk or None, 'tripod': walk or None}, or None if absent."""
    path = os.path.join(run_dir, "walks.json")
    walks = read_json(path, required=False)
    if walks is None:
        return None
    if not isinstance(walks, dict):
        raise InputError(f"{path}: expected an object with 'biped' and 'tripod'")
    out = {}
    for gait in GAITS:
        walk = field(walks, gait, path, "")
        out[gait] = None if walk is None else check_walk(walk, path, gait)
    return out


def check_pose(pose, path, where):
    """Validate a gallery pose (points [x,y], trunk [x,y,pitch], foot angles)."""
    def vector(key, size):
        """Check pose[key] is a list of `size` numbers."""
        value = field(pose, key, path, where)
        try:
            ok = np.asarray(value, dtype=float).shape == (size,)
        except (TypeError, ValueError):
            ok = False
        if not ok:
            raise InputError(f"{path}: field '{where}{key}' must be {size} numbers")
    vector("trunk", 3)
    for key in POINT_KEYS:
        vector(key, 2)
    for key in ("foot_l", "foot_r"):
        field(pose, key, path, where, (int, float))


def load_gallery(run_dir):
    """gallery.json -> list of individuals, or None if absent."""
    path = os.path.join(run_dir, "gallery.json")
    gallery = read_json(path, required=False)
    if gallery is None:
        return None
    people = field(gallery, "individuals", path, "", list)
    for i, ind in enumerate(people):
        where = f"individuals[{i}]."
        field(ind, "label", path, where, str)
        one_of(ind, "gait", path, where, GAITS)
        field(ind, "fitness", path, where, (int, float))
        body = field(ind, "body", path, where, dict)
        for key in BODY_KEYS:
            field(body, key, path, where + "body.", (int, float))
        check_pose(field(ind, "pose", path, where, dict), path, where + "pose.")
    return people


def paper_cases(scaffolds):
    """The names of the paper's cases 1, 2 and 3 (the scaffolds' places in the list)."""
    by_number = {s["number"]: s["name"] for s in scaffolds}
    if any(n not in by_number for n in (1, 2, 3)):
        raise InputError(f"{MANIFEST}: the paper's three cases need three scaffolds, "
                         f"found {len(scaffolds)}")
    return by_number[1], by_number[2], by_number[3]


def of_case(runs, case):
    """The runs of one case, by replicate."""
    return sorted((r for r in runs if r["case"] == case), key=lambda r: r["replicate"])
