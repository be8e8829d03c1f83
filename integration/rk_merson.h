// Simbody's Runge-Kutta-Merson integrator (SimTKmath's
// RungeKuttaMersonIntegrator on AbstractIntegratorRep, Simbody 3.6-3.7) at
// the settings of the authors' program: it reproduces their numerics on
// purpose, loose steps included, and is judged by how well it agrees with
// their program as they ran it, never by the accuracy criterion
// (docs/model.md, "RK-Merson"; docs/fidelity.md).
//
// Per step from (t0, y0) with f0 = f(y0), four stages and the fourth-order
// solution y1 = y0 + h/6 (f0 + 4 f3 + f4); the error estimate is
// 0.2 |y1 - y_check| with y_check = y0 + h/2 (f0 - 3 f2 + 4 f3), measured and
// normed by the system (Simbody's coordinates), projected with y1 onto the
// constraints. A step is accepted if and only if its error norm E is within
// the accuracy; the next step is 0.9 h (accuracy / E)^(1/4) within
// [0.1 h, 5 h], kept when that is less than 1.2 h or the step was cut short
// by a stop time, and kept after any accepted step that would shrink it.
// Steps end exactly at the stop times; a jump neither restarts nor resizes.
#pragma once

#include "integration/system.h"
#include "integration/time_stepper.h"

namespace walkers {

class RungeKuttaMerson final : public TimeStepper {
 public:
  // Simbody's first step: its default time scale (0.1 s) over 10
  static constexpr double kInitialStep = 0.01;  // [s]
  static constexpr int kErrorOrder = 4;

  // `system` must outlive the integrator.
  RungeKuttaMerson(SecondOrderSystem& system, const IntegratorSettings& settings);

  void Reset(double t0, const SystemState& y0) override;
  // Nothing to do: every step starts from the derivatives at its start
  // under what the system holds then, and the step size carries over.
  void MarkJump(Jump /*jump*/) override {}
  void SetState(const SystemState& y) override;
  IntegrationStatus AdvanceTo(double t) override;

  double time() const override { return t_; }
  const SystemState& state() const override { return y_; }
  IntegratorStats stats() const override { return stats_; }
  void SetStepObserver(StepObserver observer) override { observer_ = std::move(observer); }

  // Simbody's step size control (AbstractIntegratorRep::adjustStepSize):
  // from the current step h, the error norm E of the attempt (not finite: a
  // failed attempt), the accuracy and whether the attempt was cut short by a
  // stop time, the next step size; the attempt is accepted if and only if
  // that is not below h.
  struct StepDecision {
    double next_step = 0;
    bool accepted = false;
  };
  static StepDecision AdjustStepSize(double h, double error_norm, double accuracy, bool cut_short);

 private:
  // y + c (f) for the derivative f = (v, a, z')
  struct Derivative {
    Vec9 qd = Vec9::Zero();
    Vec9 vd = Vec9::Zero();
    double zd = 0;
  };
  bool Evaluate(const SystemState& y, Derivative* f);
  // One attempt from (t0, y0, f0) over h to y1: its error norm (infinite
  // when a stage is not finite or a projection fails).
  double Attempt(const Derivative& f0, double h, SystemState* y1);

  SecondOrderSystem& system_;
  IntegratorSettings settings_;
  SystemState y_;
  double t_ = 0;
  double h_ = kInitialStep;
  IntegratorStats stats_;
  StepObserver observer_;
};

}  // namespace walkers
