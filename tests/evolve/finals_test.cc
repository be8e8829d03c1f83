#include "evolve/finals.h"

#include <atomic>
#include <filesystem>
#include <fstream>
#include <tuple>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "files/durable_file.h"
#include "files/input_file.h"
#include "files/number_text.h"
#include "tests/evolve/individuals.h"
#include "tests/temp_dir_test.h"

namespace walkers {
namespace {
namespace fs = std::filesystem;
using testing::WithFitness;

// a run of two children a generation over three generations
RunConfig SmallRun() {
  RunConfig c;
  c.generations = 3;
  c.ga.population = 2;
  c.ga.archive_size = 2;
  c.ga.mutation_children = 1;
  return c;
}

// one row of evaluations.csv: generation, child, fitness, fell, gait
using Row = std::tuple<int, int, double, bool, std::string>;

class FinalsTest : public TempDirTest {
 protected:
  // A hand-made run in DIR: its evaluations.csv (each row's genome is
  // WithFitness's, kx telling them apart) and its archive of `archive`.
  std::string Write(const std::vector<Row>& rows, const std::vector<Individual>& archive) {
    const std::string dir = Dir("run");
    fs::create_directories(dir);
    std::ofstream e(dir + "/evaluations.csv");
    e << EvaluationsHeader() << "\n";
    for (const auto& [generation, child, fitness, fell, gait] : rows) {
      e << generation << ',' << child << ",0/0";
      for (double gene : WithFitness(generation, child, 0).genome.genes) e << ',' << FormatExact(gene);
      e << ',' << fitness << ",1.0," << (fell ? 1 : 0) << ',' << gait << ",3,0.1,1000,\"a, quoted\",12.5\n";
    }
    WriteFileAtomically(RunFiles(dir).archive, ArchiveFileJson(SmallRun(), 3, 4.8763, archive).dump(2));
    return dir;
  }
};

TEST_F(FinalsTest, TheFinalBestAndTheFirstOfTheFittestOfEachGait) {
  Individual best = WithFitness(1, 1, 5.0), second = WithFitness(2, 0, 5.0);
  second.result.gait = Gait::kTripod;
  const std::string dir = Write({{0, 0, 2.0, false, "biped"},
                                 {0, 1, 9.0, true, "tripod"},  // fell: no finalist
                                 {1, 0, 3.0, false, "tripod"},
                                 {1, 1, 5.0, false, "biped"},
                                 {2, 0, 5.0, false, "biped"},  // as fit as 1/1, but younger
                                 {2, 1, 2.5, false, "tripod"}},
                                {best, second});
  const RunFinals finals = LoadRunFinals(dir, SmallRun());
  EXPECT_EQ(finals.final_best.id(), "1/1");
  EXPECT_EQ(finals.final_best.genome.genes, best.genome.genes);
  ASSERT_TRUE(finals.best_biped && finals.best_tripod);
  EXPECT_EQ(finals.best_biped->id(), "1/1");
  EXPECT_EQ(finals.best_biped->fitness(), 5.0);
  EXPECT_EQ(finals.best_biped->genome.genes, WithFitness(1, 1, 0).genome.genes);
  EXPECT_EQ(finals.best_tripod->id(), "1/0");
  EXPECT_EQ(finals.best_tripod->fitness(), 3.0);
  EXPECT_EQ(finals.best_tripod->result.gait, Gait::kTripod);
  EXPECT_EQ(finals.best_tripod->genome.genes, WithFitness(1, 0, 0).genome.genes);
}

TEST_F(FinalsTest, NoTripodThatDidNotFallIsNone) {
  const std::string dir = Write({{0, 0, 2.0, false, "biped"},
                                 {0, 1, 9.0, true, "tripod"},
                                 {1, 0, 3.0, false, "biped"},
                                 {1, 1, 1.0, true, "tripod"},
                                 {2, 0, 2.5, false, "biped"},
                                 {2, 1, 4.0, true, "tripod"}},
                                {WithFitness(1, 0, 3.0), WithFitness(2, 0, 2.5)});
  const RunFinals finals = LoadRunFinals(dir, SmallRun());
  EXPECT_FALSE(finals.best_tripod);
  ASSERT_TRUE(finals.best_biped);
  EXPECT_EQ(finals.best_biped->id(), "1/0");
}

TEST_F(FinalsTest, AGenerationWithoutThePopulationIsAnErrorNamingTheFile) {
  const std::string dir = Write({{0, 0, 2.0, false, "biped"}, {0, 1, 1.0, false, "biped"}, {1, 0, 3.0, false, "biped"}},
                                {WithFitness(1, 0, 3.0), WithFitness(0, 0, 2.0)});
  try {
    LoadRunFinals(dir, SmallRun());
    FAIL() << "a generation of one child was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), dir + "/evaluations.csv: generation 1 has 1 evaluations, not the population's 2");
  }
}

TEST_F(FinalsTest, ABrokenRowIsAnErrorNamingTheFile) {
  const std::string dir = Write({}, {WithFitness(0, 0, 2.0), WithFitness(0, 1, 1.0)});
  std::ofstream(dir + "/evaluations.csv", std::ios::app) << "0,1,2\n";
  try {
    LoadRunFinals(dir, SmallRun());
    FAIL() << "a short row was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("evaluations.csv: row 2"), std::string::npos) << e.what();
  }
}

// An evaluator whose "fitness" is kx scaled by the member's relative tolerance
// over the production one (so the unperturbed member scores kx exactly), and
// that counts its evaluations.
class ScaledKx {
 public:
  ScaledKx()
      : evaluator_({[this](const EvaluationTask& task) {
          ++evaluations_;
          task.result->fitness = (*task.genome)[kKx] * task.settings->integrator.relative_tolerance /
                                 EvaluationSettings{}.integrator.relative_tolerance;
          task.result->gait = (*task.genome)[kKx] > 1000 ? Gait::kTripod : Gait::kBiped;
        }}) {}
  Evaluator& evaluator() { return evaluator_; }
  int evaluations() const { return evaluations_; }

 private:
  std::atomic<int> evaluations_{0};
  SlotEvaluator evaluator_;
};

Genome WithKx(double kx) {
  Genome g = DefaultGenome();
  g[kKx] = kx;
  return g;
}

class RescoreCacheTest : public TempDirTest {};

TEST_F(RescoreCacheTest, EvaluatesEachGenomeOnceAndKeepsTheEnsemblesOfTheGenomesAsked) {
  const std::string path = Dir("rescores.json");
  const Preset preset = OriginalPreset();
  const EvaluationSettings settings;
  ScaledKx scorer;
  std::vector<std::pair<int, int>> batches;
  {
    RescoreCache cache(path, preset, settings, 5);
    cache.Rescore({WithKx(10), WithKx(2000), WithKx(10), WithKx(30)}, scorer.evaluator(), 2,
                  [&](int done, int needed) { batches.push_back({done, needed}); });
    EXPECT_EQ(scorer.evaluations(), 3 * 5) << "the repeated genome once";
    EXPECT_EQ(batches, (std::vector<std::pair<int, int>>{{2, 3}, {3, 3}}));
    const FitnessEnsemble* e = cache.Find(WithKx(10));
    ASSERT_NE(e, nullptr);
    ASSERT_EQ(e->fitness.size(), 5u);
    EXPECT_EQ(e->fitness[2], 10.0) << "the middle member is unperturbed";
    EXPECT_LT(e->fitness[0], e->fitness[4]) << "the members' tolerances differ";
    EXPECT_EQ(e->Median(), 10.0);
    EXPECT_EQ(cache.Find(WithKx(2000))->tripods, 5);
    EXPECT_EQ(cache.Find(WithKx(11)), nullptr);
  }
  // again from the file: nothing evaluated; a new genome is, and the file
  // keeps the genomes asked for only
  {
    RescoreCache cache(path, preset, settings, 5);
    ASSERT_NE(cache.Find(WithKx(30)), nullptr);
    const std::vector<double>& read = cache.Find(WithKx(30))->fitness;
    ASSERT_EQ(read.size(), 5u);
    for (int k = 0; k < 5; ++k) EXPECT_NEAR(read[k], 30 * (1 + 1e-4 * (k - 2)), 1e-12) << "member " << k;
    cache.Rescore({WithKx(10), WithKx(40)}, scorer.evaluator(), 2);
    EXPECT_EQ(scorer.evaluations(), 4 * 5);
  }
  RescoreCache kept(path, preset, settings, 5);
  EXPECT_NE(kept.Find(WithKx(40)), nullptr);
  EXPECT_EQ(kept.Find(WithKx(30)), nullptr);
  // other settings or another size: evaluated again
  EvaluationSettings looser = settings;
  looser.integrator.relative_tolerance *= 2;
  EXPECT_EQ(RescoreCache(path, preset, looser, 5).Find(WithKx(10)), nullptr);
  EXPECT_EQ(RescoreCache(path, preset, settings, 3).Find(WithKx(10)), nullptr);
  EXPECT_EQ(RescoreCache(path, PaperPreset(), settings, 5).Find(WithKx(10)), nullptr);
}

TEST_F(RescoreCacheTest, AMalformedCacheNamesTheFileAndTheField) {
  const std::string path = Dir("rescores.json");
  ScaledKx scorer;
  RescoreCache(path, OriginalPreset(), {}, 3).Rescore({WithKx(10)}, scorer.evaluator(), 1);
  nlohmann::json j = nlohmann::json::parse(ReadFile(path));
  j["genomes"][0]["fitness"].push_back(1.0);
  WriteFileAtomically(path, j.dump());
  try {
    RescoreCache(path, OriginalPreset(), {}, 3);
    FAIL() << "a member too many was accepted";
  } catch (const InputError& e) {
    // the file first, what it is and how to do without it, then the field
    EXPECT_EQ(std::string(e.what()), path + " (a cache of re-scores: remove it to evaluate them again): field "
                                            "'genomes[0].fitness' does not hold 3 members");
  }
}

TEST(RescoreJsonTest, SaysWhetherTheUnperturbedMemberScoredTheRecordedFitness) {
  FitnessEnsemble e;
  e.fitness = {3.0, 5.0, 4.0};
  e.bipeds = 2;
  e.falls = 1;
  const nlohmann::json j = RescoreJson(e, 5.0);
  EXPECT_EQ(j["median"], 4.0);
  EXPECT_EQ(j["min"], 3.0);
  EXPECT_EQ(j["max"], 5.0);
  EXPECT_EQ(j["bipeds"], 2);
  EXPECT_EQ(j["falls"], 1);
  EXPECT_EQ(j["recorded_reproduced"], true);
  EXPECT_EQ(RescoreJson(e, 5.5)["recorded_reproduced"], false);
  e.fitness.push_back(1.0);  // an even size has no unperturbed member
  EXPECT_TRUE(RescoreJson(e, 5.0)["recorded_reproduced"].is_null());
}

}  // namespace
}  // namespace walkers
