#include "control/walking_controller.h"

#include <cmath>

#include "dynamics/kinematics.h"
#include "dynamics/observation.h"

namespace walkers {
namespace {

int SwingLeg(WalkingState s) { return s == WalkingState::kLeftSupport ? kRight : kLeft; }
int StanceLeg(WalkingState s) { return s == WalkingState::kLeftSupport ? kLeft : kRight; }

}  // namespace

const char* WalkingStateName(WalkingState state) {
  switch (state) {
    case WalkingState::kDoubleSupport:
      return "DS";
    case WalkingState::kLeftSupport:
      return "LS";
    case WalkingState::kRightSupport:
      return "RS";
  }
  return "?";
}

bool IsStable(const Genome& genome, const Preset& preset, const State& state) {
  const double tolerance = genome[kStableTolerance];
  const auto joint_rates = state.v.tail<6>();
  switch (preset.stable_rule) {
    case StableRule::kJointRateMagnitudes:
      return (joint_rates.array().abs() < tolerance).all();
    case StableRule::kSignedRatesAndTrunkMotion:
      return (joint_rates.array() < tolerance).all() && state.v(kX) + state.v(kY) < tolerance;
  }
  return false;
}

bool HasFallen(const Genome& genome, const Preset& preset, const State& state) {
  const double standing_height = genome.leg_length() + genome[kHalfFootY] + genome[kHalfBodyY];
  return state.q(kY) < preset.fall_fraction * standing_height;
}

WalkingController::WalkingController(const Genome& genome, const Model& model, const Preset& preset)
    : genome_(genome), model_(model), preset_(preset) {}

const Inputs& WalkingController::Start(const State& state) {
  Welds welds;
  for (int leg = 0; leg < kNumLegs; ++leg) welds[leg] = PlantFoot(model_, state, leg);
  return Start(welds);
}

const Inputs& WalkingController::Start(const Welds& welds) {
  state_ = WalkingState::kDoubleSupport;
  x_target_ = 0.0;
  footsteps_ = 0;
  awaits_extra_step_ = false;
  inputs_ = Inputs{};
  inputs_.welds = welds;
  return inputs_;
}

const Inputs& WalkingController::Tick(double t, const State& state) {
  Kinematics kin;
  ComputeKinematics(model_, state.q, state.v, &kin);
  // which feet are on the floor is read before anything moves
  for (int leg = 0; leg < kNumLegs; ++leg) {
    on_floor_[leg] = kin.legs[leg].ankle.p.y() < genome_[kHalfFootY] + kOnFloorMargin;
  }
  awaits_extra_step_ = UpdateState(t, state, kin);
  if (!awaits_extra_step_) UpdateTorques(state);
  return inputs_;
}

const Inputs& WalkingController::FinishTick(const State& state) {
  UpdateTorques(state);
  awaits_extra_step_ = false;
  return inputs_;
}

bool WalkingController::UpdateState(double t, const State& state, const Kinematics& kin) {
  if (state_ == WalkingState::kDoubleSupport) {
    // both feet are planted: where their welds hold them (the authors' welds
    // are exact; ours yield by micrometres, which would decide a tie)
    const double x_left = inputs_.welds[kLeft].anchor.x(), x_right = inputs_.welds[kRight].anchor.x();
    // after the lock, once stable: the rear foot swings (the left on a tie)
    if (t < kLockDuration || !IsStable(genome_, preset_, state)) return false;
    const int swing = x_left <= x_right ? kLeft : kRight;
    inputs_.welds[swing].active = false;
    state_ = swing == kLeft ? WalkingState::kRightSupport : WalkingState::kLeftSupport;
    // the bunny target runs ahead of the feet
    x_target_ = 0.5 * (x_left + x_right) + kTargetLead;
    return false;
  }
  // single support: plant the swing foot when it is down and far enough ahead
  const int swing = SwingLeg(state_), stance = StanceLeg(state_);
  const Vec2& swing_ankle = kin.legs[swing].ankle.p;
  const double lead = swing_ankle.x() - kin.legs[stance].ankle.p.x();
  const double step = footsteps_ == 0 ? kFirstStepLength : kStepLength;
  if (swing_ankle.y() < genome_[kHalfFootY] + kTouchdownMargin && lead > step) {
    inputs_.welds[swing] = PlantFoot(model_, state, swing);
    state_ = WalkingState::kDoubleSupport;
    ++footsteps_;
    return true;
  }
  return false;
}

void WalkingController::UpdateTorques(const State& state) {
  inputs_.joint_torque.setZero();
  const TrunkMotion trunk{state.q(kX), state.q(kY), state.v(kX), state.v(kY)};
  for (int leg = 0; leg < kNumLegs; ++leg) {
    const bool on_floor = on_floor_[leg];
    const bool single = state_ != WalkingState::kDoubleSupport;
    const int hip = JointIndex(leg, kHip);
    if (single && leg == SwingLeg(state_)) {
      // paper eq. (5): only the swing hip is driven
      inputs_.joint_torque(hip) = SwingHipTorque(genome_, state.q(hip));
      continue;
    }
    // a stance leg, driven only while its foot is on the floor
    if (!on_floor) continue;
    const SupportPhase phase = single ? SupportPhase::kSingle : SupportPhase::kDouble;
    const Vec3 F = VirtualForce(genome_, phase, x_target_, trunk, state.q(hip), state.v(hip));
    const Mat3 J = StanceLegJacobian(genome_[kTibiaLength], genome_[kFemurLength], StanceLegAngles(state.q, leg));
    const Vec3 tau = StanceLegTorques(J, F);  // (ankle, knee, hip)
    inputs_.joint_torque(JointIndex(leg, kAnkle)) = tau(0);
    inputs_.joint_torque(JointIndex(leg, kKnee)) = tau(1);
    inputs_.joint_torque(hip) = tau(2);
  }
}

}  // namespace walkers
