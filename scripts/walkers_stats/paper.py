"""The paper's findings (its §3) that our runs are set beside. The tripods each case's
runs ended with are the scaffolds' own (evolve/scaffold.h, paper_tripod_finals; in
reproduction.json)."""

CASE3_LEADS_SHARE = 0.83    # share of generations in which case 3's mean best exceeds case 1's
CASE2_OVER_CASE1 = 0.66     # case 2's final mean best fitness over case 1's
BIPED_OVER_TRIPOD = 1.375   # the best biped's fitness over the best tripod's
RUNS_PER_CASE = 3           # the paper's runs of each case
GENERATIONS = 4000          # of each of its runs
FELL = "37–49 % (the authors' runs)"   # the evaluations that fell
BEST_BIPED_FROM, BEST_TRIPOD_FROM = 3, 2   # the cases the best biped and the best tripod came from
