#include "evolve/time_left.h"

#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/temp_dir_test.h"

namespace walkers {
namespace {

// Without a finished run every generation costs the same: the pace of the
// generations done, over the generations left. The pace runs from the end of
// the session's first generation: the 10 s of starting up before it count
// only while it is the only generation done.
TEST(TimeLeftTest, WithoutFinishedRunsEveryGenerationCostsTheSame) {
  TimeLeft t(10);
  t.AddRun("free-1", "free", 0);
  t.AddRun("free-2", "free", 0);  // not started
  EXPECT_FALSE(t.Estimate(5.0).has_value());
  t.Done("free-1", 0, 10.0);  // the first generation alone: 10 s from the start a generation
  EXPECT_DOUBLE_EQ(*t.Estimate(10.0), 10.0 * 19);
  EXPECT_FALSE(t.RunLeft("free-1", 10.0).has_value());
  for (int g = 1; g < 5; ++g) t.Done("free-1", g, 10.0 + 2.0 * g);
  ASSERT_TRUE(t.Estimate(18.0).has_value());
  EXPECT_DOUBLE_EQ(*t.Estimate(18.0), 2.0 * 15);
  EXPECT_DOUBLE_EQ(*t.RunLeft("free-1", 18.0), 2.0 * 5);
}

// Late generations cost more than early ones in the finished runs of the
// kind, so the early generations' pace is scaled up: 2 + ... + 5 done in
// 14 s, 6 + ... + 10 left, where equal weights would say 17.5 s.
TEST(TimeLeftTest, WeighsEachGenerationByTheFinishedRunsOfItsKind) {
  std::vector<double> rising;
  for (int g = 0; g < 10; ++g) rising.push_back(g + 1.0);
  TimeLeft t(10);
  t.AddFinished("free", rising);
  t.AddRun("free-2", "free", 0);
  for (int g = 0; g < 5; ++g) t.Done("free-2", g, 0.5 * (g + 1) * (g + 2));  // generation g took g + 1 s
  EXPECT_DOUBLE_EQ(*t.Estimate(15.0), 40.0);
  EXPECT_DOUBLE_EQ(*t.RunLeft("free-2", 15.0), 40.0);
  EXPECT_FALSE(t.RunLeft("free-9", 15.0).has_value());
  t.AddRun("free-3", "free", 2);  // started, nothing done yet
  EXPECT_FALSE(t.RunLeft("free-3", 15.0).has_value());
  EXPECT_DOUBLE_EQ(*t.Estimate(15.0), 40.0 + (3 + 4 + 5 + 6 + 7 + 8 + 9 + 10));

  // the mean over the kind's finished runs: costs 1 and 3 a generation
  TimeLeft mean(4);
  mean.AddFinished("time", std::vector<double>(4, 1.0));
  mean.AddFinished("time", std::vector<double>(4, 3.0));
  mean.AddFinished("free", std::vector<double>(4, 100.0));
  mean.AddRun("time-3", "time", 0);
  mean.AddRun("free-3", "free", 0);  // not started: 4 x 100 left
  mean.Done("time-3", 0, 1.0);
  mean.Done("time-3", 1, 3.0);  // cost 2 in 2 s
  EXPECT_DOUBLE_EQ(*mean.Estimate(3.0), 2.0 * 2.0 + 400.0);
}

// A kind without a finished run takes every finished run's mean; a run
// resumed counts from where it stood; a finished one leaves nothing.
TEST(TimeLeftTest, OtherKindsResumedAndFinishedRuns) {
  TimeLeft t(5);
  t.AddFinished("free", std::vector<double>(5, 1.0));
  t.AddFinished("time", std::vector<double>(5, 3.0));
  t.AddRun("free-1", "free", 5);                // finished before this session
  t.AddRun("performance-1", "performance", 2);  // resumed after generation 2
  t.Done("performance-1", 2, 1.0);
  t.Done("performance-1", 3, 5.0);  // cost 2 in 4 s
  EXPECT_DOUBLE_EQ(*t.Estimate(5.0), 4.0);
  // a list of another length is no profile
  t.AddFinished("performance", {50.0});
  EXPECT_DOUBLE_EQ(*t.Estimate(5.0), 4.0);
  // an unknown run's generation changes nothing
  t.Done("time-9", 0, 5.0);
  EXPECT_DOUBLE_EQ(*t.Estimate(5.0), 4.0);
}

class GenerationCostsTest : public TempDirTest {
 protected:
  std::string Write(const std::string& name, const std::string& text) {
    const std::string path = Dir(name);
    std::ofstream(path) << text;
    return path;
  }
};

// What a generation took, 1 / evals_per_s, from generations.csv; nothing from
// a file that cannot be read or a rate that is not positive.
TEST_F(GenerationCostsTest, ReadsTheRateOfEveryGeneration) {
  const std::string header = "generation,best_fitness,evals_per_s\n";
  EXPECT_EQ(GenerationCosts(Write("a.csv", header + "0,1.5,4\n1,2.5,0.5\n")), (std::vector<double>{0.25, 2.0}));
  EXPECT_TRUE(GenerationCosts(Write("b.csv", header + "0,1.5,4\n1,2.5,0\n")).empty());
  EXPECT_TRUE(GenerationCosts(Write("c.csv", header + "0,1.5,nan\n")).empty());
  EXPECT_TRUE(GenerationCosts(Write("d.csv", "generation,best_fitness\n0,1\n")).empty());
  EXPECT_TRUE(GenerationCosts(Dir("missing.csv")).empty());
}

}  // namespace
}  // namespace walkers
