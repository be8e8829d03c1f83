#include "app/trajectory_csv.h"

namespace walkers::app {

TrajectoryCsv::TrajectoryCsv(const std::string& path, bool with_controller)
    : file_(std::make_unique<AtomicFileWriter>(path, "the trajectory file")), with_controller_(with_controller) {
  std::ostream& out = file_->stream();
  out.precision(10);
  out << "t";
  for (const char* name : kCoordNames) out << ',' << name;
  for (const char* name : kCoordNames) out << ',' << name << "_dot";
  out << ",kinetic,potential,trunk_contact";
  if (with_controller_) out << ",state,x_target";
  out << '\n';
}

void TrajectoryCsv::Write(double t, const State& state, const Observation& obs, const char* walking_state,
                          double x_target) {
  std::ostream& out = file_->stream();
  out << t;
  for (int i = 0; i < kNumCoords; ++i) out << ',' << state.q(i);
  for (int i = 0; i < kNumCoords; ++i) out << ',' << state.v(i);
  out << ',' << obs.kinetic << ',' << obs.potential << ',' << (obs.trunk_contact ? 1 : 0);
  if (with_controller_) out << ',' << (walking_state ? walking_state : "") << ',' << x_target;
  out << '\n';
}

void TrajectoryCsv::Close() { file_->Commit(); }

}  // namespace walkers::app
