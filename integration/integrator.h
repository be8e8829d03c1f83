// The walker's integrator: the walker as a system (integration/walker_system.h)
// advanced by the method its settings name, CVODE (the accurate one) or
// RK-Merson (the authors' numerics, on purpose). The caller says what
// changes between calls, and so marks each jump: new joint torques, welds
// switched, a projected state.
#pragma once

#include <memory>

#include "dynamics/coords.h"
#include "dynamics/equations_of_motion.h"
#include "dynamics/model.h"
#include "integration/time_stepper.h"
#include "integration/walker_system.h"

namespace walkers {

// "cvode", "rk-merson"
const char* IntegrationMethodName(IntegrationMethod method);
// The method of that name; false if there is none.
bool ParseIntegrationMethod(const std::string& name, IntegrationMethod* method);

class Integrator {
 public:
  explicit Integrator(const Model& model, const IntegratorSettings& settings = {});
  ~Integrator();
  Integrator(const Integrator&) = delete;
  Integrator& operator=(const Integrator&) = delete;

  // Starts a new trajectory at (t0, state) holding `inputs`; clears the stats
  // and RK-Merson's dissipated energy.
  void Reset(double t0, const State& state, const Inputs& inputs = {});

  // New joint torques from the current time on (a jump of the right-hand side).
  void SetTorques(const Vec9& joint_torque);
  // Welds switched on or off from the current time on.
  void SetWelds(const Welds& welds);
  // Replaces the state at the current time (a projection onto the welds at planting).
  void SetState(const State& state);

  // Integrates from the current time to t (> current time), never past it.
  // On failure the state is the last one reached and the status says why.
  IntegrationStatus AdvanceTo(double t);

  double time() const { return stepper_->time(); }
  const State& state() const { return stepper_->state(); }
  const Inputs& inputs() const { return system_.inputs(); }
  const Model& model() const { return system_.model(); }
  const IntegratorSettings& settings() const { return settings_; }
  IntegratorStats stats() const { return stepper_->stats(); }

  // Calls `observer` after every step the method accepts (none: nullptr),
  // with the inputs held during it; the results stay bit-identical.
  void SetStepObserver(StepObserver observer);

 private:
  IntegratorSettings settings_;
  WalkerSystem system_;
  std::unique_ptr<TimeStepper> stepper_;
};

}  // namespace walkers
