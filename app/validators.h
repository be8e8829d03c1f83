// Option validators shared by the commands.
#pragma once

#include <cmath>
#include <sstream>
#include <string>

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

}  // namespace walkers::app
