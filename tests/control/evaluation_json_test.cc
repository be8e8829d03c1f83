// The JSON of one evaluation (what `walkers evaluate --json` prints and the
// Python module returns): every field of the result, "failure" null or the
// reason, the ensemble's summary only when there is an ensemble.
#include "control/evaluation_json.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace walkers {
namespace {

EvaluationResult SomeResult() {
  EvaluationResult r;
  r.fitness = 3.25;
  r.distance = 4.0;
  r.leg_length = 1.23;
  r.footsteps = 7;
  r.trunk_contact_fraction = 0.125;
  r.gait = Gait::kTripod;
  r.sim_time = 15.0;
  r.wall_ms = 99.5;
  r.integrator_stats.steps = 12345;
  r.integrator_stats.rhs_evals = 23456;
  r.preset = "paper";
  return r;
}

TEST(EvaluationJsonTest, HoldsEveryFieldOfTheResult) {
  const nlohmann::json j = EvaluationToJson(SomeResult());
  EXPECT_EQ(j.size(), 15u);
  EXPECT_EQ(j.at("fitness").get<double>(), 3.25);
  EXPECT_EQ(j.at("distance").get<double>(), 4.0);
  EXPECT_EQ(j.at("leg_length").get<double>(), 1.23);
  EXPECT_FALSE(j.at("fell").get<bool>());
  EXPECT_TRUE(j.at("failure").is_null());
  EXPECT_EQ(j.at("footsteps").get<int>(), 7);
  EXPECT_EQ(j.at("trunk_contact_fraction").get<double>(), 0.125);
  EXPECT_EQ(j.at("gait").get<std::string>(), "tripod");
  EXPECT_EQ(j.at("sim_time").get<double>(), 15.0);
  EXPECT_EQ(j.at("wall_ms").get<double>(), 99.5);
  EXPECT_EQ(j.at("cvode_steps").get<long>(), 12345);
  EXPECT_EQ(j.at("rhs_evals").get<long>(), 23456);
  EXPECT_EQ(j.at("preset").get<std::string>(), "paper");
  EXPECT_EQ(j.at("integrator").get<std::string>(), "cvode");
  EXPECT_FALSE(j.at("cut_off").get<bool>());
  EXPECT_FALSE(j.contains("ensemble"));
}

TEST(EvaluationJsonTest, NamesTheIntegrator) {
  EvaluationResult r = SomeResult();
  r.integrator = IntegrationMethod::kRkMerson;
  EXPECT_EQ(EvaluationToJson(r).at("integrator").get<std::string>(), "rk-merson");
}

// The outcome is spelt by three fields: "fell", "cut_off", and "failure" with
// a failure's reason (null otherwise).
TEST(EvaluationJsonTest, SpellsEachOutcome) {
  struct Case {
    Outcome outcome;
    bool fell, cut_off, failed;
  };
  for (const Case& c : {Case{Outcome::kWalked, false, false, false}, Case{Outcome::kFell, true, false, false},
                        Case{Outcome::kFailed, false, false, true}, Case{Outcome::kCutOff, false, true, false}}) {
    SCOPED_TRACE(static_cast<int>(c.outcome));
    EvaluationResult r = SomeResult();
    r.outcome = c.outcome;
    if (c.failed) r.reason = "CVODE: too much work";
    const nlohmann::json j = EvaluationToJson(r);
    EXPECT_EQ(j.at("fell").get<bool>(), c.fell);
    EXPECT_EQ(j.at("cut_off").get<bool>(), c.cut_off);
    if (c.failed) {
      EXPECT_EQ(j.at("failure").get<std::string>(), "CVODE: too much work");
    } else {
      EXPECT_TRUE(j.at("failure").is_null());
    }
  }
}

TEST(EvaluationJsonTest, SummarisesTheEnsemble) {
  FitnessEnsemble e;
  e.fitness = {2.0, -1.0, 5.0, 4.0};
  e.bipeds = 2;
  e.tripods = 1;
  e.falls = 1;
  const nlohmann::json j = EvaluationToJson(SomeResult(), &e).at("ensemble");
  EXPECT_EQ(j.at("size").get<int>(), 4);
  EXPECT_EQ(j.at("fitness").get<std::vector<double>>(), e.fitness);
  EXPECT_EQ(j.at("fitness_median").get<double>(), 3.0);
  EXPECT_EQ(j.at("fitness_min").get<double>(), -1.0);
  EXPECT_EQ(j.at("fitness_max").get<double>(), 5.0);
  EXPECT_EQ(j.at("bipeds").get<int>(), 2);
  EXPECT_EQ(j.at("tripods").get<int>(), 1);
  EXPECT_EQ(j.at("falls").get<int>(), 1);
}

}  // namespace
}  // namespace walkers
