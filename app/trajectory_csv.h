// Trajectory files: one row per controller tick (1/30 s) and the final time.
#pragma once

#include <fstream>
#include <string>

#include "dynamics/coords.h"
#include "dynamics/observation.h"

namespace walkers::app {

class TrajectoryCsv {
 public:
  // with_controller adds the columns `state` and `x_target`. Throws if the
  // file cannot be written.
  TrajectoryCsv(const std::string& path, bool with_controller);
  void Write(double t, const State& state, const Observation& obs, const char* walking_state = nullptr,
             double x_target = 0.0);
  // Flushes and checks the file; throws if writing failed.
  void Close();

 private:
  std::string path_;
  std::ofstream out_;
  bool with_controller_;
};

}  // namespace walkers::app
