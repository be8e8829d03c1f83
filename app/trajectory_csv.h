// Trajectory files: one row per controller tick (1/30 s) and the final time.
#pragma once

#include <memory>
#include <string>

#include "dynamics/coords.h"
#include "dynamics/observation.h"
#include "files/durable_file.h"

namespace walkers::app {

class TrajectoryCsv {
 public:
  // with_controller adds the columns `state` and `x_target`. The rows go to a
  // temporary file that Close() renames into place (files/durable_file.h): a
  // failed or interrupted command leaves an earlier file at `path` as it was.
  // Throws if the file cannot be written.
  TrajectoryCsv(const std::string& path, bool with_controller);
  void Write(double t, const State& state, const Observation& obs, const char* walking_state = nullptr,
             double x_target = 0.0);
  // Flushes, checks and renames the file into place; throws if writing failed.
  void Close();

 private:
  std::unique_ptr<AtomicFileWriter> file_;
  bool with_controller_;
};

}  // namespace walkers::app
