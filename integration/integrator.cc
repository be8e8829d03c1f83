#include "integration/integrator.h"

#include <utility>

#include "integration/cvode_integrator.h"
#include "integration/rk_merson.h"

namespace walkers {

const char* IntegrationMethodName(IntegrationMethod method) {
  return method == IntegrationMethod::kRkMerson ? "rk-merson" : "cvode";
}

bool ParseIntegrationMethod(const std::string& name, IntegrationMethod* method) {
  for (const IntegrationMethod m : {IntegrationMethod::kCvode, IntegrationMethod::kRkMerson}) {
    if (name == IntegrationMethodName(m)) {
      *method = m;
      return true;
    }
  }
  return false;
}

Integrator::Integrator(const Model& model, const IntegratorSettings& settings)
    : settings_(settings), system_(model) {
  if (settings.method == IntegrationMethod::kRkMerson) {
    stepper_ = std::make_unique<RungeKuttaMerson>(system_, settings);
  } else {
    stepper_ = std::make_unique<CvodeIntegrator>(system_, settings);
  }
}

Integrator::~Integrator() = default;

void Integrator::Reset(double t0, const State& state, const Inputs& inputs) {
  system_.SetInputs(inputs);
  SystemState y;
  static_cast<State&>(y) = state;
  stepper_->Reset(t0, y);
}

void Integrator::SetTorques(const Vec9& joint_torque) {
  system_.inputs().joint_torque = joint_torque;
  stepper_->MarkJump(Jump::kInputs);
}

void Integrator::SetWelds(const Welds& welds) {
  system_.inputs().welds = welds;
  stepper_->MarkJump(Jump::kConstraints);
}

void Integrator::SetState(const State& state) {
  SystemState y = stepper_->state();  // keeps the dissipated energy
  static_cast<State&>(y) = state;
  stepper_->SetState(y);
}

IntegrationStatus Integrator::AdvanceTo(double t) { return stepper_->AdvanceTo(t); }

void Integrator::SetStepObserver(StepObserver observer) {
  if (!observer) {
    stepper_->SetStepObserver(nullptr);
    return;
  }
  stepper_->SetStepObserver([this, observer = std::move(observer)](const StepInfo& step) {
    StepInfo with_inputs = step;
    with_inputs.inputs = &system_.inputs();
    observer(with_inputs);
  });
}

}  // namespace walkers
