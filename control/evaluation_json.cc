#include "control/evaluation_json.h"

#include <nlohmann/json.hpp>

namespace walkers {

nlohmann::json EvaluationToJson(const EvaluationResult& r, const FitnessEnsemble* ensemble) {
  nlohmann::json out = {{"fitness", r.fitness},
                        {"distance", r.distance},
                        {"leg_length", r.leg_length},
                        {"fell", r.outcome == Outcome::kFell},
                        {"cut_off", r.outcome == Outcome::kCutOff},
                        {"failure", nullptr},
                        {"footsteps", r.footsteps},
                        {"trunk_contact_fraction", r.trunk_contact_fraction},
                        {"gait", GaitName(r.gait)},
                        {"sim_time", r.sim_time},
                        {"wall_ms", r.wall_ms},
                        {"cvode_steps", r.integrator_stats.steps},
                        {"rhs_evals", r.integrator_stats.rhs_evals},
                        {"integrator", IntegrationMethodName(r.integrator)},
                        {"preset", r.preset}};
  if (r.outcome == Outcome::kFailed) out["failure"] = r.reason;
  if (ensemble) {
    const FitnessEnsemble& e = *ensemble;
    out["ensemble"] = {{"size", e.fitness.size()}, {"fitness", e.fitness},   {"fitness_median", e.Median()},
                       {"fitness_min", e.Min()},   {"fitness_max", e.Max()}, {"bipeds", e.bipeds},
                       {"tripods", e.tripods},     {"falls", e.falls}};
  }
  return out;
}

}  // namespace walkers
