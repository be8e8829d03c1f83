// A profile of CVODE's steps through an evaluation, per controller tick and
// per walking state: how many steps, how many rejected attempts, their sizes
// and orders, which state component limits them (the largest weighted local
// error), and how many contact pairs, contact springs and joint stops switch
// on or off between steps. Fed by Evaluate's tick and step observers
// (control/evaluation.h); `walkers evaluate --profile` writes it, and
// docs/step_profile.md describes the files.
#pragma once

#include <array>
#include <ostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "control/walking_controller.h"
#include "dynamics/contact.h"
#include "dynamics/model.h"
#include "integration/integrator.h"

namespace walkers {

// y = (q, v): the state components CVODE's error test weighs
constexpr int kNumStateComponents = 2 * kNumCoords;
// "q_x", ..., "q_ankle_r", "v_x", ..., "v_ankle_r"
const std::array<std::string, kNumStateComponents>& StateComponentNames();

// The joint stops, leg by leg and joint by joint (AddJointStopTorques)
constexpr int kNumJointStops = kNumLegs * kNumJoints;

// What the right-hand side applies at one state: each contact pair's pushing
// springs (0 for a pair off or held by a weld, HeldByWeld) and each joint
// stop's engagement.
struct ContactSet {
  std::array<int, kNumContactPairs> elements{};
  std::array<bool, kNumJointStops> stops{};
};
ContactSet ContactSetAt(const Model& model, const State& state, const Welds& welds);

// One controller tick's steps (a tick runs from one tick observer call to the next).
struct TickProfile {
  double t = 0;  // [s] where the tick starts
  WalkingState state = WalkingState::kDoubleSupport;
  long steps = 0;
  long error_test_failures = 0;
  long nonlinear_failures = 0;
  double step_sum = 0;  // [s]
  double step_min = 0;  // [s]
  double step_max = 0;  // [s]
  int max_order = 0;
  // steps whose largest weighted local error is in this component
  std::array<long, kNumStateComponents> limiting{};
  // switches from the previous step's set to this step's (the first step of
  // a tick compares with the last of the tick before)
  std::array<long, kNumContactPairs> pair_switches{};  // pair on <-> off
  long spring_switches = 0;  // sum over pairs of |change of pushing springs|: a lower bound on springs switched
  std::array<long, kNumJointStops> stop_switches{};
  ContactSet at_end;  // what the tick's last step applied
  long PairSwitches() const;
  long StopSwitches() const;
};

class StepProfile {
 public:
  explicit StepProfile(const Model& model);

  // Evaluate's tick observer: starts a tick at t in the controller's state.
  void OnTick(double t, const State& state, const WalkingController& controller);
  // Evaluate's step observer: adds the step to the current tick.
  void OnStep(const StepInfo& step);

  // the ticks with at least one step, in order
  std::vector<TickProfile> Ticks() const;

  // One row per tick (docs/step_profile.md lists the columns).
  void WriteCsv(std::ostream& out) const;
  // Totals per walking state and over the evaluation (docs/step_profile.md).
  nlohmann::ordered_json Summary() const;

 private:
  Model model_;
  std::vector<TickProfile> ticks_;
  ContactSet previous_;
  bool has_previous_ = false;
};

}  // namespace walkers
