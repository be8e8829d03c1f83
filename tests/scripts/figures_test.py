#!/usr/bin/env python3
"""Tests for scripts/figures.py on a small synthetic reproduction directory.

Run:  /usr/bin/python3 tests/scripts/figures_test.py   (needs numpy and matplotlib)

Each test writes a RUN_DIR (3 cases x 2 replicates x 60 generations, walks of
451 frames, a gallery of 6 individuals) to a temporary directory, runs the script
as a subprocess with the same interpreter and checks its outputs and exit status.
"""
import csv
import importlib.util
import json
import math
import os
import subprocess
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
SCRIPT = os.path.join(ROOT, "scripts", "figures.py")
ALL = ("fig4a", "fig4b", "fig5", "fig6", "fig7", "fig8", "fig9", "finals")
WALK_FIGS = ("fig4a", "fig4b", "fig6")
# summary.json's list of scaffolds, as the program writes it (evolve/scaffold.cc)
SCAFFOLDS = [{"name": "free", "label": "free", "colour": "tab:green"},
             {"name": "time", "label": "time-constrained", "colour": "tab:orange"},
             {"name": "performance", "label": "performance-based", "colour": "tab:purple"}]
CASES = tuple(s["name"] for s in SCAFFOLDS)
REPLICATES, GENERATIONS, FRAMES = 2, 60, 451


# ----------------------------------------------------------------------------- data

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


def walk(gait, run, speed, b, fitness):
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
    return {"title": f"best {gait}", "run": run, "id": "50/3", "fitness": fitness,
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


def write_generations(path, seed, tripod_until):
    """60 generations of plausible evolution: fitness up, body shrinking."""
    rng = np.random.default_rng(seed)
    header = ["generation", "best_fitness", "ave_best3", "archive_mean",
              "ceiling_half_body_x", "best_half_body_x", "best_femur", "best_tibia",
              "best_gait", "falls", "evals_per_s"]
    fit = 4.0 + np.maximum.accumulate(np.cumsum(rng.uniform(0, 0.3, GENERATIONS)))
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        for g in range(GENERATIONS):
            hbx = 0.9 * math.exp(-g / 25) + 0.035
            w.writerow([g, fit[g], fit[g] - 0.5, fit[g] - 2, 0.9, hbx,
                        0.53 + 0.001 * g, 0.68 + 0.002 * g,
                        "tripod" if g < tripod_until else "biped", 3, 40.0])


def make_run_dir(root):
    """Write a complete synthetic RUN_DIR under root; returns its path."""
    run_dir = os.path.join(root, "repro")
    os.makedirs(run_dir)
    runs = []
    for c, case in enumerate(CASES):
        for rep in range(1, REPLICATES + 1):
            name = f"{case}-{rep}"
            os.makedirs(os.path.join(run_dir, name))
            write_generations(os.path.join(run_dir, name, "generations.csv"),
                              seed=10 * c + rep, tripod_until=15 * (c + rep))
            runs.append({"case": case, "replicate": rep, "dir": name})
    write_json(os.path.join(run_dir, "summary.json"),
               {"preset": "original", "generations": GENERATIONS,
                "replicates": REPLICATES, "scaffolds": SCAFFOLDS, "runs": runs})
    write_json(os.path.join(run_dir, "walks.json"), {
        "biped": walk("biped", "performance-2", 1.0, body(0.04, 0.45, 0.75, 0.08), 12.3),
        "tripod": walk("tripod", "time-1", 0.7, body(0.85, 0.5, 0.6, 0.25), 8.9)})
    write_json(os.path.join(run_dir, "gallery.json"), gallery())
    return run_dir


def load_script():
    """scripts/figures.py as a module."""
    spec = importlib.util.spec_from_file_location("figures", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def write_json(path, obj):
    """Dump obj as JSON to path."""
    with open(path, "w") as f:
        json.dump(obj, f)


def edit_json(path, change):
    """Load a JSON file, apply change(obj) in place and write it back."""
    with open(path) as f:
        obj = json.load(f)
    change(obj)
    write_json(path, obj)


# ----------------------------------------------------------------------------- tests

class FiguresTest(unittest.TestCase):
    """Runs scripts/figures.py on synthetic inputs."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.run_dir = make_run_dir(self.tmp.name)
        self.fig_dir = os.path.join(self.run_dir, "figures")

    def tearDown(self):
        self.tmp.cleanup()

    def run_script(self, expect_rc=0):
        """Run the script; assert its exit status; return stderr."""
        proc = subprocess.run([sys.executable, SCRIPT, self.run_dir], text=True,
                              capture_output=True, timeout=300)
        self.assertEqual(proc.returncode, expect_rc,
                         f"stdout:\n{proc.stdout}\nstderr:\n{proc.stderr}")
        self.assertNotIn("Traceback", proc.stderr)
        return proc.stderr

    def assert_figure(self, name):
        """NAME.png decodes, is a paper width at 200 dpi and not blank; NAME.svg parses."""
        png = os.path.join(self.fig_dir, name + ".png")
        svg = os.path.join(self.fig_dir, name + ".svg")
        for path in (png, svg):
            self.assertTrue(os.path.isfile(path), path)
            self.assertGreater(os.path.getsize(path), 0, path)
        img = mpimg.imread(png)
        self.assertIn(img.shape[1], (700, 1400), f"{png}: width {img.shape[1]} px")
        self.assertGreaterEqual(img.shape[0], 200, png)
        rgb = img[..., :3]
        ink = np.any(rgb < 0.9, axis=-1).mean()
        self.assertGreater(ink, 0.01, f"{png} looks blank")
        self.assertGreater(len(np.unique(rgb.reshape(-1, 3), axis=0)), 16, png)
        root = ET.parse(svg).getroot()
        self.assertTrue(root.tag.endswith("svg"), svg)

    def svg_text(self, name):
        """The SVG source (text is drawn as paths, each preceded by a comment)."""
        with open(os.path.join(self.fig_dir, name + ".svg")) as f:
            return f.read()

    def assert_absent(self, name):
        """Neither NAME.png nor NAME.svg was written."""
        for ext in ("png", "svg"):
            self.assertFalse(os.path.exists(os.path.join(self.fig_dir, f"{name}.{ext}")))

    def test_all_figures_written(self):
        stderr = self.run_script()
        self.assertNotIn("warning", stderr)
        for name in ALL:
            self.assert_figure(name)
        self.assertIn("performance-2", self.svg_text("fig7"))   # the best biped's run

    def test_missing_walks_skips_walk_figures(self):
        os.remove(os.path.join(self.run_dir, "walks.json"))
        stderr = self.run_script()
        self.assertIn("walks.json not found", stderr)
        for name in WALK_FIGS:
            self.assertIn(name, stderr)
            self.assert_absent(name)
        for name in ("fig5", "fig7", "fig8", "fig9"):
            self.assert_figure(name)
        self.assertIn("highest final fitness", self.svg_text("fig7"))

    def test_missing_gallery_skips_fig5(self):
        os.remove(os.path.join(self.run_dir, "gallery.json"))
        stderr = self.run_script()
        self.assertIn("gallery.json not found", stderr)
        self.assert_absent("fig5")
        for name in ALL:
            if name != "fig5":
                self.assert_figure(name)

    def test_case_without_runs_says_no_data(self):
        edit_json(os.path.join(self.run_dir, "summary.json"),
                  lambda s: s.update(runs=[r for r in s["runs"] if r["case"] != "time"]))
        stderr = self.run_script()
        self.assertIn("no runs for case 'time'", stderr)
        for name in ALL:
            self.assert_figure(name)
        self.assertIn("no data", self.svg_text("fig8"))
        self.assertIn("Case 2 time-constrained (no data)", self.svg_text("fig9"))

    def test_null_tripod_skips_only_tripod_parts(self):
        edit_json(os.path.join(self.run_dir, "walks.json"),
                  lambda w: w.update(tripod=None))
        stderr = self.run_script()
        self.assertIn("no tripod", stderr)
        for name in ALL:
            self.assert_figure(name)
        for name in WALK_FIGS:
            text = self.svg_text(name)
            self.assertIn("best biped", text, name)
            self.assertNotIn("best tripod", text, name)

    def test_both_walks_null_skip_walk_figures(self):
        edit_json(os.path.join(self.run_dir, "walks.json"),
                  lambda w: w.update(biped=None, tripod=None))
        stderr = self.run_script()
        self.assertIn("both walks are null", stderr)
        for name in WALK_FIGS:
            self.assert_absent(name)
        for name in ("fig5", "fig7", "fig8", "fig9"):
            self.assert_figure(name)

    def test_the_cases_are_the_summarys_list_of_scaffolds(self):
        # a fourth scaffold, named only in summary.json, gets its row and its line
        def add_case(summary):
            summary["scaffolds"].append({"name": "steps", "label": "stepwise",
                                         "colour": "tab:cyan"})
            summary["runs"].append({"case": "steps", "replicate": 1, "dir": "free-1"})
        edit_json(os.path.join(self.run_dir, "summary.json"), add_case)
        self.run_script()
        self.assertIn("Case 4 (steps), replicate 1", self.svg_text("fig8"))
        self.assertIn("Case 4 stepwise (n = 1)", self.svg_text("fig9"))

    def test_a_summary_without_its_scaffolds_is_an_error(self):
        for change, message in ((lambda s: s.pop("scaffolds"), "missing field 'scaffolds'"),
                                (lambda s: s["scaffolds"][1].update(colour="orangeish"),
                                 "'scaffolds[1].colour' is 'orangeish', not a colour"),
                                (lambda s: s["scaffolds"][2].update(name="free"),
                                 "'scaffolds[2].name' repeats 'free'"),
                                (lambda s: s["runs"][0].update(case="steps"),
                                 "'runs[0].case' is 'steps', expected one of free, time, "
                                 "performance")):
            make = os.path.join(self.tmp.name, "again")
            os.makedirs(make, exist_ok=True)
            self.run_dir = make_run_dir(tempfile.mkdtemp(dir=make))
            self.fig_dir = os.path.join(self.run_dir, "figures")
            edit_json(os.path.join(self.run_dir, "summary.json"), change)
            stderr = self.run_script(expect_rc=1)
            self.assertIn(message, stderr)

    def add_learners(self, summary):
        """A second learner beside the GA, whose runs reuse the GA's run folders."""
        summary["learners"] = [{"name": "ga", "label": "genetic algorithm", "colour": "tab:blue"},
                               {"name": "cmaes", "label": "CMA-ES", "colour": "tab:red"}]
        summary["learner_runs"] = [dict(r, learner=name) for name in ("ga", "cmaes")
                                   for r in summary["runs"]]

    def test_two_learners_give_the_learners_figure(self):
        self.assert_absent("learners")
        self.run_script()
        self.assert_absent("learners")          # one learner: nothing to compare
        edit_json(os.path.join(self.run_dir, "summary.json"), self.add_learners)
        stderr = self.run_script()
        self.assertNotIn("warning", stderr)
        self.assert_figure("learners")
        self.assertIn("CMA-ES", self.svg_text("learners"))
        for name in ALL:
            self.assert_figure(name)

    def test_a_learner_run_of_an_unknown_learner_is_an_error(self):
        def change(summary):
            self.add_learners(summary)
            summary["learner_runs"][3]["learner"] = "nsga2"
        edit_json(os.path.join(self.run_dir, "summary.json"), change)
        stderr = self.run_script(expect_rc=1)
        self.assertIn("'learner_runs[3].learner' is 'nsga2', expected one of ga, cmaes", stderr)

    def test_missing_summary_is_an_error(self):
        os.remove(os.path.join(self.run_dir, "summary.json"))
        stderr = self.run_script(expect_rc=1)
        self.assertIn("summary.json: file not found", stderr)
        self.assertFalse(os.path.exists(self.fig_dir))

    def test_missing_generations_is_an_error(self):
        path = os.path.join(self.run_dir, "free-2", "generations.csv")
        os.remove(path)
        stderr = self.run_script(expect_rc=1)
        self.assertIn(f"{path}: file not found", stderr)

    def test_bad_number_names_file_and_line(self):
        path = os.path.join(self.run_dir, "time-1", "generations.csv")
        with open(path) as f:
            lines = f.readlines()
        lines[3] = lines[3].replace(lines[3].split(",")[1], "oops", 1)
        with open(path, "w") as f:
            f.writelines(lines)
        stderr = self.run_script(expect_rc=1)
        self.assertIn(f"{path}: line 4, column best_fitness: 'oops'", stderr)

    def test_inconsistent_walk_frames_is_an_error(self):
        edit_json(os.path.join(self.run_dir, "walks.json"),
                  lambda w: w["biped"]["frames"]["com"].pop())
        stderr = self.run_script(expect_rc=1)
        self.assertIn("walks.json: 'biped.frames.com' has 450 entries", stderr)

    def test_a_full_disk_is_one_line_and_the_traceback_is_logged(self):
        self.run_script()                       # earlier figures, which must survive
        with open(os.path.join(self.fig_dir, "fig4a.png"), "rb") as f:
            earlier = f.read()
        driver = ("import errno, sys, matplotlib.figure\n"
                  f"sys.path.insert(0, {os.path.dirname(SCRIPT)!r})\n"
                  "import figures\n"
                  "def full(self, fname, **kwargs):\n"
                  "    with open(fname, 'wb') as f:\n"
                  "        f.write(b'half a figure')\n"
                  "    raise OSError(errno.ENOSPC, 'No space left on device')\n"
                  "matplotlib.figure.Figure.savefig = full\n"
                  f"sys.exit(figures.main([{self.run_dir!r}]))\n")
        proc = subprocess.run([sys.executable, "-c", driver], text=True, capture_output=True,
                              timeout=300)
        self.assertEqual(proc.returncode, 1, proc.stderr)
        lines = proc.stderr.strip().splitlines()
        self.assertEqual(len(lines), 1, proc.stderr)
        self.assertIn("fig4a", lines[0])
        self.assertIn("No space left on device", lines[0])
        log = os.path.join(self.fig_dir, "figures.log")
        self.assertIn(log, lines[0])
        with open(log) as f:
            self.assertIn("Traceback", f.read())
        with open(os.path.join(self.fig_dir, "fig4a.png"), "rb") as f:
            self.assertEqual(f.read(), earlier, "a failed write replaced an earlier figure")
        self.assertEqual([n for n in os.listdir(self.fig_dir) if ".tmp." in n], [])
        self.run_script()                       # the next success removes the log
        self.assertFalse(os.path.exists(log))

    def test_font_sizes_are_at_least_8_pt(self):
        module = load_script()
        sizes = {k: v for k, v in module.STYLE.items() if k.endswith("size")}
        self.assertTrue(sizes)
        for key, size in sizes.items():
            self.assertGreaterEqual(size, 8, key)


class DrawnFiguresTest(unittest.TestCase):
    """Inspects the figures as drawn, before saving, of one synthetic reproduction."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        run_dir = make_run_dir(cls.tmp.name)
        module = load_script()
        cls.figs = {}
        module.save = lambda fig, out_dir, name: cls.figs.__setitem__(name, fig)
        fig_dir = os.path.join(run_dir, "figures")
        os.makedirs(fig_dir)
        with module.plt.rc_context(module.STYLE):
            module.draw_all(module.load_run_dir(run_dir), fig_dir)
        cls.plt = module.plt

    @classmethod
    def tearDownClass(cls):
        cls.plt.close("all")
        cls.tmp.cleanup()

    def test_generation_axes_end_at_the_summarys_last_generation(self):
        figs = self.figs
        for name in ("fig8", "fig9"):
            ax = figs[name].axes[0]
            self.assertEqual(ax.get_xlim(), (0.0, GENERATIONS), name)
            self.assertIn(GENERATIONS, list(ax.get_xticks()), name)   # a tick at the end

    def test_fig7_legend_swatch_is_visible(self):
        legend = self.figs["fig7"].axes[0].get_legend()
        labels = [t.get_text() for t in legend.get_texts()]
        self.assertIn("tripod gait", labels)
        handles = getattr(legend, "legend_handles", None) or legend.legendHandles
        swatch = handles[labels.index("tripod gait")]
        face = matplotlib.colors.to_rgba(swatch.get_facecolor(), swatch.get_alpha())
        edge = matplotlib.colors.to_rgba(swatch.get_edgecolor(), swatch.get_alpha())
        self.assertGreaterEqual(max(face[3], edge[3] if swatch.get_linewidth() > 0 else 0), 0.5,
                                f"face {face}, edge {edge}")

    def test_fig9_bands_are_outlined_and_hatched_apart(self):
        bands = self.figs["fig9"].axes[0].collections
        self.assertEqual(len(bands), len(CASES))
        hatches = [b.get_hatch() for b in bands]
        self.assertTrue(all(hatches), hatches)
        self.assertEqual(len(set(hatches)), len(CASES), hatches)
        for band in bands:
            self.assertGreater(band.get_linewidths()[0], 0)
            self.assertGreaterEqual(band.get_edgecolor()[0][3], 0.5)

    def test_fig9_band_is_the_bootstrap_interval_of_the_mean(self):
        ax = self.figs["fig9"].axes[0]
        claims = load_claims()
        lines = [l for l in ax.get_lines() if len(l.get_xdata())]
        faint = [l for l in lines if l.get_alpha() is not None and l.get_alpha() < 0.5]
        means = [l for l in lines if l.get_alpha() is None]
        self.assertEqual(len(faint), len(CASES) * REPLICATES)     # every replicate, faintly
        self.assertEqual(len(means), len(CASES))
        for case, band, mean in zip(CASES, ax.collections, means):
            curves = np.array([l.get_ydata() for l in faint
                               if l.get_color() == mean.get_color()])
            np.testing.assert_allclose(mean.get_ydata(), curves.mean(axis=0))
            low, high = claims.mean_band(curves)
            edge = band.get_paths()[0].vertices[:, 1]
            # the band's outline runs along both limits
            self.assertTrue(np.isin(np.round(low, 9), np.round(edge, 9)).all(), case)
            self.assertTrue(np.isin(np.round(high, 9), np.round(edge, 9)).all(), case)
            self.assertTrue(np.all(low <= curves.mean(axis=0) + 1e-12), case)
            self.assertTrue(np.any(high - low > 0), case)

    def test_finals_shows_every_final_best_and_the_tripod_shares(self):
        left, right = self.figs["finals"].axes
        points = np.concatenate([c.get_offsets()[:, 1] for c in left.collections])
        self.assertEqual(len(points), len(CASES) * REPLICATES)
        # synthetic: only performance-2 is a tripod to the end (tripod_until = 60 > 59)
        heights = [bar.get_height() for bar in right.patches]
        self.assertEqual(heights, [0.0, 0.0, 0.5])
        claims = load_claims()
        texts = [t.get_text() for t in right.texts]
        self.assertEqual(texts, ["0 of 2", "0 of 2", "1 of 2"])
        bar_tops = [seg[:, 1].max() for seg in right.collections[-1].get_segments()]
        self.assertAlmostEqual(bar_tops[-1], claims.wilson_interval(1, 2)[1], places=12)

    def test_fig8_with_ten_replicates_stays_legible(self):
        module = load_script()
        drawn = {}
        module.save = lambda fig, out_dir, name: drawn.__setitem__(name, fig)
        with tempfile.TemporaryDirectory() as tmp:
            inputs = module.load_run_dir(make_run_dir(tmp))
        runs = [{**run, "replicate": k + 1} for k in range(10) for run in inputs["runs"]
                if run["replicate"] == 1]
        with module.plt.rc_context(module.STYLE):
            module.fig8(runs, inputs["scaffolds"], 10, GENERATIONS, None)
        fig = drawn["fig8"]
        self.assertGreater(fig.get_size_inches()[0], module.DOUBLE)
        titles = [ax.get_title() for ax in fig.axes]
        self.assertEqual(len(titles), 30)
        self.assertEqual(titles[:10], [f"rep. {k}" for k in range(1, 11)])
        self.assertEqual(fig.axes[10].get_ylabel(), "Case 2 (time)\nbest fitness")
        self.assertIn("red while it is a tripod", fig._suptitle.get_text())
        self.plt.close(fig)


def load_claims():
    """scripts/claims.py as a module."""
    spec = importlib.util.spec_from_file_location("claims", os.path.join(ROOT, "scripts", "claims.py"))
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


if __name__ == "__main__":
    unittest.main(verbosity=2)
