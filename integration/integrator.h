// Time integration of the walker with SUNDIALS CVODE (BDF, Newton iteration,
// dense direct linear solver). Each Integrator owns its SUNContext and CVODE
// memory and shares nothing, so many run at once on different threads.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "dynamics/coords.h"
#include "dynamics/equations_of_motion.h"
#include "dynamics/model.h"

namespace walkers {

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
  kAnalytic,          // AccelerationJacobian (dynamics/jacobian.h)
  kFiniteDifference,  // CVODE's own difference quotients: 18 right-hand sides each
};

struct IntegratorSettings {
  MultistepMethod method = MultistepMethod::kBdf;
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
  bool restart_on_torque_change = false;
  // A restart begins with the step CVODE last took instead of its own estimate.
  bool restart_with_last_step = false;
  // CVODE's vector and matrix bookkeeping through fixed-size loops
  // (integration/fixed_size_ops.h) instead of SUNDIALS' run-time-length ones
  // (the block Newton matrix has only its own fixed-size operations).
  // Bit-identical results either way; only the speed differs.
  bool fixed_size_ops = true;
  long step_budget = 1000000;  // steps allowed since the last Reset
};

struct IntegratorStats {
  long steps = 0;
  long rhs_evals = 0;  // every right-hand side, including those of finite-difference Jacobians
  long jacobian_evals = 0;
  long error_test_failures = 0;
  long nonlinear_failures = 0;
  long restarts = 0;
};

enum class IntegrationFailure { kNone, kNonFinite, kStepBudget, kSolver };

struct IntegrationStatus {
  IntegrationFailure failure = IntegrationFailure::kNone;
  std::string reason;  // empty on success
  bool ok() const { return failure == IntegrationFailure::kNone; }
};

// One step CVODE accepted, as a step observer sees it (Integrator::SetStepObserver).
struct StepInfo {
  double t = 0;     // [s] where the step ended
  double step = 0;  // [s] its size
  int order = 0;    // of the method that took it
  // attempts rejected on the way to it: by the local error test, and by the
  // Newton iteration failing to converge
  long error_test_failures = 0;
  long nonlinear_failures = 0;
  // each component's estimated local error times its error weight, y = (q, v):
  // the largest is the component that limits the step size
  Eigen::Matrix<double, 2 * kNumCoords, 1> weighted_error = Eigen::Matrix<double, 2 * kNumCoords, 1>::Zero();
  const State* state = nullptr;    // at t
  const Inputs* inputs = nullptr;  // held during the step
};
using StepObserver = std::function<void(const StepInfo&)>;

class Integrator {
 public:
  explicit Integrator(const Model& model, const IntegratorSettings& settings = {});
  ~Integrator();
  Integrator(const Integrator&) = delete;
  Integrator& operator=(const Integrator&) = delete;

  // Starts a new trajectory at (t0, state) holding `inputs`; clears the stats.
  void Reset(double t0, const State& state, const Inputs& inputs = {});

  // Replaces the held inputs from the current time on.
  void SetInputs(const Inputs& inputs);

  // Replaces the state at the current time (a jump, such as a projection onto
  // the welds at planting): CVODE restarts from it.
  void SetState(const State& state);

  // Integrates from the current time to t (> current time). On failure the
  // state is the last one CVODE reached and the status says why.
  IntegrationStatus AdvanceTo(double t);

  double time() const { return t_; }
  const State& state() const { return state_; }
  const Inputs& inputs() const { return inputs_; }
  const Model& model() const { return model_; }
  IntegratorStats stats() const;

  // Calls `observer` after every step CVODE accepts (none: nullptr). CVODE
  // then goes one step at a time up to the same stop time: the same steps as
  // without an observer, so the results are bit-identical, only slower.
  void SetStepObserver(StepObserver observer);

 private:
  friend struct CvodeCallbacks;
  // y' = f(y) for y = (q, v); false when the accelerations are not finite
  bool EvaluateRightHandSide(const double* y, double* ydot);
  // the lower blocks of the right-hand side's Jacobian [[0, I], [da/dq, da/dv]];
  // false when they are not finite
  bool EvaluateJacobian(const double* y, Mat9* da_dq, Mat9* da_dv);
  void Restart();
  // the state, with locked coordinates at rest, into CVODE's vector
  void TakeState(const State& state);
  void CopyStateToVector();
  void CopyStateFromVector();

  Model model_;
  IntegratorSettings settings_;
  Inputs inputs_;
  Workspace workspace_;
  State state_;
  double t_ = 0;
  bool needs_restart_ = false;
  bool restarted_since_inputs_changed_ = true;  // a failure before a restart is retried once
  bool non_finite_ = false;
  std::string last_cvode_message_;
  IntegratorStats finished_;  // stats of CVODE runs before the last restart
  long rhs_evals_ = 0;

  struct Cvode;  // SUNDIALS handles
  std::unique_ptr<Cvode> cv_;

  // CVODE to the stop time t, in one call or, with a step observer, one step
  // at a time, within the step budget. Returns CVODE's flag.
  int RunCvode(double t, double* t_reached);
  struct StepProbe;  // the step observer and its vectors
  std::unique_ptr<StepProbe> probe_;
};

}  // namespace walkers
