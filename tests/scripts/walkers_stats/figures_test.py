#!/usr/bin/env python3
"""Tests for walkers_stats/figures.py on a small synthetic reproduction (fixtures.py:
3 cases x 2 replicates x 60 generations, walks of 451 frames, a gallery of 6), run as
`walkers reproduce` runs it (`scripts/walkers_stats figures DIR`), and the figures
inspected as drawn.

Run:  /usr/bin/python3 tests/scripts/walkers_stats/figures_test.py   (needs numpy, matplotlib)
"""
import os
import subprocess
import sys
import tempfile
import unittest
import xml.etree.ElementTree as ET
from unittest import mock

import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
from matplotlib.collections import PathCollection  # noqa: E402

import fixtures  # noqa: E402
from fixtures import CASES, edit_json  # noqa: E402
from walkers_stats import figures, load, statistics  # noqa: E402

ALL = ("fig4a", "fig4b", "fig5", "fig6", "fig7", "fig8", "fig9", "tripods", "finals")
WALK_FIGS = ("fig4a", "fig4b", "fig6")
REPLICATES, GENERATIONS = 2, 60


def make_run_dir(root, learners=("ga",)):
    """A complete synthetic reproduction under root; returns its path."""
    runs = [r for learner in learners for r in fixtures.evolving_runs(REPLICATES, GENERATIONS, learner)]
    return fixtures.write_reproduction(
        root, runs, GENERATIONS, learners=learners,
        walks={"biped": fixtures.walk("biped", "performance-2", 1.0,
                                      fixtures.body(0.04, 0.45, 0.75, 0.08), 12.3),
               "tripod": fixtures.walk("tripod", "time-1", 0.7,
                                       fixtures.body(0.85, 0.5, 0.6, 0.25), 8.9)},
        gallery=fixtures.gallery())


def drawn_figures(inputs):
    """{name: figure} of every figure draw_all makes of `inputs`, not saved."""
    figs = {}
    with mock.patch.object(figures, "save", lambda fig, out_dir, name: figs.__setitem__(name, fig)), \
            figures.plt.rc_context(figures.STYLE):
        figures.draw_all(inputs, None)
    return figs


# ----------------------------------------------------------------------------- tests

class FiguresTest(unittest.TestCase):
    """Runs the figures command on synthetic inputs."""

    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.run_dir = make_run_dir(self.tmp.name)
        self.fig_dir = os.path.join(self.run_dir, "figures")

    def tearDown(self):
        self.tmp.cleanup()

    def run_script(self, expect_rc=0, *options):
        """Run the figures command; assert its exit status; return stderr."""
        status, out, err = fixtures.run_statistics("figures", self.run_dir, *options)
        self.assertEqual(status, expect_rc, f"stdout:\n{out}\nstderr:\n{err}")
        self.assertNotIn("Traceback", err)
        return err

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
        # no warning but that the authors' runs are missing, which fig9 and tripods say too
        self.assertEqual([l for l in stderr.splitlines() if "warning" in l],
                         [f"warning: fig9, tripods: {figures.AUTHORS_MISSING} (--authors PATH)"])
        self.assertIn("the authors", self.svg_text("fig9"))
        self.assertIn("the authors", self.svg_text("tripods"))
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
        edit_json(os.path.join(self.run_dir, "reproduction.json"),
                  lambda s: s.update(runs=[r for r in s["runs"] if r["case"] != "time"]))
        stderr = self.run_script()
        self.assertIn("no runs for case 'time'", stderr)
        for name in ALL:
            self.assert_figure(name)
        self.assertIn("no data", self.svg_text("fig8"))
        for name in ("fig9", "tripods"):
            self.assertIn("Case 2, time-constrained", self.svg_text(name))
            self.assertIn("<!-- no data -->", self.svg_text(name))

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

    def test_the_cases_are_the_reproductions_list_of_scaffolds(self):
        # a fourth scaffold, named only in reproduction.json, gets its row and its line
        def add_case(manifest):
            manifest["scaffolds"].append({"name": "steps", "label": "stepwise",
                                          "colour": "tab:cyan", "paper_tripod_finals": 0})
            manifest["runs"].append(dict(manifest["runs"][0], case="steps", replicate=1))
        edit_json(os.path.join(self.run_dir, "reproduction.json"), add_case)
        self.run_script()
        self.assertIn("Case 4 (steps), replicate 1", self.svg_text("fig8"))
        for name in ("fig9", "tripods"):
            self.assertIn("Case 4, stepwise", self.svg_text(name))
            self.assertIn("ours on CVODE (2/2/2/1 runs)", self.svg_text(name))

    def test_a_reproduction_without_its_scaffolds_is_an_error(self):
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
            edit_json(os.path.join(self.run_dir, "reproduction.json"), change)
            stderr = self.run_script(expect_rc=1)
            self.assertIn(message, stderr)

    def test_two_learners_give_the_learners_figure(self):
        self.run_script()
        self.assert_absent("learners")          # one learner: nothing to compare
        self.run_dir = make_run_dir(tempfile.mkdtemp(dir=self.tmp.name), learners=("ga", "cmaes"))
        self.fig_dir = os.path.join(self.run_dir, "figures")
        stderr = self.run_script()
        self.assertEqual(stderr.count("warning"), 1, stderr)    # the authors' runs only
        self.assert_figure("learners")
        self.assertIn("CMA-ES", self.svg_text("learners"))
        for name in ALL:
            self.assert_figure(name)

    def test_a_run_of_an_unknown_learner_is_an_error(self):
        self.run_dir = make_run_dir(tempfile.mkdtemp(dir=self.tmp.name), learners=("ga", "cmaes"))
        edit_json(os.path.join(self.run_dir, "reproduction.json"),
                  lambda m: m["runs"][7].update(learner="nsga2"))
        stderr = self.run_script(expect_rc=1)
        self.assertIn("field 'runs[7].learner' is 'nsga2', expected one of ga, cmaes", stderr)

    def test_missing_reproduction_json_is_an_error(self):
        os.remove(os.path.join(self.run_dir, "reproduction.json"))
        stderr = self.run_script(expect_rc=1)
        self.assertIn("reproduction.json: file not found", stderr)
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
                  f"sys.path.insert(0, {fixtures.SCRIPTS!r})\n"
                  "from walkers_stats import figures\n"
                  "def full(self, fname, **kwargs):\n"
                  "    with open(fname, 'wb') as f:\n"
                  "        f.write(b'half a figure')\n"
                  "    raise OSError(errno.ENOSPC, 'No space left on device')\n"
                  "matplotlib.figure.Figure.savefig = full\n"
                  f"sys.exit(figures.draw({self.run_dir!r}, {{'checkout': '.', 'runs': {{}}, "
                  "'gaits': {}, 'children': {}}))\n")
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
        sizes = {k: v for k, v in figures.STYLE.items() if k.endswith("size")}
        self.assertTrue(sizes)
        for key, size in sizes.items():
            self.assertGreaterEqual(size, 8, key)


class DrawnFiguresTest(unittest.TestCase):
    """Inspects the figures as drawn, before saving, of one synthetic reproduction."""

    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.run_dir = make_run_dir(cls.tmp.name)
        cls.figs = drawn_figures(figures.load_inputs(cls.run_dir))

    @classmethod
    def tearDownClass(cls):
        figures.plt.close("all")
        cls.tmp.cleanup()

    def test_generation_axes_end_at_the_reproductions_generations(self):
        figs = self.figs
        for name in ("fig8", "fig9", "tripods"):
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

    def test_fig9_has_a_panel_a_case_and_its_band_outlined_and_hatched(self):
        panels = self.figs["fig9"].axes[:len(CASES)]
        for number, (panel, scaffold) in enumerate(zip(panels, fixtures.SCAFFOLDS), 1):
            self.assertEqual(panel.get_title(), f"Case {number}, {scaffold['label']}")
            self.assertEqual(panel.get_xlim(), (0.0, GENERATIONS))
            bands = panel.collections
            self.assertEqual(len(bands), 1)              # one experiment of ours
            self.assertTrue(bands[0].get_hatch())
            self.assertGreater(bands[0].get_linewidths()[0], 0)
            self.assertGreaterEqual(bands[0].get_edgecolor()[0][3], 0.5)
        self.assertEqual(len(self.figs["fig9"].axes), len(CASES) + 1)    # and the legend's row

    def test_fig9_band_is_the_bootstrap_interval_of_the_mean(self):
        for case, panel in zip(CASES, self.figs["fig9"].axes):
            lines = [l for l in panel.get_lines() if len(l.get_xdata())]
            faint = [l for l in lines if l.get_alpha() is not None and l.get_alpha() < 0.5]
            means = [l for l in lines if l.get_alpha() is None]
            self.assertEqual(len(faint), REPLICATES, case)       # every replicate, faintly
            self.assertEqual(len(means), 1, case)
            curves = np.array([l.get_ydata() for l in faint])
            np.testing.assert_allclose(means[0].get_ydata(), curves.mean(axis=0))
            low, high = statistics.mean_band(curves)
            edge = panel.collections[0].get_paths()[0].vertices[:, 1]
            # the band's outline runs along both limits
            self.assertTrue(np.isin(np.round(low, 9), np.round(edge, 9)).all(), case)
            self.assertTrue(np.isin(np.round(high, 9), np.round(edge, 9)).all(), case)
            self.assertTrue(np.all(low <= curves.mean(axis=0) + 1e-12), case)
            self.assertTrue(np.any(high - low > 0), case)

    def test_tripods_draws_the_share_of_tripod_bests_per_generation(self):
        # fixtures.evolving_runs: replicate r of the case in place c is a tripod until
        # generation 15 (c + r): case 1's two runs until 15 and 30
        panels = self.figs["tripods"].axes[:len(CASES)]
        for c, panel in enumerate(panels):
            (line,) = panel.get_lines()
            share = line.get_ydata()
            self.assertEqual(len(share), GENERATIONS)
            until = [15 * (c + r) for r in range(1, REPLICATES + 1)]
            expected = [sum(g < u for u in until) / REPLICATES for g in range(GENERATIONS)]
            np.testing.assert_allclose(share, expected)

    def test_finals_shows_every_re_scored_final_best_and_the_tripod_shares(self):
        left, right = self.figs["finals"].axes
        points = np.concatenate([c.get_offsets()[:, 1] for c in left.collections
                                 if isinstance(c, PathCollection)])
        self.assertEqual(len(points), len(CASES) * REPLICATES)
        # the re-scored medians, each with its ensemble's range
        rep = load.load_reproduction(self.run_dir)
        medians = [r["final_best"]["rescore"]["median"] for r in rep["primary"]]
        self.assertEqual(sorted(points), sorted(medians))
        self.assertNotIn(rep["primary"][0]["final_best"]["fitness"], list(points))
        ranges = [c for c in left.collections if not isinstance(c, PathCollection)]
        self.assertEqual(sum(len(c.get_segments()) for c in ranges), len(CASES) * REPLICATES)
        # synthetic: only performance-2 is a tripod to the end (tripod_until = 60 > 59)
        heights = [bar.get_height() for bar in right.patches]
        self.assertEqual(heights, [0.0, 0.0, 0.5])
        texts = [t.get_text() for t in right.texts]
        self.assertEqual(texts, ["0 of 2", "0 of 2", "1 of 2"])
        bar_tops = [seg[:, 1].max() for seg in right.collections[-1].get_segments()]
        self.assertAlmostEqual(bar_tops[-1], statistics.wilson_interval(1, 2)[1], places=12)

    def test_fig8_with_ten_replicates_stays_legible(self):
        drawn = {}
        inputs = figures.load_inputs(self.run_dir)
        runs = [{**run, "replicate": k + 1} for k in range(10) for run in inputs["runs"]
                if run["replicate"] == 1]
        with mock.patch.object(figures, "save", lambda fig, out_dir, name: drawn.__setitem__(name, fig)), \
                figures.plt.rc_context(figures.STYLE):
            figures.fig8(runs, inputs["scaffolds"], 10, GENERATIONS, None)
        fig = drawn["fig8"]
        self.assertGreater(fig.get_size_inches()[0], figures.DOUBLE)
        titles = [ax.get_title() for ax in fig.axes]
        self.assertEqual(len(titles), 30)
        self.assertEqual(titles[:10], [f"rep. {k}" for k in range(1, 11)])
        self.assertEqual(fig.axes[10].get_ylabel(), "Case 2 (time)\nbest fitness")
        self.assertIn("red while it is a tripod", fig._suptitle.get_text())
        figures.plt.close(fig)


if __name__ == "__main__":
    unittest.main(verbosity=2)
