// Progress of a long run on stderr: one line rewritten in place when stderr
// is a terminal, one line every few seconds otherwise (logs, CI).
#pragma once

#include <chrono>
#include <optional>
#include <string>

#include "evolve/run_config.h"

namespace walkers::app {

class Progress {
 public:
  explicit Progress(std::string label, double log_interval_s = 5.0);
  // `all_left_s`: the caller's estimate of the time left for a whole batch
  // of runs (walkers reproduce), shown after the run's own. `run_left_s`: the
  // caller's estimate of the run's own; without it, this session's pace
  // over the generations left.
  void Report(const GenerationSummary& s, std::optional<double> all_left_s = std::nullopt,
              std::optional<double> run_left_s = std::nullopt);
  // Ends the in-place line, if any.
  void Finish();

 private:
  std::string label_;
  bool terminal_;
  double log_interval_s_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_log_;
  int first_generation_ = -1;
  bool line_open_ = false;
};

// "1h02m", "3m05s", "42s"
std::string FormatDuration(double seconds);

}  // namespace walkers::app
