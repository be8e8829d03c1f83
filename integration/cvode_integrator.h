// SUNDIALS CVODE (BDF, Newton iteration, a direct linear solver) on a
// SecondOrderSystem: the accurate integrator, its settings chosen by the
// accuracy criterion of docs/performance.md. Each CvodeIntegrator owns its
// SUNContext and CVODE memory and shares nothing, so many run at once on
// different threads.
#pragma once

#include <memory>
#include <string>

#include "integration/system.h"
#include "integration/time_stepper.h"

namespace walkers {

class CvodeIntegrator final : public TimeStepper {
 public:
  // `system` must outlive the integrator.
  CvodeIntegrator(SecondOrderSystem& system, const IntegratorSettings& settings);
  ~CvodeIntegrator() override;
  CvodeIntegrator(const CvodeIntegrator&) = delete;
  CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;

  void Reset(double t0, const SystemState& y0) override;
  // New inputs keep CVODE's history (or restart it, restart_at_ticks);
  // a switched weld restarts it. A failure right after a jump without a
  // restart is retried once from a restart at the last step CVODE accepted.
  void MarkJump(Jump jump) override;
  // CVODE restarts from the new state.
  void SetState(const SystemState& y) override;
  IntegrationStatus AdvanceTo(double t) override;

  double time() const override { return t_; }
  const SystemState& state() const override { return state_; }
  IntegratorStats stats() const override;

  // CVODE then goes one step at a time up to the same stop time: the same
  // steps as without an observer, so the results are bit-identical, only slower.
  void SetStepObserver(StepObserver observer) override;

 private:
  friend struct CvodeCallbacks;
  // y' = f(y) for y = (q, v); false when the accelerations are not finite
  bool EvaluateRightHandSide(const double* y, double* ydot);
  // the lower blocks of the right-hand side's Jacobian [[0, I], [da/dq, da/dv]];
  // false when they are not finite
  bool EvaluateJacobian(const double* y, Mat9* da_dq, Mat9* da_dv);
  void Restart();
  // the state, with locked coordinates at rest, into CVODE's vector
  void TakeState(const SystemState& state);
  void CopyStateToVector();
  void CopyStateFromVector();

  SecondOrderSystem& system_;
  IntegratorSettings settings_;
  SystemState state_;
  double t_ = 0;
  bool needs_restart_ = false;
  bool restarted_since_inputs_changed_ = true;  // a failure before a restart is retried once
  bool non_finite_ = false;
  std::string last_cvode_message_;
  IntegratorStats finished_;  // stats of CVODE runs before the last restart
  long rhs_evals_ = 0;
  long switches_located_ = 0;

  struct Cvode;  // SUNDIALS handles
  std::unique_ptr<Cvode> cv_;

  // CVODE to the stop time t, in one call or, with a step observer, one step
  // at a time, within the step budget, restarting at every switch it
  // locates. Returns CVODE's flag.
  int RunCvode(double t, double* t_reached);
  // the same up to the stop time or the first located switch (CV_ROOT_RETURN,
  // the state at the switch)
  int RunCvodeToRoot(double t, double* t_reached);
  struct StepProbe;  // the step observer and its vectors
  std::unique_ptr<StepProbe> probe_;
};

}  // namespace walkers
