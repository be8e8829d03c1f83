"""The statistics of a reproduction: the one owner of its summary and figures.

`walkers reproduce` runs the evolution, re-scores each run's finals and writes what needs
the simulator (reproduction.json, walks.json, gallery.json: evolve/reproduction.h); this
package reads those files and every run's generations.csv and writes everything else:

  load.py        reading the files, every field checked
  statistics.py  the tests, effect sizes and intervals, each computed here only
  claims.py      the paper's claims, each with its test, effect and verdict
  authors.py     the authors' own runs, from a checkout the user names, beside ours
  experiments.py the experiments set side by side (the authors', ours on CVODE, ours as
                 the authors ran it), declared once
  tripods.py     where the tripods go, in each experiment
  cut_offs.py    the cut-offs' share, in each experiment that has a cut-off
  summary.py     summary.json and summary.md
  figures.py     figures/ (the paper's Figs. 4-9, tripods, finals, learners)
  side_by_side.py  the experiments side by side: experiments.md and .json, their figures,
                 the README's table of claims
  paper.py       the paper's findings our runs are set beside
  text.py        numbers as the lines and tables print them

Run it as `/usr/bin/python3 scripts/walkers_stats COMMAND ...` (Debian's python3 with
python3-scipy and python3-matplotlib; cli.py lists the commands).
"""
