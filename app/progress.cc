#include "app/progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace walkers::app {

std::string FormatDuration(double seconds) {
  const long s = std::lround(std::max(0.0, seconds));
  char buffer[32];
  if (s >= 3600) {
    std::snprintf(buffer, sizeof(buffer), "%ldh%02ldm", s / 3600, (s % 3600) / 60);
  } else if (s >= 60) {
    std::snprintf(buffer, sizeof(buffer), "%ldm%02lds", s / 60, s % 60);
  } else {
    std::snprintf(buffer, sizeof(buffer), "%lds", s);
  }
  return buffer;
}

Progress::Progress(std::string label, double log_interval_s)
    : label_(std::move(label)),
      terminal_(::isatty(STDERR_FILENO) == 1),
      log_interval_s_(log_interval_s),
      start_(std::chrono::steady_clock::now()),
      last_log_(start_) {}

void Progress::Report(const GenerationSummary& s, std::optional<double> all_left_s,
                      std::optional<double> run_left_s) {
  const auto now = std::chrono::steady_clock::now();
  if (first_generation_ < 0) first_generation_ = s.generation;
  const bool last = s.generation + 1 == s.generations;
  if (!terminal_ && !last && s.generation != first_generation_ &&
      std::chrono::duration<double>(now - last_log_).count() < log_interval_s_) {
    return;
  }
  last_log_ = now;

  // time left: the caller's, or from this session's pace
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const int done = s.generation + 1 - first_generation_;
  const double left = run_left_s.value_or(elapsed / done * (s.generations - s.generation - 1));
  // all runs cannot end before this one: never show less than its own estimate
  const std::string all = all_left_s ? ", all runs " + FormatDuration(std::max(*all_left_s, left)) : "";
  char line[320];
  std::snprintf(line, sizeof(line),
                "%s gen %d/%d  best %.3f  ave3 %.3f  ceiling %.3f  %.1f evals/s  %s left%s", label_.c_str(),
                s.generation + 1, s.generations, s.best_fitness, s.ave_best3, s.ceiling, s.evals_per_s,
                FormatDuration(left).c_str(), all.c_str());
  if (terminal_) {
    std::fprintf(stderr, "\r\033[K%s", line);
    line_open_ = true;
  } else {
    std::fprintf(stderr, "%s\n", line);
  }
  std::fflush(stderr);
}

void Progress::Finish() {
  if (line_open_) std::fprintf(stderr, "\n");
  line_open_ = false;
}

}  // namespace walkers::app
