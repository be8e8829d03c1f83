"""The commands:

  summary DIR [--authors PATH]   summary.json and summary.md of the reproduction in DIR
                                 (statistics, the claims' verdicts, the authors' runs
                                 beside ours when PATH names a checkout of theirs)
  figures DIR [--authors PATH]   DIR/figures/ (Fig. 9 with the authors' runs, given PATH)
  authors PATH                   check that PATH holds the authors' runs, and count them

`walkers reproduce` runs summary, then figures (and authors first, given
--authors-checkout). Bad input is an error naming the file and the field (or line and
column) on stderr, nothing is written, and the exit status is 1.
"""
import argparse
import sys

from . import authors as the_authors
from . import figures, load, summary


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
    args = parser.parse_args(argv)
    try:
        return args.run(args)
    except load.InputError as e:
        print(f"error: {e}", file=sys.stderr)
        return 1
