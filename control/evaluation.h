// One evaluation of a genome: 15 s of walking under the state machine, scored
// by paper eq. (6). Pure: the same genome, preset and settings give
// bit-identical results (but for wall_ms) on any thread.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "control/genome.h"
#include "control/preset.h"
#include "control/walking_controller.h"
#include "integration/integrator.h"

namespace walkers {

// A walker that did not walk the whole duration (it fell, failed or was cut
// off) has no gait class.
enum class Gait { kBiped, kTripod, kNone };

// "biped", "tripod", "none"
const char* GaitName(Gait gait);

// A walker whose trunk touches the ground in at least this fraction of the
// ticks after the lock is a tripod (docs/model.md gives the reasons).
constexpr double kTripodContactFraction = 0.10;

// The fitness of an evaluation cut off for taking too long, as the authors'
// evolver scored every evaluation past 25 s of wall clock (their
// evolution/newEvolver2.py); it sorts below every fall.
constexpr double kCutOffFitness = -124.0;

// The authors' cut-off of 25 s of wall clock on their machine, in
// right-hand sides of RK-Merson at their accuracy: their program's time
// grows with its right-hand sides, and this budget cuts off case 1's early
// children as often as theirs were cut off (docs/fidelity.md, "The cut-off").
constexpr long kAuthorsCutOffRhs = 128000;

// System::project's default tolerance, at which the authors' program
// projects onto the welds at a touchdown (docs/model.md, "RK-Merson").
constexpr double kSimbodyProjectTolerance = 1e-4;

struct EvaluationSettings {
  double duration = 15.0;  // [s]
  IntegratorSettings integrator;
  // An evaluation whose integration takes more right-hand sides than this
  // stops and scores kCutOffFitness: the authors' 25 s cut-off in units
  // that do not depend on the machine (docs/fidelity.md, "The cut-off").
  // 0: no cut-off.
  long cut_off_rhs = 0;
  ContactParameters contact;
  WeldParameters weld;
  // Switching a weld on projects the state onto the active welds as the
  // authors' program does (ProjectOntoWelds), instead of letting the weld's
  // stabilisation pull the foot into place.
  bool project_on_plant = true;
  // [m] the start pose's trunk raised by this before its projection onto the
  // welds (StartState): how the accuracy criterion's ensembles perturb a walk
  // (control/accuracy.h). Evaluations and runs leave it at 0.
  double start_trunk_raise = 0.0;
};

// How the caller names the three choices of SettingsOfIntegrator in its
// messages: the command line's options or the Python module's arguments.
struct IntegrationChoiceNames {
  std::string integrator = "integrator";
  std::string accuracy = "accuracy";
  std::string cut_off = "cut_off";
};

// The evaluation settings of an integrator by its name ("cvode",
// "rk-merson"): its accuracy (RK-Merson's; none: the authors' 0.05) and its
// cut-off in right-hand sides (none: the integrator's own, the authors'
// kAuthorsCutOffRhs under RK-Merson and none under CVODE; 0: none). Throws
// InputError naming, by `names`, the choice that is not allowed.
EvaluationSettings SettingsOfIntegrator(const std::string& integrator, std::optional<double> accuracy = std::nullopt,
                                        std::optional<long> cut_off_rhs = std::nullopt,
                                        const IntegrationChoiceNames& names = {});

// How an evaluation ended; its fitness and gait follow from it.
enum class Outcome {
  kWalked,  // walked the whole duration: paper eq. (6), a biped or a tripod
  kFell,    // fell (HasFallen): fitness -1, no gait class
  kFailed,  // the integration or a projection onto the welds failed: fitness -1, no gait class
  kCutOff,  // took more right-hand sides than EvaluationSettings::cut_off_rhs: kCutOffFitness, no gait class
};

struct EvaluationResult {
  Outcome outcome = Outcome::kWalked;
  std::string reason;          // why it failed (Outcome::kFailed); empty otherwise
  double fitness = -1;         // from the outcome: paper eq. (6) distance / leg length for a walk
  double distance = 0;         // [m] min(x_footL, x_footR) when the evaluation ended
  double leg_length = 0;       // [m] tibia + femur
  int footsteps = 0;           // touchdowns
  double trunk_contact_fraction = 0;  // of the 30 Hz ticks after the lock
  Gait gait = Gait::kBiped;    // from the outcome and trunk_contact_fraction
  double sim_time = 0;         // [s] simulated
  double wall_ms = 0;          // [ms] wall time (not deterministic)
  IntegrationMethod integrator = IntegrationMethod::kCvode;  // the method that integrated it
  IntegratorStats integrator_stats;  // every counter of the integrator: steps, right-hand sides, ...
  double max_weld_drift = 0;   // [m] furthest a planted foot's centre moved from its weld, at ticks
  std::string preset;
};

// Called at every controller tick (after the controller decided) and once at
// the end, with the time, the walker's state and the controller.
using TickObserver = std::function<void(double t, const State& state, const WalkingController& controller)>;

// A step observer (integration/integrator.h) sees every CVODE step; the
// results stay bit-identical.
EvaluationResult Evaluate(const Genome& genome, const Preset& preset, const EvaluationSettings& settings = {},
                          const TickObserver& observer = nullptr, const StepObserver& step_observer = nullptr);

}  // namespace walkers
