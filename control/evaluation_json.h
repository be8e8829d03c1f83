// One evaluation as a JSON object: what `walkers evaluate --json` prints and
// what the Python module's evaluate returns (python/, docs/python.md), so the
// two name the same fields with the same values.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include "control/accuracy.h"
#include "control/evaluation.h"

namespace walkers {

// The result's fields ("failure" null when the integration did not fail),
// and, when `ensemble` is given, an "ensemble" object of its size, fitnesses,
// their median, minimum and maximum, and its gait classes and falls.
nlohmann::json EvaluationToJson(const EvaluationResult& result, const FitnessEnsemble* ensemble = nullptr);

}  // namespace walkers
