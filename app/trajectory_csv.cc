#include "app/trajectory_csv.h"

#include <stdexcept>

namespace walkers::app {

TrajectoryCsv::TrajectoryCsv(const std::string& path, bool with_controller)
    : path_(path), out_(path), with_controller_(with_controller) {
  if (!out_) throw std::runtime_error(path + ": cannot write the trajectory file");
  out_.precision(10);
  out_ << "t";
  for (const char* name : kCoordNames) out_ << ',' << name;
  for (const char* name : kCoordNames) out_ << ',' << name << "_dot";
  out_ << ",kinetic,potential,trunk_contact";
  if (with_controller_) out_ << ",state,x_target";
  out_ << '\n';
}

void TrajectoryCsv::Write(double t, const State& state, const Observation& obs, const char* walking_state,
                          double x_target) {
  out_ << t;
  for (int i = 0; i < kNumCoords; ++i) out_ << ',' << state.q(i);
  for (int i = 0; i < kNumCoords; ++i) out_ << ',' << state.v(i);
  out_ << ',' << obs.kinetic << ',' << obs.potential << ',' << (obs.trunk_contact ? 1 : 0);
  if (with_controller_) out_ << ',' << (walking_state ? walking_state : "") << ',' << x_target;
  out_ << '\n';
}

void TrajectoryCsv::Close() {
  out_.close();
  if (!out_) throw std::runtime_error(path_ + ": writing the trajectory file failed");
}

}  // namespace walkers::app
