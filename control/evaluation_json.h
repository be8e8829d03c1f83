// One evaluation as a JSON object: what `walkers evaluate --json` prints and
// what the Python module's evaluate returns (python/, docs/python.md), so the
// two name the same fields with the same values.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include "control/accuracy.h"
#include "control/evaluation.h"

namespace walkers {

// The result's fields, its outcome spelt as "fell", "cut_off" and "failure"
// (a failure's reason, null otherwise), its integrator's steps and
// right-hand sides as "cvode_steps" and "rhs_evals", and, when `ensemble` is
// given, an "ensemble" object of its size, fitnesses, their median, minimum
// and maximum, and its gait classes and falls.
nlohmann::json EvaluationToJson(const EvaluationResult& result, const FitnessEnsemble* ensemble = nullptr);

}  // namespace walkers
