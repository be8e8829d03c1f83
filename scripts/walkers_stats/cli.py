"""The commands:

  summary DIR [--authors PATH]   summary.json and summary.md of the reproduction in DIR
                                 (statistics, the claims' verdicts, the authors' runs
                                 beside ours when PATH names a checkout of theirs)
  figures DIR [--authors PATH]   DIR/figures/ (Fig. 9 with the authors' runs, given PATH)
  authors PATH                   check that PATH holds the authors' runs, and count them
  experiments ROOT [--authors PATH] [--readme FILE]
                                 the experiments side by side: ROOT/experiments.md and
                                 .json, ROOT/figures/experiments-*, and FILE's block of
                                 the claims (ROOT: the committed results, docs/results)
  cut-offs RUN_DIR...            the cut_offs.csv of each run made under a cut-off, from its
                                 evaluations.csv, so that its cut-offs outlive that
                                 (scripts/stage_results.sh)

`walkers reproduce` runs summary, then figures (and authors first, given
--authors-checkout). Bad input is an error naming the file and the field (or line and
column) on stderr, nothing is written, and the exit status is 1.
"""
import argparse
import sys

from . import authors as the_authors
from . import cut_offs, figures, load, side_by_side, summary


def load_checkout(path):
    """The authors' runs from a checkout, or None for no path."""
    return None if path is None else the_authors.load_authors(path)


def run_summary(args):
    """summary DIR: write summary.json and summary.md, print the verdicts."""
    rep = load.load_reproduction(args.run_dir)
    content = summary.summarize(rep, load_checkout(args.authors))
    try:
        summary.write(args.run_dir, content, rep)
    except OSError as e:
        print(f"error: writing the summary failed: {e}", file=sys.stderr)
        return 1
    print(summary.report(content))
    return 0


def run_figures(args):
    """figures DIR: draw every figure."""
    return figures.draw(args.run_dir, load_checkout(args.authors))


def run_authors(args):
    """authors PATH: read the authors' runs and count them."""
    print(the_authors.describe(the_authors.load_authors(args.checkout)))
    return 0


def run_experiments(args):
    """experiments ROOT: the experiments side by side."""
    return side_by_side.write(args.root, load_checkout(args.authors), args.readme)


def run_cut_offs(args):
    """cut-offs RUN_DIR...: the cut_offs.csv of each run made under a cut-off (every
    run read before any is written)."""
    counted = [(run_dir, cut_offs.run_counts(run_dir) if cut_offs.run_cut_off(run_dir) else None)
               for run_dir in args.run_dirs]
    for run_dir, counts in counted:
        print(f"{run_dir}: no cut-off, nothing to keep" if counts is None else
              f"wrote {cut_offs.write_run(run_dir, counts)}")
    return 0


def main(argv=None):
    """Parse the arguments, run the command; returns the exit status."""
    parser = argparse.ArgumentParser(prog="walkers_stats", description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter,
                                     epilog=__doc__)
    commands = parser.add_subparsers(dest="command", required=True)
    for name, run, helptext in (("summary", run_summary, "summary.json and summary.md"),
                                ("figures", run_figures, "the figures")):
        command = commands.add_parser(name, help=helptext)
        command.add_argument("run_dir", help="reproduction directory (with reproduction.json)")
        command.add_argument("--authors", metavar="PATH",
                             help="a checkout of the authors' repository: their runs beside ours")
        command.set_defaults(run=run)
    command = commands.add_parser("authors", help="check a checkout of the authors' repository")
    command.add_argument("checkout", metavar="PATH")
    command.set_defaults(run=run_authors)
    command = commands.add_parser("experiments", help="the experiments side by side")
    command.add_argument("root", metavar="ROOT",
                         help="the committed results (docs/results), each experiment in its folder")
    command.add_argument("--authors", metavar="PATH",
                         help="a checkout of the authors' repository: their runs beside ours")
    command.add_argument("--readme", metavar="FILE",
                         help="a file whose marked block gets the claims (README.md)")
    command.set_defaults(run=run_experiments)
    command = commands.add_parser("cut-offs", help="runs' cut_offs.csv from their evaluations.csv")
    command.add_argument("run_dirs", metavar="RUN_DIR", nargs="+")
    command.set_defaults(run=run_cut_offs)
    args = parser.parse_args(argv)
    try:
        return args.run(args)
    except load.InputError as e:
        print(f"error: {e}", file=sys.stderr)
        return 1
