#include "evolve/run.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "evolve/files.h"

namespace walkers {
namespace {
namespace fs = std::filesystem;

// A small, quick run: short evaluations, small population; the logic is the
// full one.
RunConfig SmallRun(ScaffoldCase c = ScaffoldCase::kPerformance, int generations = 4) {
  RunConfig config;
  config.scaffold_case = c;
  config.generations = generations;
  config.seed = 42;
  config.ga.population = 8;
  config.ga.archive_size = 8;
  config.ga.mutation_children = 5;
  config.evaluation.duration = 3.0;
  return config;
}

// a file with the last field of every line removed (the wall-clock columns:
// wall_ms of evaluations.csv, evals_per_s of generations.csv)
std::string WithoutTimingColumn(const std::string& path) {
  std::istringstream in(ReadFile(path));
  std::string line, out;
  while (std::getline(in, line)) out += line.substr(0, line.rfind(',')) + "\n";
  return out;
}

class RunTest : public ::testing::Test {
 protected:
  fs::path root_ = fs::temp_directory_path() / ("walkers_run_test_" + std::to_string(::getpid()));
  void SetUp() override { fs::create_directories(root_); }
  void TearDown() override { fs::remove_all(root_); }
  std::string Dir(const std::string& name) const { return (root_ / name).string(); }

  void ExpectSameRun(const std::string& a, const std::string& b) {
    const RunFiles fa(a), fb(b);
    EXPECT_EQ(WithoutTimingColumn(fa.evaluations), WithoutTimingColumn(fb.evaluations));
    EXPECT_EQ(WithoutTimingColumn(fa.generations), WithoutTimingColumn(fb.generations));
    // checkpoint.json is internal: it records byte offsets, which the timing columns shift
    for (auto file : {&RunFiles::archive, &RunFiles::best, &RunFiles::config}) {
      EXPECT_EQ(ReadFile(fa.*file), ReadFile(fb.*file)) << fa.*file;
    }
  }
};

TEST_F(RunTest, WritesEveryFileWithTheDocumentedColumns) {
  EvolutionRun run(SmallRun(), Dir("a"), StartMode::kNew, 2);
  int reported = 0;
  run.Run([&](const GenerationSummary& s) { EXPECT_EQ(s.generation, reported++); });
  EXPECT_EQ(reported, 4);
  const RunFiles f(Dir("a"));
  std::istringstream generations(ReadFile(f.generations));
  std::string header;
  std::getline(generations, header);
  EXPECT_EQ(header, kGenerationsHeader);
  int rows = 0;
  for (std::string line; std::getline(generations, line);) ++rows;
  EXPECT_EQ(rows, 4);
  std::istringstream evaluations(ReadFile(f.evaluations));
  std::getline(evaluations, header);
  EXPECT_EQ(header, EvaluationsHeader());
  rows = 0;
  for (std::string line; std::getline(evaluations, line);) ++rows;
  EXPECT_EQ(rows, 4 * 8);
  // best.json is a genome file the evaluator accepts; the archive is best first
  const Genome best = LoadGenome(f.best);
  EXPECT_EQ(best.genes, run.archive().best().genome.genes);
  const auto archive = nlohmann::json::parse(ReadFile(f.archive));
  ASSERT_EQ(archive.at("archive").size(), 8u);
  EXPECT_GE(archive["archive"][0]["fitness"].get<double>(), archive["archive"][7]["fitness"].get<double>());
  // the config says how to rerun it
  const RunConfig again = RunConfigFromJson(nlohmann::json::parse(ReadFile(f.config)), f.config);
  EXPECT_EQ(again.seed, 42u);
  EXPECT_EQ(again.scaffold_case, ScaffoldCase::kPerformance);
  EXPECT_EQ(again.ga.population, 8);
}

TEST_F(RunTest, SameSeedGivesIdenticalFilesWithOneAndTwoThreads) {
  EvolutionRun(SmallRun(), Dir("one"), StartMode::kNew, 1).Run();
  EvolutionRun(SmallRun(), Dir("two"), StartMode::kNew, 2).Run();
  ExpectSameRun(Dir("one"), Dir("two"));
  // and another seed gives another run
  RunConfig other = SmallRun();
  other.seed = 43;
  EvolutionRun(other, Dir("other"), StartMode::kNew, 2).Run();
  EXPECT_NE(WithoutTimingColumn(RunFiles(Dir("one")).evaluations),
            WithoutTimingColumn(RunFiles(Dir("other")).evaluations));
}

TEST_F(RunTest, KilledAndResumedEndsIdenticalToAnUninterruptedRun) {
  EvolutionRun(SmallRun(), Dir("whole"), StartMode::kNew, 2).Run();

  // killed right after generation 1's checkpoint...
  struct Killed {};
  try {
    EvolutionRun run(SmallRun(), Dir("killed"), StartMode::kNew, 2);
    run.Run([](const GenerationSummary& s) {
      if (s.generation == 1) throw Killed{};
    });
  } catch (const Killed&) {
  }
  // ...while generation 2's rows were reaching the disk: a partial row that
  // no checkpoint names
  const RunFiles f(Dir("killed"));
  AppendDurably(f.evaluations, "2,0,1/3,0.5,0.1");
  AppendDurably(f.generations, "2,7.0,");

  EvolutionRun resumed(SmallRun(), Dir("killed"), StartMode::kResume, 1);
  EXPECT_EQ(resumed.completed_generations(), 2);
  resumed.Run();
  ExpectSameRun(Dir("whole"), Dir("killed"));
}

TEST_F(RunTest, AResumedRunCanBeExtended) {
  EvolutionRun(SmallRun(ScaffoldCase::kTime, 5), Dir("long"), StartMode::kNew, 2).Run();
  EvolutionRun(SmallRun(ScaffoldCase::kTime, 3), Dir("short"), StartMode::kNew, 2).Run();
  EvolutionRun extended(SmallRun(ScaffoldCase::kTime, 5), Dir("short"), StartMode::kResume, 2);
  EXPECT_EQ(extended.completed_generations(), 3);
  extended.Run();
  ExpectSameRun(Dir("long"), Dir("short"));
}

TEST_F(RunTest, NeverOverwritesARunUnlessForced) {
  EvolutionRun(SmallRun(ScaffoldCase::kFree, 1), Dir("a"), StartMode::kNew, 2).Run();
  const std::string before = ReadFile(RunFiles(Dir("a")).evaluations);
  std::ofstream(Dir("a") + "/notes.txt") << "mine";
  try {
    EvolutionRun(SmallRun(), Dir("a"), StartMode::kNew, 2);
    FAIL() << "opened an existing run without --resume or --force";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("--resume"), std::string::npos) << e.what();
  }
  EXPECT_EQ(ReadFile(RunFiles(Dir("a")).evaluations), before);
  // --force replaces the run's files, and only those
  EvolutionRun(SmallRun(ScaffoldCase::kFree, 1), Dir("a"), StartMode::kForce, 2);
  EXPECT_EQ(ReadFile(Dir("a") + "/notes.txt"), "mine");
  EXPECT_FALSE(fs::exists(RunFiles(Dir("a")).checkpoint));
}

TEST_F(RunTest, ResumingWithOtherSettingsIsRefused) {
  EvolutionRun(SmallRun(ScaffoldCase::kFree, 1), Dir("a"), StartMode::kNew, 2).Run();
  RunConfig other = SmallRun(ScaffoldCase::kFree, 2);
  other.seed = 7;
  try {
    EvolutionRun(other, Dir("a"), StartMode::kResume, 2);
    FAIL() << "resumed with another seed";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("seed"), std::string::npos) << e.what();
  }
  EXPECT_THROW(EvolutionRun(SmallRun(), Dir("nothing-here"), StartMode::kResume, 2), std::runtime_error);
}

TEST_F(RunTest, AnUnwritableDirectoryIsAClearError) {
  std::ofstream(Dir("file")) << "x";
  try {
    EvolutionRun(SmallRun(), Dir("file") + "/run", StartMode::kNew, 1);
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("file/run"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace walkers
