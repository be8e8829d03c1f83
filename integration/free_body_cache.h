// The walker's state in the authors' coordinates (ToFreeBodies,
// dynamics/planting.h), remembered for the last few states asked for.
// An RK-Merson attempt asks for the same few states again and again: the
// step's start for both of its error norms, the step's end for the error
// estimate and both projections. Each conversion is a pass of the
// kinematics, so the repeats cost about a tenth of an evaluation under
// RK-Merson (docs/performance.md, "RK-Merson against CVODE"). A state is
// recognised by its bits, so a remembered conversion is the one that would be
// computed.
#pragma once

#include <array>

#include "dynamics/coords.h"
#include "dynamics/model.h"
#include "dynamics/planting.h"

namespace walkers {

class FreeBodyCache {
 public:
  FreeBodyState Get(const Model& model, const State& state);

 private:
  // a step's start, its end and the embedded solution: the states of an attempt
  static constexpr int kSize = 3;
  struct Entry {
    State state;
    FreeBodyState free_bodies;
    bool valid = false;
  };
  std::array<Entry, kSize> entries_;
  int next_ = 0;  // the oldest entry, replaced next
};

}  // namespace walkers
