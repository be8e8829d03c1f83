#include "control/evaluation.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "control/start_pose.h"
#include "files/errors.h"
#include "dynamics/contact.h"
#include "dynamics/kinematics.h"
#include "dynamics/planting.h"

namespace walkers {

const char* GaitName(Gait gait) {
  switch (gait) {
    case Gait::kBiped:
      return "biped";
    case Gait::kTripod:
      return "tripod";
    case Gait::kNone:
      break;
  }
  return "none";
}

EvaluationSettings SettingsOfIntegrator(const std::string& integrator, std::optional<double> accuracy,
                                        std::optional<long> cut_off_rhs, const IntegrationChoiceNames& names) {
  EvaluationSettings settings;
  if (!ParseIntegrationMethod(integrator, &settings.integrator.method)) {
    throw InputError(names.integrator + " = \"" + integrator + "\" is none of cvode, rk-merson");
  }
  const bool rk_merson = settings.integrator.method == IntegrationMethod::kRkMerson;
  if (accuracy) {
    if (!rk_merson) throw InputError(names.accuracy + " applies to the rk-merson integrator only");
    if (!(*accuracy > 0.0 && *accuracy <= 1.0)) {
      throw InputError(names.accuracy + " = " + std::to_string(*accuracy) + " is outside its allowed range (0, 1]");
    }
    settings.integrator.accuracy = *accuracy;
  }
  if (cut_off_rhs && *cut_off_rhs < 0) {
    throw InputError(names.cut_off + " = " + std::to_string(*cut_off_rhs) +
                     " is outside its allowed range [0 (none), 1000000000] right-hand sides");
  }
  settings.cut_off_rhs = cut_off_rhs ? *cut_off_rhs : rk_merson ? kAuthorsCutOffRhs : 0;
  return settings;
}

namespace {

// The fitness and gait an outcome gives: a walk scores paper eq. (6) and is a
// tripod when its trunk supported it often enough; a fall or a failure scores
// -1 and a cut-off kCutOffFitness, with no gait class.
void ScoreOutcome(EvaluationResult* result) {
  switch (result->outcome) {
    case Outcome::kWalked:
      result->fitness = result->distance / result->leg_length;
      result->gait = result->trunk_contact_fraction >= kTripodContactFraction ? Gait::kTripod : Gait::kBiped;
      return;
    case Outcome::kFell:
    case Outcome::kFailed:
      result->fitness = -1.0;
      result->gait = Gait::kNone;
      return;
    case Outcome::kCutOff:
      result->fitness = kCutOffFitness;
      result->gait = Gait::kNone;
      return;
  }
}

}  // namespace

EvaluationResult Evaluate(const Genome& genome, const Preset& preset, const EvaluationSettings& settings,
                          const TickObserver& observer, const StepObserver& step_observer) {
  const auto wall_start = std::chrono::steady_clock::now();
  const bool rk_merson = settings.integrator.method == IntegrationMethod::kRkMerson;
  // Simbody's welds are exact at the level of accelerations and projected
  // after every step; CVODE's path holds them by Baumgarte's stabilisation
  WeldParameters welds = settings.weld;
  if (rk_merson) welds.stabilization = 0.0;
  const Model model = BuildModel(BodyOf(genome), ModelOptions{}, settings.contact, welds);
  const State start = StartState(model, settings.start_trunk_raise);

  WalkingController controller(genome, model, preset);
  Integrator integrator(model, settings.integrator);
  if (step_observer) integrator.SetStepObserver(step_observer);
  // both feet welded at x = 0: on that tie the left foot swings first
  integrator.Reset(0.0, start, controller.Start(StartWelds(model)));

  EvaluationResult result;
  result.preset = preset.name;
  result.leg_length = genome.leg_length();

  // The authors' loop: at each 1/30 s tick the controller decides; a
  // touchdown first advances one extra tick with the torques held; then the
  // fall check, the new torques and one tick. It ends after the tick that
  // reaches the duration.
  const long ticks = std::lround(settings.duration * kControlRate);
  long ticks_after_lock = 0, ticks_in_contact = 0;
  Kinematics kin;
  // each tick's instant: its bookkeeping (trunk support, the welds' drift,
  // the distance), then the fall check; false once the walker fell
  const auto record_standing = [&](double t) {
    const State& state = integrator.state();
    ComputeKinematics(model, state.q, state.v, &kin);
    if (t >= kLockDuration) {
      ++ticks_after_lock;
      ticks_in_contact += TrunkSupported(model, kin) ? 1 : 0;
    }
    for (int leg = 0; leg < kNumLegs; ++leg) {
      const Weld& weld = controller.inputs().welds[leg];
      if (weld.active) {
        result.max_weld_drift = std::max(result.max_weld_drift, (kin.legs[leg].ankle.p - weld.anchor).norm());
      }
    }
    result.distance = std::min(kin.legs[kLeft].ankle.p.x(), kin.legs[kRight].ankle.p.x());
    if (!HasFallen(genome, preset, state)) return true;
    result.outcome = Outcome::kFell;
    return false;
  };
  // the controller's inputs from now on; a weld switched on first projects
  // the state onto every active weld, as the authors' program calls
  // project() after enabling one
  const auto hold = [&](const Inputs& inputs) {
    bool weld_added = false, welds_switched = false;
    for (int leg = 0; leg < kNumLegs; ++leg) {
      const bool same = SameWeld(inputs.welds[leg], integrator.inputs().welds[leg]);
      welds_switched = welds_switched || !same;
      weld_added = weld_added || (inputs.welds[leg].active && !same);
    }
    if (weld_added && settings.project_on_plant) {
      State projected = integrator.state();
      // the authors' System::project at its default tolerance under their
      // integrator; onto the welds exactly under CVODE
      const bool projected_ok = rk_merson ? ProjectOntoWeldsAsSimbody(model, inputs.welds, kSimbodyProjectTolerance,
                                                                      &projected)
                                          : ProjectOntoWelds(model, inputs.welds, &projected);
      if (!projected_ok) {
        result.outcome = Outcome::kFailed;
        result.reason = "projection onto the welds did not converge at t=" + std::to_string(integrator.time());
        return false;
      }
      integrator.SetState(projected);
    }
    // the jumps the controller makes: welds switched, new torques
    if (welds_switched) integrator.SetWelds(inputs.welds);
    if (inputs.joint_torque != integrator.inputs().joint_torque) integrator.SetTorques(inputs.joint_torque);
    return true;
  };
  // the integration to tick k; false once it failed or passed the cut-off
  const auto advance = [&](long k) {
    const IntegrationStatus status = integrator.AdvanceTo(k / kControlRate);
    if (!status.ok()) {
      result.outcome = Outcome::kFailed;
      result.reason = status.reason;
      return false;
    }
    // the authors' evolver scored an evaluation past its wall-clock limit -124
    if (settings.cut_off_rhs > 0 && integrator.stats().rhs_evals > settings.cut_off_rhs) {
      result.outcome = Outcome::kCutOff;
      return false;
    }
    return true;
  };
  for (long k = 0; k < ticks;) {
    double t = k / kControlRate;
    if (!record_standing(t) || !hold(controller.Tick(t, integrator.state()))) break;
    if (controller.awaits_extra_step()) {
      if (observer) observer(t, integrator.state(), controller);
      if (!advance(++k)) break;
      t = k / kControlRate;
      if (!record_standing(t) || !hold(controller.FinishTick(integrator.state()))) break;
    }
    if (observer) observer(t, integrator.state(), controller);
    if (!advance(++k)) break;
  }
  // a walk is measured where it ended
  if (result.outcome == Outcome::kWalked) {
    ComputeKinematics(model, integrator.state().q, integrator.state().v, &kin);
    result.distance = std::min(kin.legs[kLeft].ankle.p.x(), kin.legs[kRight].ankle.p.x());
  }
  if (observer) observer(integrator.time(), integrator.state(), controller);

  result.sim_time = integrator.time();
  result.footsteps = controller.footsteps();
  result.trunk_contact_fraction =
      ticks_after_lock > 0 ? static_cast<double>(ticks_in_contact) / static_cast<double>(ticks_after_lock) : 0.0;
  ScoreOutcome(&result);

  result.integrator = settings.integrator.method;
  result.integrator_stats = integrator.stats();
  result.wall_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall_start).count();
  return result;
}

}  // namespace walkers
