// Numerical variants compared in docs/performance.md: each changes one choice
// of the production settings (EvaluationSettings' defaults).
#pragma once

#include <string>
#include <vector>

#include "control/evaluation.h"

namespace walkers::bench {

struct Variant {
  std::string name;
  EvaluationSettings settings;
};

inline std::vector<Variant> Variants() {
  std::vector<Variant> v;
  auto add = [&v](const std::string& name, auto change) {
    EvaluationSettings s;
    change(&s);
    v.push_back({name, s});
  };
  add("production", [](EvaluationSettings*) {});
  add("library_vector_ops", [](EvaluationSettings* s) { s->integrator.fixed_size_ops = false; });
  add("adams", [](EvaluationSettings* s) { s->integrator.multistep = MultistepMethod::kAdams; });
  add("adams_tolerances_3e-8", [](EvaluationSettings* s) {
    s->integrator.multistep = MultistepMethod::kAdams;
    s->integrator.relative_tolerance = s->integrator.absolute_tolerance_position = 3e-8;
    s->integrator.absolute_tolerance_velocity = 3e-6;
  });
  add("max_order_2", [](EvaluationSettings* s) { s->integrator.max_order = 2; });
  add("max_order_3", [](EvaluationSettings* s) { s->integrator.max_order = 3; });
  add("stability_limit_detection", [](EvaluationSettings* s) { s->integrator.stability_limit_detection = true; });
  add("newton_gamma_change_0.15", [](EvaluationSettings* s) { s->integrator.newton_matrix_gamma_change = 0.15; });
  add("newton_gamma_change_1.5", [](EvaluationSettings* s) { s->integrator.newton_matrix_gamma_change = 1.5; });
  add("max_order_3_newton_gamma_change_0.15", [](EvaluationSettings* s) {
    s->integrator.max_order = 3;
    s->integrator.newton_matrix_gamma_change = 0.15;
  });
  add("newton_matrix_age_50", [](EvaluationSettings* s) { s->integrator.newton_matrix_max_age = 50; });
  add("newton_matrix_age_10", [](EvaluationSettings* s) { s->integrator.newton_matrix_max_age = 10; });
  add("finite_difference_jacobian", [](EvaluationSettings* s) {
    s->integrator.jacobian = JacobianSource::kFiniteDifference;
    s->integrator.linear_solver = LinearSolver::kSchurComplement;  // CVODE's quotients fill dense matrices only
  });
  add("dense_newton_matrix",
      [](EvaluationSettings* s) { s->integrator.linear_solver = LinearSolver::kSchurComplement; });
  add("dense_linear_solver", [](EvaluationSettings* s) { s->integrator.linear_solver = LinearSolver::kDense; });
  add("restart_every_tick", [](EvaluationSettings* s) { s->integrator.restart_at_ticks = true; });
  add("restart_every_tick_with_last_step", [](EvaluationSettings* s) {
    s->integrator.restart_at_ticks = true;
    s->integrator.restart_with_last_step = true;
  });
  add("contact_events", [](EvaluationSettings* s) { s->integrator.locate_contact_switches = true; });
  add("contact_events_restart_every_tick", [](EvaluationSettings* s) {
    s->integrator.locate_contact_switches = true;
    s->integrator.restart_at_ticks = true;
  });
  add("velocity_atol_3e-6", [](EvaluationSettings* s) { s->integrator.absolute_tolerance_velocity = 3e-6; });
  add("velocity_atol_3e-6_restart_every_tick", [](EvaluationSettings* s) {
    s->integrator.absolute_tolerance_velocity = 3e-6;
    s->integrator.restart_at_ticks = true;
  });
  add("velocity_atol_1e-3", [](EvaluationSettings* s) { s->integrator.absolute_tolerance_velocity = 1e-3; });
  add("velocity_atol_1e-2", [](EvaluationSettings* s) { s->integrator.absolute_tolerance_velocity = 1e-2; });
  add("tolerances_1e-5", [](EvaluationSettings* s) {
    s->integrator.relative_tolerance = s->integrator.absolute_tolerance_position = 1e-5;
  });
  add("tolerances_1e-7", [](EvaluationSettings* s) {
    s->integrator.relative_tolerance = s->integrator.absolute_tolerance_position = 1e-7;
  });
  add("friction_transition_0.01", [](EvaluationSettings* s) { s->contact.transition_velocity = 0.01; });
  add("weld_stabilization_30", [](EvaluationSettings* s) { s->weld.stabilization = 30.0; });
  return v;
}

}  // namespace walkers::bench
