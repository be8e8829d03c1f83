#include "integration/cvode_integrator.h"

#include "files/errors.h"
#include "integration/block_matrix18.h"
#include "integration/fixed_size_ops.h"
#include "integration/schur_linear_solver.h"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace walkers {

constexpr int kStateSize = 2 * kNumCoords;  // y = (q, v)
static_assert(kStateSize == kFixedVectorLength);

struct CvodeIntegrator::Cvode {
  SUNContext context = nullptr;
  N_Vector y = nullptr;
  N_Vector abs_tol = nullptr;
  SUNMatrix jacobian = nullptr;
  SUNLinearSolver linear_solver = nullptr;
  void* mem = nullptr;

  ~Cvode() {
    if (mem) CVodeFree(&mem);
    if (linear_solver) SUNLinSolFree(linear_solver);
    if (jacobian) SUNMatDestroy(jacobian);
    if (abs_tol) N_VDestroy(abs_tol);
    if (y) N_VDestroy(y);
    if (context) SUNContext_Free(&context);
  }
};

struct CvodeIntegrator::StepProbe {
  StepObserver observer;
  N_Vector weights = nullptr;  // CVODE's error weights
  N_Vector errors = nullptr;   // its estimated local errors

  ~StepProbe() {
    if (errors) N_VDestroy(errors);
    if (weights) N_VDestroy(weights);
  }
};

// C entry points CVODE calls back into
struct CvodeCallbacks {
  static int RightHandSide(sunrealtype /*t*/, N_Vector y, N_Vector ydot, void* self) {
    // a non-finite result is unrecoverable: CVODE stops with CV_RHSFUNC_FAIL
    return static_cast<CvodeIntegrator*>(self)->EvaluateRightHandSide(N_VGetArrayPointer(y), N_VGetArrayPointer(ydot))
               ? 0
               : -1;
  }
  // d(q, v)'/d(q, v) = [[0, I], [da/dq, da/dv]] into the block or dense matrix
  static int Jacobian(sunrealtype /*t*/, N_Vector y, N_Vector /*fy*/, SUNMatrix jacobian, void* self,
                      N_Vector /*tmp1*/, N_Vector /*tmp2*/, N_Vector /*tmp3*/) {
    Mat9 da_dq, da_dv;
    if (!static_cast<CvodeIntegrator*>(self)->EvaluateJacobian(N_VGetArrayPointer(y), &da_dq, &da_dv)) return -1;
    return StoreWalkerJacobian(da_dq, da_dv, jacobian) ? 0 : -1;
  }
  // the system's switch functions, whose zeros CVODE's root finding locates
  static int Switches(sunrealtype /*t*/, N_Vector y, sunrealtype* g, void* self) {
    const double* state = N_VGetArrayPointer(y);
    static_cast<CvodeIntegrator*>(self)->system_.SwitchFunctions(Eigen::Map<const Vec9>(state),
                                                                 Eigen::Map<const Vec9>(state + kNumCoords), g);
    return 0;
  }
  static void ErrorHandler(int /*code*/, const char* /*module*/, const char* /*function*/, char* message,
                           void* self) {
    // keep CVODE quiet: the message travels back to the caller in the status
    static_cast<CvodeIntegrator*>(self)->last_cvode_message_ = message ? message : "";
  }
};

namespace {

void Check(int flag, const char* call) {
  if (flag < 0) throw std::runtime_error(std::string("CVODE setup failed in ") + call);
}

}  // namespace

CvodeIntegrator::CvodeIntegrator(SecondOrderSystem& system, const IntegratorSettings& settings)
    : system_(system), settings_(settings), cv_(std::make_unique<Cvode>()) {
  Check(SUNContext_Create(nullptr, &cv_->context), "SUNContext_Create");
  cv_->y = N_VNew_Serial(kStateSize, cv_->context);
  cv_->abs_tol = N_VNew_Serial(kStateSize, cv_->context);
  if (!cv_->y || !cv_->abs_tol) throw std::runtime_error("CVODE setup failed: N_VNew_Serial");
  // before CVodeInit and CVodeSVtolerances, which clone these two
  if (settings.fixed_size_ops && !(UseFixedSizeVectorOps(cv_->y) && UseFixedSizeVectorOps(cv_->abs_tol))) {
    throw std::runtime_error("CVODE setup failed: fixed-size vector operations");
  }
  N_VConst(0.0, cv_->y);

  const int lmm = settings.multistep == MultistepMethod::kBdf ? CV_BDF : CV_ADAMS;
  cv_->mem = CVodeCreate(lmm, cv_->context);
  if (!cv_->mem) throw std::runtime_error("CVODE setup failed: CVodeCreate");
  Check(CVodeInit(cv_->mem, &CvodeCallbacks::RightHandSide, 0.0, cv_->y), "CVodeInit");
  Check(CVodeSetUserData(cv_->mem, this), "CVodeSetUserData");
  Check(CVodeSetErrHandlerFn(cv_->mem, &CvodeCallbacks::ErrorHandler, this), "CVodeSetErrHandlerFn");

  // per-component absolute tolerances: positions, then velocities
  double* atol = N_VGetArrayPointer(cv_->abs_tol);
  for (int i = 0; i < kNumCoords; ++i) {
    atol[i] = settings.absolute_tolerance_position;
    atol[kNumCoords + i] = settings.absolute_tolerance_velocity;
  }
  Check(CVodeSVtolerances(cv_->mem, settings.relative_tolerance, cv_->abs_tol), "CVodeSVtolerances");
  Check(CVodeSetMaxOrd(cv_->mem, settings.max_order), "CVodeSetMaxOrd");
  Check(CVodeSetStabLimDet(cv_->mem, settings.stability_limit_detection ? SUNTRUE : SUNFALSE),
        "CVodeSetStabLimDet");
  Check(CVodeSetDeltaGammaMaxLSetup(cv_->mem, settings.newton_matrix_gamma_change), "CVodeSetDeltaGammaMaxLSetup");
  Check(CVodeSetLSetupFrequency(cv_->mem, settings.newton_matrix_max_age), "CVodeSetLSetupFrequency");

  // Newton iteration (CVODE's default) with a direct solver on a block or a
  // dense matrix
  if (settings.linear_solver == LinearSolver::kSchurBlocks) {
    // CVODE's difference quotients fill dense or band matrices only
    WALKERS_CHECK(settings.jacobian == JacobianSource::kAnalytic,
                  "IntegratorSettings: the block Newton matrix needs the analytic Jacobian");
    cv_->jacobian = MakeBlockMatrix18(cv_->context);
  } else {
    cv_->jacobian = SUNDenseMatrix(kStateSize, kStateSize, cv_->context);
    // before CVodeSetLinearSolver, which clones it for the saved Jacobian
    if (cv_->jacobian && settings.fixed_size_ops && !UseFixedSizeMatrixOps(cv_->jacobian)) {
      throw std::runtime_error("CVODE setup failed: fixed-size matrix operations");
    }
  }
  if (cv_->jacobian) {
    cv_->linear_solver = settings.linear_solver == LinearSolver::kDense
                             ? SUNLinSol_Dense(cv_->y, cv_->jacobian, cv_->context)
                             : MakeSchurLinearSolver(cv_->y, cv_->jacobian, cv_->context);
  }
  if (!cv_->jacobian || !cv_->linear_solver) throw std::runtime_error("CVODE setup failed: Newton matrix or linear solver");
  Check(CVodeSetLinearSolver(cv_->mem, cv_->linear_solver, cv_->jacobian), "CVodeSetLinearSolver");
  if (settings.jacobian == JacobianSource::kAnalytic) {
    Check(CVodeSetJacFn(cv_->mem, &CvodeCallbacks::Jacobian), "CVodeSetJacFn");
  }

  // root finding on the switch functions (kept across CVodeReInit); a
  // function that is zero at a restart is not reported there
  if (settings.locate_contact_switches && system.NumSwitchFunctions() > 0) {
    Check(CVodeRootInit(cv_->mem, system.NumSwitchFunctions(), &CvodeCallbacks::Switches), "CVodeRootInit");
    Check(CVodeSetNoInactiveRootWarn(cv_->mem), "CVodeSetNoInactiveRootWarn");
  }
}

CvodeIntegrator::~CvodeIntegrator() = default;

void CvodeIntegrator::Reset(double t0, const SystemState& state) {
  t_ = t0;
  TakeState(state);
  Check(CVodeReInit(cv_->mem, t0, cv_->y), "CVodeReInit");
  finished_ = IntegratorStats{};
  rhs_evals_ = 0;
  switches_located_ = 0;
  needs_restart_ = false;
  non_finite_ = false;
}

void CvodeIntegrator::SetState(const SystemState& state) {
  TakeState(state);
  needs_restart_ = true;
}

void CvodeIntegrator::TakeState(const SystemState& state) {
  state_ = state;
  for (int i = 0; i < kNumCoords; ++i) {
    if (system_.Locked(i)) state_.v(i) = 0.0;
  }
  CopyStateToVector();
}

void CvodeIntegrator::MarkJump(Jump jump) {
  if (jump == Jump::kConstraints || settings_.restart_at_ticks) needs_restart_ = true;
  restarted_since_inputs_changed_ = false;
}

void CvodeIntegrator::Restart() {
  // CVodeReInit clears CVODE's counters: keep what they held
  const IntegratorStats s = stats();
  finished_ = s;
  finished_.restarts = s.restarts + 1;
  double last_step = 0.0;
  if (settings_.restart_with_last_step && s.steps > 0) CVodeGetLastStep(cv_->mem, &last_step);
  Check(CVodeReInit(cv_->mem, t_, cv_->y), "CVodeReInit");
  // 0 lets CVODE estimate the first step
  Check(CVodeSetInitStep(cv_->mem, last_step), "CVodeSetInitStep");
  needs_restart_ = false;
  restarted_since_inputs_changed_ = true;
}

IntegratorStats CvodeIntegrator::stats() const {
  IntegratorStats s = finished_;
  long n = 0;
  CVodeGetNumSteps(cv_->mem, &n);
  s.steps += n;
  CVodeGetNumJacEvals(cv_->mem, &n);
  s.jacobian_evals += n;
  CVodeGetNumErrTestFails(cv_->mem, &n);
  s.error_test_failures += n;
  CVodeGetNumNonlinSolvConvFails(cv_->mem, &n);
  s.nonlinear_failures += n;
  s.rhs_evals = rhs_evals_;
  s.switches_located = switches_located_;
  return s;
}

IntegrationStatus CvodeIntegrator::AdvanceTo(double t) {
  IntegrationStatus status;
  if (!(t > t_)) return status;

  if (needs_restart_) Restart();

  const IntegratorStats before = stats();
  const long remaining = settings_.step_budget - before.steps;
  if (remaining <= 0) {
    status.failure = IntegrationFailure::kStepBudget;
    status.reason = "step budget of " + std::to_string(settings_.step_budget) + " steps exhausted at t=" +
                    std::to_string(t_);
    return status;
  }
  CVodeSetMaxNumSteps(cv_->mem, remaining);
  // never step past t: the caller may change the inputs there
  CVodeSetStopTime(cv_->mem, t);

  double t_reached = t_;
  int flag = RunCvode(t, &t_reached);
  t_ = t_reached;
  CopyStateFromVector();

  // CVODE failed after the held inputs jumped without a restart: its history
  // still described the old right-hand side. Restart where it stopped (the
  // last step it accepted) and try once more.
  const bool recoverable = flag == CV_ERR_FAILURE || flag == CV_CONV_FAILURE;
  if (recoverable && !restarted_since_inputs_changed_ && state_.q.allFinite() && state_.v.allFinite()) {
    last_cvode_message_.clear();
    Restart();
    CVodeSetMaxNumSteps(cv_->mem, std::max(1L, settings_.step_budget - stats().steps));
    CVodeSetStopTime(cv_->mem, t);
    flag = RunCvode(t, &t_reached);
    t_ = t_reached;
    CopyStateFromVector();
  }

  if (flag >= 0 && state_.q.allFinite() && state_.v.allFinite()) return status;

  if (non_finite_ || !state_.q.allFinite() || !state_.v.allFinite()) {
    status.failure = IntegrationFailure::kNonFinite;
    status.reason = "non-finite accelerations at t=" + std::to_string(t_);
  } else if (flag == CV_TOO_MUCH_WORK) {
    status.failure = IntegrationFailure::kStepBudget;
    status.reason = "step budget of " + std::to_string(settings_.step_budget) + " steps exhausted at t=" +
                    std::to_string(t_);
  } else {
    status.failure = IntegrationFailure::kSolver;
    status.reason = std::string(CVodeGetReturnFlagName(flag)) + " at t=" + std::to_string(t_);
    if (!last_cvode_message_.empty()) status.reason += ": " + last_cvode_message_;
  }
  return status;
}

void CvodeIntegrator::SetStepObserver(StepObserver observer) {
  if (!observer) {
    probe_.reset();
    return;
  }
  if (!probe_) {
    probe_ = std::make_unique<StepProbe>();
    probe_->weights = N_VClone(cv_->y);
    probe_->errors = N_VClone(cv_->y);
    if (!probe_->weights || !probe_->errors) throw std::runtime_error("CVODE setup failed: N_VClone");
  }
  probe_->observer = std::move(observer);
}

int CvodeIntegrator::RunCvode(double t, double* t_reached) {
  for (;;) {
    const int flag = RunCvodeToRoot(t, t_reached);
    if (flag != CV_ROOT_RETURN) return flag;
    // a switch located (locate_contact_switches): restart CVODE at it, so
    // that its history starts on the switch's far side, and carry on to t
    ++switches_located_;
    t_ = *t_reached;
    CopyStateFromVector();
    Restart();
    if (!(*t_reached < t)) return CV_SUCCESS;
    const long remaining = settings_.step_budget - stats().steps;
    if (remaining <= 0) return CV_TOO_MUCH_WORK;
    CVodeSetMaxNumSteps(cv_->mem, remaining);
    CVodeSetStopTime(cv_->mem, t);
  }
}

int CvodeIntegrator::RunCvodeToRoot(double t, double* t_reached) {
  if (!probe_) return CVode(cv_->mem, t, cv_->y, t_reached, CV_NORMAL);

  // CV_ONE_STEP under the stop time t takes the steps CV_NORMAL takes (the
  // stop time, not tout, ends both) and hands back the same state at t; the
  // step budget that CVodeSetMaxNumSteps gives CV_NORMAL is counted here
  const long max_steps = std::max(1L, settings_.step_budget - stats().steps);
  for (long taken = 0; taken < max_steps; ++taken) {
    long error_tests_before = 0, nonlinear_before = 0;
    CVodeGetNumErrTestFails(cv_->mem, &error_tests_before);
    CVodeGetNumNonlinSolvConvFails(cv_->mem, &nonlinear_before);
    const int flag = CVode(cv_->mem, t, cv_->y, t_reached, CV_ONE_STEP);
    if (flag < 0) return flag;

    StepInfo info;
    info.t = *t_reached;
    CVodeGetLastStep(cv_->mem, &info.step);
    CVodeGetLastOrder(cv_->mem, &info.order);
    CVodeGetNumErrTestFails(cv_->mem, &info.error_test_failures);
    CVodeGetNumNonlinSolvConvFails(cv_->mem, &info.nonlinear_failures);
    info.error_test_failures -= error_tests_before;
    info.nonlinear_failures -= nonlinear_before;
    CVodeGetErrWeights(cv_->mem, probe_->weights);
    CVodeGetEstLocalErrors(cv_->mem, probe_->errors);
    const double* w = N_VGetArrayPointer(probe_->weights);
    const double* e = N_VGetArrayPointer(probe_->errors);
    for (int i = 0; i < kStateSize; ++i) info.weighted_error(i) = std::abs(e[i] * w[i]);
    t_ = *t_reached;
    CopyStateFromVector();
    info.state = &state_;
    probe_->observer(info);

    if (flag == CV_ROOT_RETURN) return flag;
    if (flag == CV_TSTOP_RETURN || !(*t_reached < t)) return CV_SUCCESS;
  }
  return CV_TOO_MUCH_WORK;
}

void CvodeIntegrator::CopyStateToVector() {
  double* y = N_VGetArrayPointer(cv_->y);
  Eigen::Map<Vec9> q(y), v(y + kNumCoords);
  q = state_.q;
  v = state_.v;
}

void CvodeIntegrator::CopyStateFromVector() {
  const double* y = N_VGetArrayPointer(cv_->y);
  state_.q = Eigen::Map<const Vec9>(y);
  state_.v = Eigen::Map<const Vec9>(y + kNumCoords);
}

bool CvodeIntegrator::EvaluateRightHandSide(const double* y, double* ydot) {
  ++rhs_evals_;
  const Eigen::Map<const Vec9> q(y), v(y + kNumCoords);
  Eigen::Map<Vec9> qd(ydot), vd(ydot + kNumCoords);
  Vec9 qdd;
  if (!system_.Accelerations(q, v, &qdd)) {
    non_finite_ = true;
    return false;
  }
  qd = v;
  vd = qdd;
  return true;
}

bool CvodeIntegrator::EvaluateJacobian(const double* y, Mat9* da_dq, Mat9* da_dv) {
  const Eigen::Map<const Vec9> q(y), v(y + kNumCoords);
  if (!system_.AccelerationJacobian(q, v, da_dq, da_dv)) {
    non_finite_ = true;
    return false;
  }
  return true;
}

}  // namespace walkers
