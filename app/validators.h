// Options and validators shared by the commands.
#pragma once

#include <cmath>
#include <sstream>
#include <algorithm>
#include <string>
#include <thread>

#include <CLI/CLI.hpp>

namespace walkers::app {

// A finite number in [lo, hi]; unlike CLI::Range it rejects nan.
inline CLI::Validator FiniteRange(double lo, double hi) {
  std::ostringstream range;
  range << "[" << lo << ", " << hi << "]";
  return CLI::Validator(
      [lo, hi, r = range.str()](std::string& text) -> std::string {
        double x = 0;
        if (!CLI::detail::lexical_cast(text, x) || !std::isfinite(x) || x < lo || x > hi) {
          return "value " + text + " is not a finite number in " + r;
        }
        return "";
      },
      "FLOAT in " + range.str());
}

// --preset: where the paper and the authors' program differ (control/preset.h)
inline CLI::Option* AddPresetOption(CLI::App* sub, std::string* preset) {
  return sub->add_option("--preset", *preset, "Where the paper and the authors' program differ")
      ->check(CLI::IsMember({"paper", "original"}))
      ->capture_default_str();
}

// --threads: worker threads; left at 0, ThreadsOrAllCores gives every core
inline CLI::Option* AddThreadsOption(CLI::App* sub, int* threads) {
  return sub->add_option("--threads", *threads, "Worker threads (default: all cores)")->check(CLI::Range(1, 1024));
}

inline int ThreadsOrAllCores(int requested) {
  return requested > 0 ? requested : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

}  // namespace walkers::app
