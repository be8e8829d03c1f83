"""The paper's figures 4-9 of a reproduction, and two of our own.

Writes RUN_DIR/figures/<name>.png (200 dpi) and <name>.svg for

  fig4a  distance walked (leg lengths) over 15 s, best biped vs best tripod
  fig4b  filmstrip of both walkers over the first 5 s (a snapshot every 0.5 s)
  fig5   gallery of evolved individuals, bipeds on the top row, tripods below
  fig6   relative CoG height and CoG velocities (leg lengths, leg lengths/s)
  fig7   body, femur and tibia length per generation of the best biped's run
  fig8   best fitness per generation of every run, coloured by gait class
  fig9   one panel per case: our mean best fitness per generation with its bootstrap
         95 % band, each replicate faintly, and, given a checkout of the authors'
         repository, each of their runs as a thin dashed line (without one, a note says
         why theirs are missing)
  tripods  one panel per case: the share of runs whose best is a tripod, per generation,
         ours and (given their checkout) the authors' (tripods.py's table)
  finals each run's final best fitness per case, re-scored: the ensemble's median (points
         over a box) and its range (a line); and the share of runs whose final best is a
         tripod, with Wilson 95 % intervals (not in the paper)
  learners  (a reproduction of two learners or more) final best fitness (re-scored) per
         learner and case with the runs ending as tripods, and each learner's mean best
         fitness per generation and case

from the files load.py reads: reproduction.json and every run's generations.csv
(required), walks.json and gallery.json (optional). Figures 4-9 and finals show the
first learner's runs.

Absent data (documented choice):
  * A required file that is missing, or ANY input file that is present but malformed,
    is an error (load.InputError): nothing is drawn.
  * An optional file that is absent makes the figures that need it be skipped with a
    "warning:" line on stderr; the other figures are still written. fig7 then uses the
    run with the highest final best_fitness.
  * A null walk in walks.json (no biped or no tripod found) drops only that walker's
    line (fig4a, fig6) and filmstrip row (fig4b), with a warning; if both are null the
    three figures are skipped.
  * A case with no runs is still drawn: its fig8 panels say "no data" and its fig9
    legend entry reads "... (no data)"; a warning is printed.
  * An empty gallery row (no bipeds or no tripods) says "no data" in fig5.

A figure that cannot be drawn or written (a full disk, say) is reported in one line
on stderr naming the figure and the cause; the traceback goes to
RUN_DIR/figures/figures.log (removed again by the next run that succeeds), and the
exit status is 1.

fig9's band is the percentile bootstrap 95 % interval of the mean over the replicates
(statistics.mean_band, seeded), drawn at up to BAND_POINTS generations; with one
replicate no band is drawn. Replicates of unequal length are averaged over the
generations they all have (warning printed). The generation axes of fig8, fig9 and
tripods end at the generations reproduction.json names. fig9 and tripods take the
experiments they show as experiments.series makes them, so that the experiments' page
(side_by_side.py) draws them with more than one of ours.
"""
import math
import os
import sys
import traceback

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Circle, Patch, Polygon  # noqa: E402

from . import experiments, load  # noqa: E402
from .load import POINT_KEYS, InputError  # noqa: E402
from .statistics import SEED, mean_band, wilson_interval  # noqa: E402

# fig9's bands, told apart where they overlap (by the experiment's place in the list)
HATCHES = ("////", "\\\\\\\\", "....", "xxxx", "++++", "oooo")
GAIT_COLOURS = {"biped": "tab:blue", "tripod": "tab:red"}
# a generation whose best fell has no gait class (every child fell)
BEST_GAIT_COLOURS = {**GAIT_COLOURS, "none": "tab:gray"}
GAIT_CMAPS = {"biped": "Blues", "tripod": "Reds"}
SINGLE, DOUBLE = 3.5, 7.0          # column widths, inches
DPI = 200
FILM_END_S, FILM_STEP_S = 5.0, 0.5
STYLE = {"font.size": 8, "axes.titlesize": 8, "axes.labelsize": 8,
         "xtick.labelsize": 8, "ytick.labelsize": 8, "legend.fontsize": 8,
         "figure.titlesize": 9, "axes.linewidth": 0.6, "lines.linewidth": 1.0,
         "legend.frameon": False, "svg.hashsalt": "figures", "figure.dpi": DPI,
         "hatch.linewidth": 0.4}
LOG_NAME = "figures.log"
BAND_POINTS = 400                  # fig9's band: bootstrapped at this many generations at most


class FigureError(Exception):
    """A figure that could not be drawn or written; the message names it."""


def warn(message):
    """Print a warning line to stderr."""
    print(f"warning: {message}", file=sys.stderr)


def load_inputs(run_dir, authors=None):
    """Every input, read and checked (load.py), with the authors' runs (authors.py's
    load_authors, or None) by our case names; raises InputError naming the bad file."""
    rep = load.load_reproduction(run_dir)
    return {"scaffolds": rep["scaffolds"], "runs": rep["primary"],
            "replicates": max([rep["replicates"]] + [r["replicate"] for r in rep["primary"]]),
            "learners": rep["learners"], "learner_runs": rep["runs"],
            "series": experiments.series(rep, authors),
            "walks": load.load_walks(run_dir), "gallery": load.load_gallery(run_dir),
            "generations": rep["generations"]}


# ----------------------------------------------------------------------------- drawing

def save(fig, out_dir, name):
    """Write NAME.png (200 dpi) and NAME.svg, then close the figure. Each is written
    to a temporary file first and renamed into place: a failed write leaves an
    earlier figure as it was."""
    for ext in ("png", "svg"):
        path = os.path.join(out_dir, f"{name}.{ext}")
        temporary = f"{path}.tmp.{os.getpid()}"
        try:
            fig.savefig(temporary, format=ext, dpi=DPI,
                        metadata={"Date": None} if ext == "svg" else None)
            os.replace(temporary, path)
        finally:
            if os.path.exists(temporary):
                os.remove(temporary)
    plt.close(fig)
    print(f"wrote {os.path.join(out_dir, name)}.png/.svg")


def no_data(ax, text="no data", left=False):
    """Blank an axes with a 'no data' note, centred or from the left edge."""
    ax.text(0.05 if left else 0.5, 0.5, text, ha="left" if left else "center",
            va="center", transform=ax.transAxes, color="0.4")
    ax.set_xticks([])
    ax.set_yticks([])


def box(centre, half_x, half_y, angle):
    """Corners (4x2) of a box with the given half sizes, centre and CCW angle."""
    c, s = math.cos(angle), math.sin(angle)
    local = np.array([[-half_x, -half_y], [half_x, -half_y],
                      [half_x, half_y], [-half_x, half_y]])
    return local @ np.array([[c, s], [-s, c]]) + np.asarray(centre[:2], dtype=float)


def walker_shapes(body, pose):
    """Trunk and feet corners plus the leg polylines (far/right leg first)."""
    trunk = box(pose["trunk"][:2], body["half_body_x"], body["half_body_y"],
                pose["trunk"][2])
    legs, feet = [], []
    for side in ("r", "l"):
        legs.append(np.array([pose["hip"], pose[f"knee_{side}"], pose[f"ankle_{side}"]],
                             dtype=float))
        feet.append(box(pose[f"ankle_{side}"], body["half_foot_x"], body["half_foot_y"],
                        pose[f"foot_{side}"]))
    return trunk, legs, feet


def walker_extent(body, pose):
    """(xmin, xmax, ymin, ymax) of a drawn walker, knees included."""
    trunk, legs, feet = walker_shapes(body, pose)
    pts = np.vstack([trunk] + legs + feet)
    r = body["knee_radius"]
    return pts[:, 0].min() - r, pts[:, 0].max() + r, pts[:, 1].min() - r, \
        pts[:, 1].max() + r


def draw_walker(ax, body, pose, colour, dx=0.0, knees=True, lw=1.0, zorder=2):
    """Draw trunk box, legs, feet (and knees to scale) of one pose, shifted by dx."""
    trunk, legs, feet = walker_shapes(body, pose)
    shift = np.array([dx, 0.0])
    far = matplotlib.colors.to_rgb(colour)
    far = tuple(0.55 * c + 0.45 for c in far)        # far (right) leg paler
    ax.add_patch(Polygon(trunk + shift, closed=True, facecolor=colour, alpha=0.25,
                         edgecolor="none", zorder=zorder))
    ax.add_patch(Polygon(trunk + shift, closed=True, fill=False, edgecolor=colour,
                         lw=lw, zorder=zorder))
    for leg, foot, c in zip(legs, feet, (far, colour)):
        ax.plot(leg[:, 0] + dx, leg[:, 1], color=c, lw=lw * 1.3,
                solid_capstyle="round", zorder=zorder)
        ax.add_patch(Polygon(foot + shift, closed=True, facecolor=c, edgecolor=c,
                             lw=lw * 0.5, zorder=zorder))
        if knees:
            ax.add_patch(Circle(leg[1] + shift, body["knee_radius"], fill=False,
                                edgecolor=c, lw=lw * 0.6, zorder=zorder))


def ground(ax):
    """Ground line at y = 0 with a light band below it."""
    ax.axhline(0.0, color="0.3", lw=0.8, zorder=1)
    ax.axhspan(-10.0, 0.0, color="0.92", zorder=0)


def scale_bar(ax, x, y, length=1.0):
    """A horizontal scale bar of `length` metres starting at (x, y), data units."""
    ax.plot([x, x + length], [y, y], color="k", lw=1.5, solid_capstyle="butt",
            zorder=5)
    ax.text(x + length * 1.05, y, f"{length:g} m", ha="left", va="center", zorder=5)


def frame_pose(frames, i):
    """The pose dict of frame i of a walk."""
    pose = {k: frames[k][i] for k in ("trunk",) + POINT_KEYS}
    pose["foot_l"], pose["foot_r"] = frames["foot_l"][i], frames["foot_r"][i]
    return pose


def walk_label(walk):
    """Legend text for a walk: gait, run and fitness."""
    return f"best {walk['gait']} ({walk['run']}), fitness {walk['fitness']:.1f}"


def legend_above(ax, ncol=1, title=None, handles=None):
    """A legend above the axes, left-aligned, so it never hides data."""
    if handles is None:
        handles = ax.get_legend_handles_labels()[0]
    ax.legend(handles=handles, loc="lower left", bbox_to_anchor=(0.0, 1.01), ncol=ncol,
              title=title,
              title_fontsize=8, alignment="left", borderaxespad=0.0,
              handlelength=1.5, columnspacing=1.0)


def present_walks(walks):
    """[(gait, walk)] for the non-null walks, biped first."""
    return [(g, walks[g]) for g in GAIT_COLOURS if walks[g] is not None]


def fig4a(walks, out_dir):
    """Distance walked (leg lengths) over time for the best biped and tripod."""
    fig, ax = plt.subplots(figsize=(SINGLE, 2.5), layout="constrained")
    for gait, walk in present_walks(walks):
        f = walk["frames"]
        ax.plot(f["t"], np.asarray(f["distance"], float) / walk["leg_length"],
                color=GAIT_COLOURS[gait], label=walk_label(walk))
    ax.set_xlabel("time (s)")
    ax.set_ylabel("distance (leg lengths)")
    ax.set_xlim(left=0)
    ax.grid(alpha=0.3, lw=0.5)
    legend_above(ax)
    save(fig, out_dir, "fig4a")


def film_layout(walk, indices):
    """Per-snapshot x shifts: 0 (true positions) unless the walker hardly moves,
    then snapshots are spread evenly; returns (shifts, spread?)."""
    body, frames = walk["body"], walk["frames"]
    ext = [walker_extent(body, frame_pose(frames, i)) for i in indices]
    width = max(e[1] - e[0] for e in ext)
    moved = ext[-1][0] - ext[0][0]
    if moved >= 0.5 * width or len(indices) < 2:
        return np.zeros(len(indices)), False
    step = 1.1 * width
    return np.array([k * step - (e[0] - ext[0][0]) for k, e in enumerate(ext)]), True


def fig4b(walks, out_dir):
    """Filmstrip: a snapshot every 0.5 s over the first 5 s, biped above tripod."""
    rows = present_walks(walks)
    plans = []
    for gait, walk in rows:
        t = np.asarray(walk["frames"]["t"], float)
        times = np.arange(0.0, min(FILM_END_S, t[-1]) + 1e-9, FILM_STEP_S)
        idx = [int(np.argmin(np.abs(t - s))) for s in times]
        shifts, spread = film_layout(walk, idx)
        ext = np.array([walker_extent(walk["body"], frame_pose(walk["frames"], i))
                        for i in idx])
        box_ = (ext[:, 0] + shifts).min(), (ext[:, 1] + shifts).max(), \
            min(ext[:, 2].min(), 0.0), ext[:, 3].max()
        plans.append((gait, walk, times, idx, shifts, spread, box_))
    span_x = max(p[6][1] - p[6][0] for p in plans) + 0.3
    span_y = max(p[6][3] - p[6][2] for p in plans) + 0.3
    fig, axes = plt.subplots(len(plans), 1, squeeze=False, layout="constrained",
                             figsize=(DOUBLE, len(plans) * (0.62 + max(
                                 0.5, min(2.6, 6.2 * span_y / span_x)))))
    for ax, (gait, walk, times, idx, shifts, spread, bx) in zip(axes[:, 0], plans):
        cmap = plt.get_cmap(GAIT_CMAPS[gait])
        for k, (i, dx) in enumerate(zip(idx, shifts)):
            colour = cmap(0.3 + 0.7 * k / max(1, len(idx) - 1))
            draw_walker(ax, walk["body"], frame_pose(walk["frames"], i), colour, dx=dx,
                        knees=False, lw=0.8, zorder=2 + k)
        ground(ax)
        x0, y0 = bx[0] - 0.15, bx[2] - 0.15
        ax.set_xlim(x0, x0 + span_x)
        ax.set_ylim(y0, y0 + span_y)
        ax.set_aspect("equal")
        ax.set_xlabel("x (m)" + (", snapshots spread evenly for clarity" if spread
                                 else ""))
        ax.set_ylabel("y (m)")
        ax.set_title(f"{walk_label(walk)}: snapshots every {FILM_STEP_S:g} s, "
                     f"0-{times[-1]:g} s (light = early)", loc="left")
        sm = matplotlib.cm.ScalarMappable(
            cmap=matplotlib.colors.LinearSegmentedColormap.from_list(
                gait, [cmap(0.3), cmap(1.0)]),
            norm=matplotlib.colors.Normalize(0, times[-1]))
        fig.colorbar(sm, ax=ax, label="time (s)", aspect=12, pad=0.01)
    save(fig, out_dir, "fig4b")


def fig5(gallery, out_dir):
    """Gallery of individuals: bipeds on the top row, tripods below, same scale."""
    rows = [[p for p in gallery if p["gait"] == g] for g in GAIT_COLOURS]
    ncols = max(1, *(len(r) for r in rows))
    ext = [walker_extent(p["body"], p["pose"]) for p in gallery]
    span_x = max(e[1] - e[0] for e in ext) + 0.2
    span_y = max(max(e[3] for e in ext) - min(0.0, *(e[2] for e in ext)), 0.5) + 0.4
    panel_w = (DOUBLE - 0.3) / ncols
    fig, axes = plt.subplots(2, ncols, squeeze=False, layout="constrained",
                             figsize=(DOUBLE, 2 * (panel_w * span_y / span_x + 0.4)))
    for r, (gait, people) in enumerate(zip(GAIT_COLOURS, rows)):
        for c in range(ncols):
            ax = axes[r, c]
            ax.set_xticks([])
            ax.set_yticks([])
            for side in ax.spines.values():
                side.set_visible(False)
            if c >= len(people):
                if c == 0:
                    # a narrow first panel of a wide row: start at its left edge
                    no_data(ax, f"no {gait}s: no data", left=True)
                else:
                    ax.set_visible(False)
                continue
            p = people[c]
            e = walker_extent(p["body"], p["pose"])
            draw_walker(ax, p["body"], p["pose"], GAIT_COLOURS[gait], lw=0.9)
            ground(ax)
            mid = 0.5 * (e[0] + e[1])
            ax.set_xlim(mid - span_x / 2, mid + span_x / 2)
            y0 = min(0.0, e[2]) - 0.3                     # ground band holds the bar
            ax.set_ylim(y0, y0 + span_y)
            ax.set_aspect("equal")
            crowded = ncols > 6                          # long labels on two lines
            label = p["label"].replace(" ", "\n", 1) if crowded else p["label"]
            ax.set_title(f"{label}\nfitness {p['fitness']:.1f}", fontsize=6 if crowded else 8)
            if r == len(rows) - 1 - (not rows[1]) and c == 0:
                scale_bar(ax, mid - span_x / 2 + 0.1, y0 + 0.13)
        axes[r, 0].set_ylabel(f"{gait}s", color=GAIT_COLOURS[gait], fontsize=9)
        axes[r, 0].yaxis.label.set_visible(True)
    save(fig, out_dir, "fig5")


def fig6(walks, out_dir):
    """Relative CoG height and CoG velocities in leg lengths (per second)."""
    fig, axes = plt.subplots(3, 1, sharex=True, figsize=(SINGLE, 4.6),
                             layout="constrained")
    for gait, walk in present_walks(walks):
        f, leg = walk["frames"], walk["leg_length"]
        com, vel = np.asarray(f["com"], float), np.asarray(f["com_velocity"], float)
        series = ((com[:, 1] - com[0, 1]) / leg, vel[:, 0] / leg, vel[:, 1] / leg)
        for ax, y in zip(axes, series):
            ax.plot(f["t"], y, color=GAIT_COLOURS[gait], lw=0.8, label=walk_label(walk))
    labels = ("rel. CoG height\n(leg lengths)", "horizontal velocity\n(leg lengths/s)",
              "vertical velocity\n(leg lengths/s)")
    for ax, label in zip(axes, labels):
        ax.set_ylabel(label)
        ax.axhline(0.0, color="0.5", lw=0.5)
        ax.grid(alpha=0.3, lw=0.5)
    legend_above(axes[0])
    axes[-1].set_xlabel("time (s)")
    axes[-1].set_xlim(left=0)
    save(fig, out_dir, "fig6")


def pick_fig7_run(runs, walks):
    """The run of the best biped, else the run with the highest final best_fitness."""
    if walks is not None and walks["biped"] is not None:
        for run in runs:
            if run["dir"] == walks["biped"]["run"] or \
                    f"{run['case']}-{run['replicate']}" == walks["biped"]["run"]:
                return run, "run of the best biped"
        warn(f"walks.json: best biped's run '{walks['biped']['run']}' is not in "
             "reproduction.json; fig7 uses the run with the highest final fitness")
    best = max(runs, key=lambda r: r["data"]["best_fitness"][-1])
    return best, "run with the highest final fitness"


def fig7(runs, walks, out_dir):
    """Body, femur and tibia length of the best individual per generation."""
    run, why = pick_fig7_run(runs, walks)
    d = run["data"]
    g = d["generation"]
    fig, ax = plt.subplots(figsize=(SINGLE, 2.6), layout="constrained")
    tripod = np.array([x == "tripod" for x in d["best_gait"]])
    band = Patch(facecolor=matplotlib.colors.to_rgba("tab:red", 0.3), edgecolor="tab:red",
                 lw=0.6, label="tripod gait")      # the band's swatch, visible in the legend
    if tripod.any():
        ax.fill_between(g, 0, 1, where=tripod, step="mid", color="tab:red", alpha=0.15,
                        lw=0, transform=ax.get_xaxis_transform())
    ax.plot(g, 2 * d["best_half_body_x"], color="k", label="body")
    ax.plot(g, d["best_femur"], color="tab:cyan", label="femur")
    ax.plot(g, d["best_tibia"], color="tab:brown", label="tibia")
    ax.set_xlabel("generation")
    ax.set_ylabel("length (m)")
    ax.set_xlim(g[0], g[-1])
    ax.set_ylim(bottom=0)
    ax.grid(alpha=0.3, lw=0.5)
    handles = ax.get_legend_handles_labels()[0] + ([band] if tripod.any() else [])
    legend_above(ax, ncol=4 if tripod.any() else 3, title=f"{run['dir']} ({why})",
                 handles=handles)
    save(fig, out_dir, "fig7")


def runs_by_case(runs, scaffolds):
    """[(scaffold, [its runs sorted by replicate])] for every case, possibly empty."""
    return [(s, sorted((r for r in runs if r["case"] == s["name"]),
                       key=lambda r: r["replicate"])) for s in scaffolds]


def fig8(runs, scaffolds, replicates, generations, out_dir):
    """Grid (rows = cases, columns = replicates) of best fitness coloured by gait."""
    grouped = runs_by_case(runs, scaffolds)
    ncols = max(1, replicates)
    # beyond three replicates: narrow panels, so short titles, the case on each row's
    # label, the figure wider and the gait colours said in words above
    compact = ncols > 3
    fig, axes = plt.subplots(len(grouped), ncols, sharex=True, sharey=True, squeeze=False,
                             figsize=(max(DOUBLE, 0.8 + 0.75 * ncols) if compact else DOUBLE,
                                      1.15 + 1.45 * len(grouped)),
                             layout="constrained")
    for row, (scaffold, group) in enumerate(grouped):
        by_rep = {r["replicate"]: r for r in group}
        for col in range(ncols):
            ax = axes[row, col]
            ax.set_title(f"rep. {col + 1}" if compact else
                         f"Case {scaffold['number']} ({scaffold['name']}), replicate {col + 1}")
            run = by_rep.get(col + 1)
            if run is None:
                ax.text(0.5, 0.5, "no data", ha="center", va="center",
                        transform=ax.transAxes, color="0.4")
                continue
            d = run["data"]
            x, y = d["generation"], d["best_fitness"]
            colours = [BEST_GAIT_COLOURS[gait] for gait in d["best_gait"]]
            if len(x) > 1:
                seg = np.stack([np.column_stack([x[:-1], y[:-1]]),
                                np.column_stack([x[1:], y[1:]])], axis=1)
                ax.add_collection(LineCollection(seg, colors=colours[1:], lw=1.2))
            else:
                ax.scatter(x, y, c=colours, s=6)
            ax.grid(alpha=0.3, lw=0.5)
        axes[row, 0].set_ylabel(f"Case {scaffold['number']} ({scaffold['name']})\nbest fitness" if compact
                                else "best fitness\n(leg lengths)")
    for ax in axes[-1]:
        ax.set_xlabel("generation")
        if compact:
            ax.set_xticks([0, generations], ["0", f"{generations:g}"])
    axes[0, 0].set_xlim(0, generations)
    ymax = max([float(np.nanmax(r["data"]["best_fitness"])) for r in runs] + [1.0])
    axes[0, 0].set_ylim(0, 1.05 * ymax)
    if compact:
        fig.suptitle("best fitness (leg lengths) of every run: blue while the best is a "
                     "biped, red while it is a tripod")
    else:
        handles = [Line2D([], [], color=c, lw=1.5, label=f"best is a {g}")
                   for g, c in GAIT_COLOURS.items()]
        axes[0, 0].legend(handles=handles, loc="upper left", frameon=True,
                          framealpha=0.85, edgecolor="none")
    save(fig, out_dir, "fig8")


def case_curves(case, curves):
    """(generations, replicates x generations best fitness) of a case's curves of best
    fitness, cut to the generations all its replicates have."""
    n = min(len(c) for c in curves)
    if any(len(c) != n for c in curves):
        warn(f"fig9: {case} runs have different lengths; using their first {n} "
             "generations")
    return np.arange(n), np.stack([np.asarray(c[:n], float) for c in curves])


def case_label(scaffold):
    """'Case 2 time-constrained'"""
    return f"Case {scaffold['number']} {scaffold['label']}"


AUTHORS_MISSING = "the authors' runs are not shown: no checkout of their repository was named"


def case_panels(scaffolds, height):
    """A figure of one panel per case (sharing the y axis) under a row for the legend:
    (figure, legend axes, panels)."""
    fig = plt.figure(figsize=(DOUBLE, height), layout="constrained")
    grid = fig.add_gridspec(2, len(scaffolds), height_ratios=(0.2, 1.0))
    panels = []
    for i, scaffold in enumerate(scaffolds):
        ax = fig.add_subplot(grid[1, i], sharey=panels[0] if panels else None)
        ax.set_title(f"Case {scaffold['number']}, {scaffold['label']}", color=scaffold["colour"])
        ax.set_xlabel("generation")
        ax.grid(alpha=0.3, lw=0.5)
        panels.append(ax)
    key = fig.add_subplot(grid[0, :])      # after the panels: fig.axes[i] is case i + 1's
    key.axis("off")
    return fig, key, panels


def line_style(experiment):
    """An experiment's lines: the authors' thin and dashed, ours solid."""
    if experiment == experiments.AUTHORS:
        return {"color": experiment.colour, "lw": 0.8, "ls": "--"}
    return {"color": experiment.colour, "lw": 1.2, "ls": "-"}


def runs_count(by_case):
    """'10 runs a case', or '10/9/10 runs' when the cases differ."""
    counts = [len(courses) for courses in by_case.values()]
    return f"{counts[0]} run{'s' if counts[0] != 1 else ''} a case" if len(set(counts)) == 1 \
        else "/".join(map(str, counts)) + " runs"


def finish_case_panels(fig, key, panels, series, scaffolds, generations, what, out_dir, name):
    """'no data' where no experiment has runs, the generation axes, the legend row (one
    entry an experiment, and a note when the authors' runs are missing), and save."""
    for ax, scaffold in zip(panels, scaffolds):
        if not any(by_case.get(scaffold["name"]) for _, by_case in series):
            ax.text(0.5, 0.5, "no data", ha="center", va="center", transform=ax.transAxes,
                    color="0.4")
        ax.set_xlim(0, generations)
    handles = [Line2D([], [], **line_style(e), label=f"{e.label} ({runs_count(by_case)})")
               for e, by_case in series if by_case]
    if all(e != experiments.AUTHORS for e, _ in series):
        handles.append(Line2D([], [], ls="", label=AUTHORS_MISSING))
    key.legend(handles=handles, loc="center", ncol=2 if len(handles) > 1 else 1, title=what,
               title_fontsize=8, handlelength=2.0, columnspacing=1.5)
    save(fig, out_dir, name)


def fig9(series, scaffolds, generations, out_dir, name="fig9"):
    """One panel per case: each experiment of ours (series: [(experiment, {case:
    [course]})], experiments.series) with its mean best fitness per generation, the
    bootstrap 95 % band of the mean and each replicate's curve faintly; the authors'
    runs each as a thin dashed line; without them a note says why."""
    fig, key, panels = case_panels(scaffolds, 3.3)
    for index, (experiment, by_case) in enumerate(series):
        colour = experiment.colour
        for ax, scaffold in zip(panels, scaffolds):
            courses = by_case.get(scaffold["name"], [])
            if not courses:
                continue
            g, y = case_curves(f"{experiment.id} {scaffold['name']}",
                               [c["best_fitness"] for c in courses])
            g, y = g[:generations], y[:, :generations]
            if experiment == experiments.AUTHORS:
                for curve in y:
                    ax.plot(g, curve, **line_style(experiment))
                continue
            for curve in y:
                ax.plot(g, curve, color=colour, lw=0.4, alpha=0.35)
            ax.plot(g, y.mean(axis=0), **line_style(experiment))
            at = np.unique(np.linspace(0, len(g) - 1, min(len(g), BAND_POINTS)).round().astype(int))
            band = mean_band(y[:, at])
            if band is not None:
                # outlined and hatched, so that overlapping bands stay apart
                ax.fill_between(g[at], band[0], band[1], lw=0.6, ls="--",
                                facecolor=matplotlib.colors.to_rgba(colour, 0.15),
                                edgecolor=matplotlib.colors.to_rgba(colour, 0.8),
                                hatch=HATCHES[index % len(HATCHES)])
    panels[0].set_ylim(bottom=0)
    panels[0].set_ylabel("best fitness (leg lengths)")
    finish_case_panels(fig, key, panels, series, scaffolds, generations,
                       "best fitness: ours as the mean of the runs, its bootstrap 95 % band and "
                       "each run faintly; the authors' runs dashed", out_dir, name)


def tripods_figure(series, scaffolds, generations, out_dir, name="tripods"):
    """One panel per case: the share of each experiment's runs whose best is a tripod,
    per generation (series as fig9's); the authors' dashed."""
    fig, key, panels = case_panels(scaffolds, 2.6)
    for experiment, by_case in series:
        for ax, scaffold in zip(panels, scaffolds):
            courses = by_case.get(scaffold["name"], [])
            if not courses:
                continue
            n = min(min(len(c["best_gait"]) for c in courses), generations)
            share = np.mean([[gait == "tripod" for gait in c["best_gait"][:n]] for c in courses],
                            axis=0)
            ax.step(np.arange(n), share, where="post", **line_style(experiment))
    panels[0].set_ylim(-0.03, 1.03)
    panels[0].set_ylabel("runs whose best is a tripod")
    finish_case_panels(fig, key, panels, series, scaffolds, generations,
                       "share of the runs whose best is a tripod", out_dir, name)


def finals(runs, scaffolds, out_dir):
    """Left: each run's final best fitness per case, re-scored: the ensemble's median
    (points over a box) and its range (a line). Right: the share of each case's runs
    whose final best is a tripod, Wilson 95 % interval."""
    fig, (left, right) = plt.subplots(1, 2, figsize=(DOUBLE, 2.8), layout="constrained",
                                      gridspec_kw={"width_ratios": (3, 2)})
    grouped = runs_by_case(runs, scaffolds)
    names = [f"Case {s['number']}\n{s['label']}" for s, _ in grouped]
    spread = np.random.default_rng(SEED)       # the points' sideways jitter
    for x, (scaffold, group) in enumerate(grouped):
        colour = scaffold["colour"]
        if not group:
            left.text(x, 0.5, "no data", ha="center", va="center", color="0.4",
                      transform=left.get_xaxis_transform())
            right.text(x, 0.5, "no data", ha="center", va="center", color="0.4",
                       transform=right.get_xaxis_transform())
            continue
        rescores = [r["final_best"]["rescore"] for r in group]
        final = np.array([e["median"] for e in rescores])
        tripod = np.array([r["data"]["best_gait"][-1] == "tripod" for r in group])
        left.boxplot(final, positions=[x], widths=0.5, showfliers=False,
                     medianprops={"color": colour}, boxprops={"color": "0.4"},
                     whiskerprops={"color": "0.4"}, capprops={"color": "0.4"})
        jitter = x + spread.uniform(-0.12, 0.12, len(final))
        left.vlines(jitter, [e["min"] for e in rescores], [e["max"] for e in rescores],
                    color=colour, lw=0.6, alpha=0.8, zorder=2)
        for gait, marker in (("biped", "o"), ("tripod", "^")):
            mine = tripod if gait == "tripod" else ~tripod
            left.scatter(jitter[mine], final[mine], s=14, marker=marker, zorder=3,
                         facecolor=matplotlib.colors.to_rgba(colour, 0.6),
                         edgecolor=GAIT_COLOURS[gait], lw=0.8)
        k, n = int(tripod.sum()), len(group)
        low, high = wilson_interval(k, n)
        right.bar(x, k / n, width=0.6, color=matplotlib.colors.to_rgba(colour, 0.5),
                  edgecolor=colour)
        right.errorbar(x, k / n, yerr=[[k / n - low], [high - k / n]], color="k", lw=0.8,
                       capsize=3)
        right.text(x, high + 0.03, f"{k} of {n}", ha="center", va="bottom")
    # the narrow panel names the cases by number only
    for ax, labels in ((left, names), (right, [n.split("\n")[0] for n in names])):
        ax.set_xticks(range(len(grouped)), labels)
        ax.set_xlim(-0.6, len(grouped) - 0.4)
        ax.grid(alpha=0.3, lw=0.5, axis="y")
    left.set_ylabel("final best fitness, re-scored\n(leg lengths)")
    left.set_ylim(bottom=0)
    left.legend(handles=[Line2D([], [], ls="", marker=m, markerfacecolor="none",
                                markeredgecolor=GAIT_COLOURS[g], label=f"ends as a {g}")
                         for g, m in (("biped", "o"), ("tripod", "^"))] +
                [Line2D([], [], ls="", marker="|", markersize=10, color="0.4",
                        label="range of the re-scores")],
                loc="lower left", bbox_to_anchor=(0.0, 1.01), ncol=2, borderaxespad=0.0)
    right.set_ylabel("runs ending as a tripod")
    right.set_ylim(0, 1.15)
    right.set_title("share, Wilson 95 % interval", loc="left")
    save(fig, out_dir, "finals")


def learners_figure(learners, learner_runs, scaffolds, generations, out_dir):
    """Final best fitness per learner and case (bars: mean over replicates; dots: each
    replicate; above each bar its runs ending as tripods), and below, one panel per
    learner, the mean best fitness per generation of each case."""
    n = len(learners)
    fig = plt.figure(figsize=(DOUBLE, 5.2), layout="constrained")
    grid = fig.add_gridspec(2, n, height_ratios=(1.2, 1.0))
    bars = fig.add_subplot(grid[0, :])
    width = 0.8 / max(1, len(scaffolds))
    top = 1.0
    for i, learner in enumerate(learners):
        for j, scaffold in enumerate(scaffolds):
            group = [r for r in learner_runs
                     if r["learner"] == learner["name"] and r["case"] == scaffold["name"]]
            x = i - 0.4 + width * (j + 0.5)
            if not group:
                bars.text(x, 0.2, "no data", rotation=90, ha="center", va="bottom",
                          fontsize=6, color="0.4")
                continue
            finals = np.array([r["final_best"]["rescore"]["median"] for r in group])
            tripods = sum(r["data"]["best_gait"][-1] == "tripod" for r in group)
            bars.bar(x, finals.mean(), width * 0.9, color=scaffold["colour"], alpha=0.75,
                     label=case_label(scaffold) if i == 0 else None)
            bars.scatter(np.full(len(finals), x), finals, s=6, color="black", zorder=3)
            bars.text(x, max(finals.max(), finals.mean()) + 0.3, f"{tripods}/{len(group)}",
                      ha="center", va="bottom", fontsize=6)
            top = max(top, float(finals.max()))
    bars.set_xticks(range(n), [f"{l['label']}\n({l['name']})" for l in learners])
    bars.set_ylabel("final best fitness,\nre-scored (leg lengths)")
    bars.set_ylim(0, 1.2 * top)
    bars.grid(axis="y", alpha=0.3, lw=0.5)
    legend_above(bars, ncol=len(scaffolds),
                 title="final best: bars the mean, dots the replicates, "
                       "figures above: runs ending as tripods")
    panels = []
    curves_top = 1.0
    for i, learner in enumerate(learners):
        ax = fig.add_subplot(grid[1, i], sharey=panels[0] if panels else None)
        panels.append(ax)
        for scaffold in scaffolds:
            group = [r for r in learner_runs
                     if r["learner"] == learner["name"] and r["case"] == scaffold["name"]]
            if group:
                g, y = case_curves(f"{learner['name']} {scaffold['name']}",
                                   [r["data"]["best_fitness"] for r in group])
                ax.plot(g, y.mean(axis=0), color=scaffold["colour"])
                curves_top = max(curves_top, float(y.mean(axis=0).max()))
        ax.set_title(learner["label"])
        ax.set_xlim(0, generations)
        ax.set_xlabel("generation")
        ax.grid(alpha=0.3, lw=0.5)
        if i == 0:
            ax.set_ylabel("mean best fitness")
    # one scale for every learner's panel, from 0 to the highest mean best
    panels[0].set_ylim(0, 1.05 * curves_top)
    save(fig, out_dir, "learners")


# ----------------------------------------------------------------------------- main

def drawn(name, draw, *args):
    """draw(*args), any failure raised as a FigureError naming the figure."""
    try:
        draw(*args)
    except Exception as e:  # noqa: BLE001 - whatever failed, the figure is named
        raise FigureError(f"{name}: {e}") from e


def log_traceback(path, error):
    """Write error's traceback to path; returns where it went, for the message."""
    try:
        with open(path, "w", encoding="utf-8") as f:
            traceback.print_exception(type(error), error, error.__traceback__, file=f)
        return f"traceback in {path}"
    except OSError as e:
        return f"its traceback could not be written to {path}: {e.strerror}"


def draw_all(inputs, out_dir):
    """Draw every figure whose data is present; warn about the rest."""
    runs, walks, gallery = inputs["runs"], inputs["walks"], inputs["gallery"]
    if walks is None:
        warn("walks.json not found: skipping fig4a, fig4b, fig6")
    elif not present_walks(walks):
        warn("walks.json: both walks are null: skipping fig4a, fig4b, fig6")
    else:
        for gait in GAIT_COLOURS:
            if walks[gait] is None:
                warn(f"walks.json: no {gait} (null): fig4a, fig4b, fig6 show the "
                     "other walker only")
        drawn("fig4a", fig4a, walks, out_dir)
        drawn("fig4b", fig4b, walks, out_dir)
        drawn("fig6", fig6, walks, out_dir)
    if gallery is None:
        warn("gallery.json not found: skipping fig5")
    elif not gallery:
        warn("gallery.json: no individuals: skipping fig5")
    else:
        drawn("fig5", fig5, gallery, out_dir)
    if not runs:
        warn("reproduction.json lists no runs: skipping fig7, fig8, fig9, tripods, finals")
        return
    scaffolds = inputs["scaffolds"]
    for scaffold, group in runs_by_case(runs, scaffolds):
        if not group:
            warn(f"reproduction.json: no runs for case '{scaffold['name']}': fig8, fig9 and finals "
                 "say 'no data'")
    drawn("fig7", fig7, runs, walks, out_dir)
    drawn("fig8", fig8, runs, scaffolds, inputs["replicates"], inputs["generations"], out_dir)
    drawn("fig9", fig9, inputs["series"], scaffolds, inputs["generations"], out_dir)
    drawn("tripods", tripods_figure, inputs["series"], scaffolds, inputs["generations"], out_dir)
    drawn("finals", finals, runs, scaffolds, out_dir)
    if len(inputs["learners"]) > 1:
        drawn("learners", learners_figure, inputs["learners"], inputs["learner_runs"],
              scaffolds, inputs["generations"], out_dir)


def draw(run_dir, authors=None):
    """Load and check the inputs, draw every figure; returns the exit status."""
    try:
        inputs = load_inputs(run_dir, authors)
    except InputError as e:
        print(f"error: {e}", file=sys.stderr)
        return 1
    if all(e != experiments.AUTHORS for e, _ in inputs["series"]):
        warn(f"fig9, tripods: {AUTHORS_MISSING} (--authors PATH)")
    out_dir = os.path.join(run_dir, "figures")
    log = os.path.join(out_dir, LOG_NAME)
    try:
        os.makedirs(out_dir, exist_ok=True)
        with plt.rc_context(STYLE):
            draw_all(inputs, out_dir)
    except Exception as e:  # noqa: BLE001 - one line here, the traceback in the log
        print(f"error: drawing the figures failed: {e} ({log_traceback(log, e)})",
              file=sys.stderr)
        return 1
    if os.path.exists(log):
        os.remove(log)     # an earlier failure's
    return 0
