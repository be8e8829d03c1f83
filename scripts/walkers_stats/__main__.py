"""`python3 scripts/walkers_stats ...` (or `python3 -m walkers_stats` with scripts/ on the
path): cli.main."""
import os
import sys

if not __package__:
    # run as a folder: the package is imported from its parent, and this folder
    # leaves the path (its statistics.py would hide the standard library's)
    here = os.path.dirname(os.path.abspath(__file__))
    sys.path[:] = [p for p in sys.path if os.path.abspath(p or ".") != here]
    sys.path.insert(0, os.path.dirname(here))

from walkers_stats.cli import main  # noqa: E402

sys.exit(main())
