// Accuracy is not traded for speed (docs/performance.md): on a subset of the
// benchmark genomes, the production settings' fitness agrees with the same
// evaluation at 100x tighter tolerances, and the gait class and fall verdict
// agree.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "control/evaluation.h"

namespace walkers {
namespace {

std::string BenchGenome(const std::string& name) {
  return std::string(WALKERS_SOURCE_DIR) + "/data/genomes/bench/" + name + ".json";
}

TEST(AccuracyTest, ProductionSettingsAgreeWithHundredTimesTighterTolerances) {
  EvaluationSettings production, tight;
  tight.integrator.relative_tolerance /= 100.0;
  tight.integrator.absolute_tolerance_position /= 100.0;
  tight.integrator.absolute_tolerance_velocity /= 100.0;
  std::vector<double> differences;
  for (const char* name : {"performance_best_biped", "short_trunk_biped", "time_mid_biped", "evolved_faller"}) {
    const Genome g = LoadGenome(BenchGenome(name));
    const EvaluationResult a = Evaluate(g, OriginalPreset(), production);
    const EvaluationResult b = Evaluate(g, OriginalPreset(), tight);
    EXPECT_EQ(a.gait, b.gait) << name;
    EXPECT_EQ(a.fell, b.fell) << name;
    differences.push_back(std::abs(a.fitness - b.fitness) / std::max(1.0, std::abs(b.fitness)));
  }
  std::sort(differences.begin(), differences.end());
  const double median = 0.5 * (differences[1] + differences[2]);
  EXPECT_LT(median, 0.01) << "median relative fitness difference";
}

}  // namespace
}  // namespace walkers
