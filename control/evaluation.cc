#include "control/evaluation.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "control/start_pose.h"
#include "dynamics/contact.h"
#include "dynamics/kinematics.h"

namespace walkers {

const char* GaitName(Gait gait) { return gait == Gait::kTripod ? "tripod" : "biped"; }

EvaluationResult Evaluate(const Genome& genome, const Preset& preset, const EvaluationSettings& settings,
                          const TickObserver& observer) {
  const auto wall_start = std::chrono::steady_clock::now();
  const Model model = BuildModel(BodyOf(genome), ModelOptions{}, settings.contact, settings.weld);
  const State start = StartState(model);

  WalkingController controller(genome, model, preset);
  Integrator integrator(model, settings.integrator);
  integrator.Reset(0.0, start, controller.Start(start));

  EvaluationResult result;
  result.preset = preset.name;
  result.leg_length = genome.leg_length();

  const long ticks = std::lround(settings.duration * kControlRate);
  long ticks_after_lock = 0, ticks_in_contact = 0;
  Kinematics kin;
  for (long k = 0;; ++k) {
    const double t = k / kControlRate;
    const State& state = integrator.state();
    ComputeKinematics(model, state.q, state.v, &kin);

    // bookkeeping of this instant: trunk contact, the welds' drift
    if (t >= kLockDuration) {
      ++ticks_after_lock;
      ticks_in_contact += TrunkTouchesGround(model, kin) ? 1 : 0;
    }
    for (int leg = 0; leg < kNumLegs; ++leg) {
      const Weld& weld = controller.inputs().welds[leg];
      if (weld.active) {
        result.max_weld_drift = std::max(result.max_weld_drift, (kin.legs[leg].ankle.p - weld.anchor).norm());
      }
    }
    result.distance = std::min(kin.legs[kLeft].ankle.p.x(), kin.legs[kRight].ankle.p.x());

    if (HasFallen(genome, preset, state)) {
      result.fell = true;
      break;
    }
    if (k == ticks) break;

    integrator.SetInputs(controller.Tick(t, state));
    if (observer) observer(t, state, controller);
    const IntegrationStatus status = integrator.AdvanceTo((k + 1) / kControlRate);
    if (!status.ok()) {
      result.failure = status.reason;
      break;
    }
  }
  if (observer) observer(integrator.time(), integrator.state(), controller);

  result.sim_time = integrator.time();
  result.footsteps = controller.footsteps();
  result.trunk_contact_fraction =
      ticks_after_lock > 0 ? static_cast<double>(ticks_in_contact) / static_cast<double>(ticks_after_lock) : 0.0;
  result.gait = result.trunk_contact_fraction >= kTripodContactFraction ? Gait::kTripod : Gait::kBiped;
  result.fitness = result.fell || !result.failure.empty() ? -1.0 : result.distance / result.leg_length;

  result.integrator_stats = integrator.stats();
  result.cvode_steps = result.integrator_stats.steps;
  result.rhs_evals = result.integrator_stats.rhs_evals;
  result.wall_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall_start).count();
  return result;
}

}  // namespace walkers
