#include "evolve/analysis.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "evolve/run.h"
#include "tests/temp_dir_test.h"

namespace walkers {
namespace {
namespace fs = std::filesystem;

// A hand-made run: its best fitness and gait per generation, and its
// evaluations as (fitness, fell, gait) rows, written in the runs' formats.
struct HandMadeRun {
  ScaffoldCase scaffold_case;
  int replicate;
  std::vector<double> best;
  std::vector<std::string> gaits;
  std::vector<std::tuple<int, double, bool, std::string>> evaluations;  // generation, fitness, fell, gait
  double evals_per_s = 4.0;
};

class AnalysisTest : public TempDirTest {
 protected:

  RunData Write(const HandMadeRun& h) {
    const std::string name = std::string(ScaffoldCaseName(h.scaffold_case)) + "-" + std::to_string(h.replicate);
    const fs::path dir = root_ / name;
    fs::create_directories(dir);
    std::ofstream g(dir / "generations.csv");
    g << kGenerationsHeader << "\n";
    for (std::size_t i = 0; i < h.best.size(); ++i) {
      g << i << ',' << h.best[i] << ",0,0,0.9,0.5,0.5,0.6," << h.gaits[i] << ",0," << h.evals_per_s << "\n";
    }
    std::ofstream e(dir / "evaluations.csv");
    e << EvaluationsHeader() << "\n";
    int child = 0;
    for (const auto& [gen, fitness, fell, gait] : h.evaluations) {
      e << gen << ',' << child++ << ",0/0";
      for (int k = 0; k < kNumGenes; ++k) e << ",0.5";
      e << ',' << fitness << ",1.0," << (fell ? 1 : 0) << ',' << gait << ",3,0.1,1000,\"a, quoted\",12.5\n";
    }
    g.close();
    e.close();
    return LoadRunData(dir.string(), h.scaffold_case, h.replicate, name);
  }
};

TEST(ReportedGenerationsTest, PaperGenerationsThatWereReachedAndTheLast) {
  EXPECT_EQ(ReportedGenerations(4000), (std::vector<int>{500, 1000, 2000, 4000}));
  EXPECT_EQ(ReportedGenerations(1500), (std::vector<int>{500, 1000, 1500}));
  EXPECT_EQ(ReportedGenerations(30), (std::vector<int>{30}));
  EXPECT_EQ(ReportedGenerations(500), (std::vector<int>{500}));
}

TEST(MeanAndSdTest, SampleStandardDeviation) {
  const MeanSd m = MeanAndSd({2.0, 4.0, 4.0, 4.0, 5.0, 5.0, 7.0, 9.0});
  EXPECT_DOUBLE_EQ(m.mean, 5.0);
  EXPECT_NEAR(m.sd, std::sqrt(32.0 / 7.0), 1e-12);
  EXPECT_EQ(MeanAndSd({3.0}).sd, 0.0);
}

TEST_F(AnalysisTest, KnownAnswersOnHandMadeRuns) {
  const std::vector<std::string> bipeds(3, "biped");
  std::vector<RunData> runs;
  // case 1: best [1,2,3] and [3,4,5]: means [2,3,4]
  runs.push_back(Write({ScaffoldCase::kFree, 1, {1, 2, 3}, bipeds, {{0, 1.0, false, "biped"}, {2, 3.0, false, "biped"}}}));
  runs.push_back(Write({ScaffoldCase::kFree, 2, {3, 4, 5}, bipeds, {{1, 4.0, false, "biped"}, {2, 5.0, false, "biped"}}}));
  // case 2: a tripod that ends at 2
  runs.push_back(Write({ScaffoldCase::kTime, 1, {1, 1, 2}, {"tripod", "tripod", "tripod"},
                        {{0, 2.0, false, "tripod"}, {1, 9.0, true, "tripod"}, {2, -1.0, true, "biped"}}}));
  // case 3: best [1,5,5] and [1,1,5]: means [1,3,5], above case 1's only at the end
  runs.push_back(Write({ScaffoldCase::kPerformance, 1, {1, 5, 5}, bipeds,
                        {{1, 5.0, false, "biped"}, {2, 6.5, false, "biped"}, {2, 2.5, false, "tripod"}}}));
  runs.push_back(Write({ScaffoldCase::kPerformance, 2, {1, 1, 5}, bipeds, {{2, 5.0, false, "biped"}}}));

  const ReproductionSummary s = Summarize(runs);
  ASSERT_EQ(s.cases.size(), 3u);
  const CaseSummary& free = s.cases[0];
  EXPECT_EQ(free.scaffold_case, ScaffoldCase::kFree);
  EXPECT_EQ(free.mean_best, (std::vector<double>{2, 3, 4}));
  EXPECT_NEAR(free.sd_best[0], std::sqrt(2.0), 1e-12);
  ASSERT_EQ(free.best_after.size(), 1u);  // only "the last": 3 generations
  EXPECT_EQ(free.best_after[0].first, 3);
  EXPECT_DOUBLE_EQ(free.best_after[0].second.mean, 4.0);
  EXPECT_EQ(free.tripod_finals, 0);
  EXPECT_EQ(s.cases[1].tripod_finals, 1);

  EXPECT_NEAR(*s.case3_over_case1, 1.0 / 3.0, 1e-12);  // strictly above in generation 2 only
  EXPECT_NEAR(*s.case2_over_case1, 2.0 / 4.0, 1e-12);

  // the best of each class over every evaluation that did not fall
  ASSERT_TRUE(s.best_biped && s.best_tripod);
  EXPECT_DOUBLE_EQ(s.best_biped->fitness, 6.5);
  EXPECT_EQ(s.best_biped->run, "performance-1");
  EXPECT_EQ(s.best_biped->id, "2/1");
  EXPECT_DOUBLE_EQ(s.best_tripod->fitness, 2.5);  // 9.0 fell
  EXPECT_NEAR(*s.biped_over_tripod, 6.5 / 2.5, 1e-12);

  EXPECT_EQ(s.evaluations, 11);  // 2 + 2 + 3 + 3 + 1
  EXPECT_EQ(s.falls, 2);
  EXPECT_NEAR(s.evaluation_seconds, 11 / 4.0, 1e-12);

  // the JSON and the table carry them, beside the paper's values
  const nlohmann::json j = SummaryToJson(s);
  EXPECT_NEAR(j["case3_over_case1_share"]["value"].get<double>(), 1.0 / 3.0, 1e-12);
  EXPECT_DOUBLE_EQ(j["case3_over_case1_share"]["paper"].get<double>(), 0.83);
  EXPECT_EQ(j["cases"]["time"]["tripod_finals"].get<int>(), 1);
  EXPECT_DOUBLE_EQ(j["fell_share"].get<double>(), 2.0 / 11.0);
  const std::string md = SummaryToMarkdown(s, "test");
  EXPECT_NE(md.find("| 33.3 % | 83 % |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 50.0 % | 66 % |"), std::string::npos) << md;
  EXPECT_NE(md.find("+160.0 %"), std::string::npos) << md;
  EXPECT_NE(md.find("4.00 ± 1.41"), std::string::npos) << md;
  EXPECT_NE(md.find("| 2, time-constrained | 1 | 2.00 |"), std::string::npos) << md;  // one run: no spread
}

TEST_F(AnalysisTest, OneReplicateShowsNoSpread) {
  const std::vector<std::string> bipeds(2, "biped");
  std::vector<RunData> runs;
  for (ScaffoldCase c : {ScaffoldCase::kFree, ScaffoldCase::kTime, ScaffoldCase::kPerformance}) {
    runs.push_back(Write({c, 1, {1, 2}, bipeds, {{0, 1.0, false, "biped"}, {1, 2.0, false, "biped"}}}));
  }
  const std::string md = SummaryToMarkdown(Summarize(runs), "one");
  EXPECT_EQ(md.find("±"), std::string::npos) << md;
  EXPECT_NE(md.find("## Best fitness (one replicate)"), std::string::npos) << md;
  EXPECT_NE(md.find("| 1, free | 1 | 2.00 |"), std::string::npos) << md;
}

TEST_F(AnalysisTest, MissingCasesLeaveTheirComparisonsOut) {
  const RunData only = Write({ScaffoldCase::kFree, 1, {1, 2}, {"biped", "biped"}, {{0, 1.0, false, "biped"}}});
  const ReproductionSummary s = Summarize({only});
  EXPECT_FALSE(s.case3_over_case1);
  EXPECT_FALSE(s.case2_over_case1);
  EXPECT_FALSE(s.best_tripod);
  EXPECT_FALSE(s.biped_over_tripod);
  EXPECT_TRUE(SummaryToJson(s)["biped_over_tripod"]["value"].is_null());
}

TEST_F(AnalysisTest, ABrokenRowIsAnErrorNamingTheFile) {
  const fs::path dir = root_ / "broken";
  fs::create_directories(dir);
  std::ofstream(dir / "generations.csv") << kGenerationsHeader << "\n0,1.0,2\n";
  std::ofstream(dir / "evaluations.csv") << EvaluationsHeader() << "\n";
  try {
    LoadRunData(dir.string(), ScaffoldCase::kFree, 1, "broken");
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("generations.csv: row 2"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace walkers
