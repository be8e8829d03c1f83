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
  r.cvode_steps = 12345;
  r.rhs_evals = 23456;
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

TEST(EvaluationJsonTest, NamesTheIntegratorAndACutOff) {
  EvaluationResult r = SomeResult();
  r.integrator = IntegrationMethod::kRkMerson;
  r.cut_off = true;
  r.fitness = kCutOffFitness;
  const nlohmann::json j = EvaluationToJson(r);
  EXPECT_EQ(j.at("integrator").get<std::string>(), "rk-merson");
  EXPECT_TRUE(j.at("cut_off").get<bool>());
  EXPECT_EQ(j.at("fitness").get<double>(), -124.0);
}

TEST(EvaluationJsonTest, NamesAFailureAndAFall) {
  EvaluationResult r = SomeResult();
  r.fitness = -1;
  r.fell = true;
  r.gait = Gait::kNone;
  r.failure = "CVODE: too much work";
  const nlohmann::json j = EvaluationToJson(r);
  EXPECT_TRUE(j.at("fell").get<bool>());
  EXPECT_EQ(j.at("gait").get<std::string>(), "none");
  EXPECT_EQ(j.at("failure").get<std::string>(), "CVODE: too much work");
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
