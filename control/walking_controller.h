// The walking state machine of paper §2.3 (docs/model.md, "Controller"):
// double support, left support, right support; virtual model control of the
// stance legs, the swing hip spring, and planting and unplanting feet through
// the dynamics' welds.
// It runs at 30 Hz; its torques are held between ticks.
#pragma once

#include <array>

#include "control/genome.h"
#include "control/preset.h"
#include "control/vmc.h"
#include "dynamics/equations_of_motion.h"
#include "dynamics/model.h"

namespace walkers {

enum class WalkingState { kDoubleSupport, kLeftSupport, kRightSupport };

// "DS", "LS", "RS"
const char* WalkingStateName(WalkingState state);

constexpr double kLockDuration = 2.0;       // [s] held in double support at the start
constexpr double kOnFloorMargin = 0.031;    // [m] ankle below halfFootY + this: foot on the floor
constexpr double kTouchdownMargin = 0.001;  // [m] swing ankle below halfFootY + this: touchdown
constexpr double kFirstStepLength = 0.01;   // [m] the first step must reach this far ahead of the stance ankle
constexpr double kStepLength = 0.04;        // [m] later steps
constexpr double kTargetLead = 0.8;         // [m] bunny target ahead of the feet's midpoint

// The preset's "stable" rule: may the walker leave double support?
bool IsStable(const Genome& genome, const Preset& preset, const State& state);

// The preset's fall rule: the trunk centre below a fraction of the standing height.
bool HasFallen(const Genome& genome, const Preset& preset, const State& state);

class WalkingController {
 public:
  WalkingController(const Genome& genome, const Model& model, const Preset& preset);

  // Both feet planted where they stand (or at the given welds), no torques,
  // double support, x_d = 0.
  const Inputs& Start(const State& state);
  const Inputs& Start(const Welds& welds);

  // One controller tick at time t: updates the state machine from the
  // walker's state and returns the inputs to hold until the next tick. A
  // tick that plants a foot holds the previous torques: the authors' loop
  // then advances one extra tick before it sets new ones (FinishTick).
  const Inputs& Tick(double t, const State& state);

  // True after a Tick that planted a foot, until FinishTick.
  bool awaits_extra_step() const { return awaits_extra_step_; }

  // The torques after the extra tick that follows a touchdown: from the state
  // it reached, with the feet on the floor as they were at the touchdown.
  const Inputs& FinishTick(const State& state);

  WalkingState state() const { return state_; }
  double x_target() const { return x_target_; }
  int footsteps() const { return footsteps_; }
  const Inputs& inputs() const { return inputs_; }

 private:
  // true when it planted a foot
  bool UpdateState(double t, const State& state, const Kinematics& kin);
  // the torques from the state, with the feet on the floor as at the tick's start
  void UpdateTorques(const State& state);

  Genome genome_;
  Model model_;
  Preset preset_;
  WalkingState state_ = WalkingState::kDoubleSupport;
  double x_target_ = 0.0;
  int footsteps_ = 0;
  Inputs inputs_;
  std::array<bool, kNumLegs> on_floor_{};  // at the tick's start
  bool awaits_extra_step_ = false;
};

}  // namespace walkers
