// The seam between a system (integration/system.h) and the methods that
// integrate it: CVODE (integration/cvode_integrator.h), the accurate one, and
// Simbody's Runge-Kutta-Merson at the authors' settings
// (integration/rk_merson.h), which reproduces their program's numerics on
// purpose. The caller changes what the system holds between calls and marks
// each jump: new torques at a tick, a weld switched, a projected state.
#pragma once

#include <functional>
#include <string>

#include "dynamics/coords.h"
#include "integration/system.h"

namespace walkers {

struct Inputs;

enum class IntegrationMethod { kCvode, kRkMerson };

enum class MultistepMethod { kBdf, kAdams };

// How CVODE's Newton systems (18x18) are stored and solved.
enum class LinearSolver {
  // the 9x9 Schur complement (integration/schur_linear_solver.h) of a matrix
  // stored as its blocks (integration/block_matrix18.h); needs the analytic
  // Jacobian. Bit-identical to kSchurComplement, with less copying.
  kSchurBlocks,
  kSchurComplement,  // the 9x9 Schur complement of a dense 18x18 matrix
  kDense,            // SUNDIALS' dense LU of the whole matrix
};

// Where CVODE's Newton iteration gets the Jacobian of the right-hand side.
enum class JacobianSource {
  kAnalytic,          // SecondOrderSystem::AccelerationJacobian
  kFiniteDifference,  // CVODE's own difference quotients: 18 right-hand sides each
};

struct IntegratorSettings {
  IntegrationMethod method = IntegrationMethod::kCvode;

  // ---- CVODE ----
  MultistepMethod multistep = MultistepMethod::kBdf;
  // chosen by the accuracy criterion of docs/performance.md ("Accuracy")
  double relative_tolerance = 1e-7;           // [-]
  double absolute_tolerance_position = 1e-7;  // [m, rad]
  double absolute_tolerance_velocity = 1e-5;  // [m/s, rad/s]
  int max_order = 5;                          // BDF: 1..5, Adams: 1..12
  JacobianSource jacobian = JacobianSource::kAnalytic;
  LinearSolver linear_solver = LinearSolver::kSchurBlocks;
  bool stability_limit_detection = false;
  // When CVODE refreshes the Newton matrix I - gamma J: after this relative
  // change of gamma, and at least every this many steps (CVODE's defaults).
  double newton_matrix_gamma_change = 0.3;
  long newton_matrix_max_age = 20;  // [steps]
  // Restart CVODE (back to order 1) whenever the held joint torques change,
  // that is at every controller tick: its history then never straddles a
  // jump of the right-hand side. It takes about 10 % fewer steps, but it
  // fails the accuracy criterion on a stalled walker (docs/performance.md),
  // so production leaves CVODE's history across the jumps; when its error
  // test cannot cope (the history still holds the old accelerations),
  // AdvanceTo restarts at the jump and tries again. Switching a weld always restarts.
  bool restart_at_ticks = false;
  // A restart begins with the step CVODE last took instead of its own estimate.
  bool restart_with_last_step = false;
  // Locate where the right-hand side switches law (a contact pair starting or
  // stopping to touch, a joint stop engaging or letting go: the system's
  // SwitchFunctions) with CVODE's root finding, and restart CVODE there, so
  // that its history never straddles a kink of the contact forces. Off in
  // production: a swing's steps go to the toe's impact and to the foot on its
  // springs, not to the switches, so it takes as many steps or more, and the
  // switch functions cost about a fifth of a step each (docs/performance.md).
  bool locate_contact_switches = false;
  // CVODE's vector and matrix bookkeeping through fixed-size loops
  // (integration/fixed_size_ops.h) instead of SUNDIALS' run-time-length ones
  // (the block Newton matrix has only its own fixed-size operations).
  // Bit-identical results either way; only the speed differs.
  bool fixed_size_ops = true;

  // ---- RK-Merson, as the authors ran Simbody (their walker.cpp) ----
  double accuracy = 0.05;              // [-] Integrator::setAccuracy
  double constraint_tolerance = 0.01;  // [-] Integrator::setConstraintTolerance

  long step_budget = 1000000;  // steps allowed since the last Reset
};

struct IntegratorStats {
  long steps = 0;
  long rhs_evals = 0;  // every right-hand side, including those of finite-difference Jacobians
  long jacobian_evals = 0;
  long error_test_failures = 0;
  // CVODE: the Newton iteration failed to converge; RK-Merson: a projection
  // onto the constraints failed
  long nonlinear_failures = 0;
  long restarts = 0;
  long switches_located = 0;  // roots of the system's switch functions (locate_contact_switches)
};

enum class IntegrationFailure { kNone, kNonFinite, kStepBudget, kSolver };

struct IntegrationStatus {
  IntegrationFailure failure = IntegrationFailure::kNone;
  std::string reason;  // empty on success
  bool ok() const { return failure == IntegrationFailure::kNone; }
};

// One step a method accepted, as a step observer sees it.
struct StepInfo {
  double t = 0;     // [s] where the step ended
  double step = 0;  // [s] its size
  int order = 0;    // of the method that took it
  // attempts rejected on the way to it: by the local error test, and by the
  // Newton iteration (CVODE) or the projection (RK-Merson) failing
  long error_test_failures = 0;
  long nonlinear_failures = 0;
  // CVODE: each component's estimated local error times its error weight,
  // y = (q, v): the largest is the component that limits the step size
  Eigen::Matrix<double, 2 * kNumCoords, 1> weighted_error = Eigen::Matrix<double, 2 * kNumCoords, 1>::Zero();
  const State* state = nullptr;    // at t
  const Inputs* inputs = nullptr;  // held during the step (the walker's Integrator fills it in)
};
using StepObserver = std::function<void(const StepInfo&)>;

// What changed in the system at the current time.
enum class Jump {
  kInputs,       // the held inputs (new joint torques at a tick)
  kConstraints,  // a weld switched on or off
};

class TimeStepper {
 public:
  virtual ~TimeStepper() = default;

  // Starts a new trajectory at (t0, y0); clears the stats.
  virtual void Reset(double t0, const SystemState& y0) = 0;

  // The system's right-hand side jumps at the current time.
  virtual void MarkJump(Jump jump) = 0;

  // Replaces the state at the current time (a jump, such as a projection
  // onto the welds at planting).
  virtual void SetState(const SystemState& y) = 0;

  // Integrates from the current time to t (> current time), never past it.
  // On failure the state is the last one reached and the status says why.
  virtual IntegrationStatus AdvanceTo(double t) = 0;

  virtual double time() const = 0;
  virtual const SystemState& state() const = 0;
  virtual IntegratorStats stats() const = 0;

  // Calls `observer` after every step the method accepts (none: nullptr);
  // the results stay bit-identical.
  virtual void SetStepObserver(StepObserver observer) = 0;
};

}  // namespace walkers
