// The time left for a batch of runs (walkers reproduce), with each
// generation weighted by what it costs. A run's early generations, whose
// walkers fall within a second, cost a fraction of its late ones, whose
// walkers walk the whole evaluation; a pace measured on the early ones alone
// promises the end hours too soon.
//
// A generation's expected cost is the mean, over the runs of its kind
// (learner and case) finished before this session, of what that generation
// took (their generations.csv); with no finished run of its kind, the mean
// over every finished run; with none at all, every generation costs the same.
// The session's pace, its elapsed time per unit of expected cost done, turns
// the expected cost left into time.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace walkers {

class TimeLeft {
 public:
  explicit TimeLeft(int generations);

  // A run finished before this session: its kind and each generation's cost
  // (seconds, any common scale). A list of any other length is ignored.
  void AddFinished(const std::string& kind, const std::vector<double>& costs);
  // A run of the batch, of `kind`, with `completed` generations done before
  // this session (0 for a run not started; added again when it starts).
  void AddRun(const std::string& name, const std::string& kind, int completed);
  // Generation `generation` (0-based) of run `name` is done, `now_s` seconds
  // into the session. The pace is measured from the end of the first
  // generation done, so that loading and starting up do not count as work.
  void Done(const std::string& name, int generation, double now_s);

  // The time left for all runs at `now_s`: the expected cost of every run's
  // generations not done, at the session's pace (after its first generation
  // alone, the pace since the session began). None before a generation.
  std::optional<double> Estimate(double now_s) const;
  // The time left for run `name` alone at `now_s`: the expected cost of its
  // generations not done, at its own pace since its first generation here.
  std::optional<double> RunLeft(const std::string& name, double now_s) const;

 private:
  struct Run {
    std::string kind;
    int first = 0;  // the first generation done in this session
    int next = 0;   // the next generation to do
    int paced_from = -1;     // the generation after its first one done here; -1 before
    double paced_since = 0;  // when that first one was done
  };
  // the expected cost of generations [0, g) of a kind: its prefix sums
  const std::vector<double>& Prefix(const std::string& kind) const;

  int generations_;
  std::map<std::string, std::vector<std::vector<double>>> finished_;  // by kind
  std::map<std::string, Run> runs_;
  // the session's first generation done: its run, and when
  std::string first_run_;
  double first_done_s_ = 0;
  mutable std::map<std::string, std::vector<double>> prefix_;  // by kind; "" for every finished run
};

// A finished run's generation costs from its generations.csv: the wall time
// of each generation's evaluations, 1 / evals_per_s for each of them. Empty
// when the file cannot be read or a generation's rate is not a positive
// number (the estimate then does without the run).
std::vector<double> GenerationCosts(const std::string& generations_csv);

}  // namespace walkers
