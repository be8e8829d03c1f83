#include "evolve/run.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "files/durable_file.h"
#include "files/input_file.h"
#include "tests/evolve/individuals.h"
#include "tests/evolve/small_runs.h"
#include "tests/temp_dir_test.h"

namespace walkers {
namespace {
namespace fs = std::filesystem;
using testing::ExpectSameRun;
using testing::SmallRun;
using testing::Threads;
using testing::WithoutTimingColumn;

class RunTest : public TempDirTest {};

TEST_F(RunTest, WritesEveryFileWithTheDocumentedColumns) {
  EvolutionRun run(SmallRun(), Dir("a"), StartMode::kNew, Threads(2));
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
  // and the integrator's choices with it
  EXPECT_EQ(again.evaluation.integrator.relative_tolerance, SmallRun().evaluation.integrator.relative_tolerance);
  EXPECT_EQ(again.evaluation.integrator.restart_at_ticks,
            SmallRun().evaluation.integrator.restart_at_ticks);
  RunConfig history = SmallRun();
  history.evaluation.integrator.restart_at_ticks = !history.evaluation.integrator.restart_at_ticks;
  EXPECT_EQ(RunConfigFromJson(RunConfigToJson(history), "config.json").evaluation.integrator.restart_at_ticks,
            history.evaluation.integrator.restart_at_ticks);
}

TEST_F(RunTest, SameSeedGivesIdenticalFilesWithOneAndTwoThreads) {
  EvolutionRun(SmallRun(), Dir("one"), StartMode::kNew, Threads(1)).Run();
  EvolutionRun(SmallRun(), Dir("two"), StartMode::kNew, Threads(2)).Run();
  ExpectSameRun(Dir("one"), Dir("two"));
  // and another seed gives another run
  RunConfig other = SmallRun();
  other.seed = 43;
  EvolutionRun(other, Dir("other"), StartMode::kNew, Threads(2)).Run();
  EXPECT_NE(WithoutTimingColumn(RunFiles(Dir("one")).evaluations),
            WithoutTimingColumn(RunFiles(Dir("other")).evaluations));
}

TEST_F(RunTest, KilledAndResumedEndsIdenticalToAnUninterruptedRun) {
  EvolutionRun(SmallRun(), Dir("whole"), StartMode::kNew, Threads(2)).Run();

  // killed right after generation 1's checkpoint...
  struct Killed {};
  try {
    EvolutionRun run(SmallRun(), Dir("killed"), StartMode::kNew, Threads(2));
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

  EvolutionRun resumed(SmallRun(), Dir("killed"), StartMode::kResume, Threads(1));
  EXPECT_EQ(resumed.completed_generations(), 2);
  resumed.Run();
  ExpectSameRun(Dir("whole"), Dir("killed"));
}

// The caller drives each generation in two halves, acting between them, as
// the Python module's ask/tell run does: the files are Run()'s.
TEST_F(RunTest, AGenerationDrivenHalfByHalfIsRunsGeneration) {
  EvolutionRun(SmallRun(), Dir("run"), StartMode::kNew, Threads(2)).Run();

  EvolutionRun driven(SmallRun(), Dir("driven"), StartMode::kNew, Threads(2));
  std::unique_ptr<Learner> learner = MakeLearner("ga", SmallRun().ga, SmallRun().seed);
  int generations = 0;
  while (!driven.done()) {
    const BreedingInputs in = driven.BeginGeneration();
    EXPECT_EQ(in.generation, driven.completed_generations());
    // beginning a generation changes nothing: begun again, it is the same
    EXPECT_EQ(driven.BeginGeneration().body_ceiling, in.body_ceiling);
    const EvaluatedChildren evaluated = driven.EvaluateChildren(in, learner->Propose(in, driven.archive()));
    ASSERT_EQ(evaluated.children.size(), 8u);
    EXPECT_FALSE(fs::exists(RunFiles(Dir("driven")).archive));
    const GenerationSummary s = driven.FinishGeneration(in, evaluated, learner->State());
    EXPECT_EQ(s.generation, generations++);
    EXPECT_EQ(s.ceiling, in.body_ceiling);
  }
  EXPECT_EQ(generations, SmallRun().generations);
  ExpectSameRun(Dir("run"), Dir("driven"));
  // a generation out of order is a bug of the caller's, named where it was found
  try {
    driven.BeginGeneration();
    FAIL() << "began a generation of a finished run";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("run.cc"), std::string::npos) << e.what();
  }
}

TEST_F(RunTest, AFinishedRunResumedWritesItsResultsAgain) {
  EvolutionRun(SmallRun(ScaffoldCase::kFree, 2), Dir("a"), StartMode::kNew, Threads(2)).Run();
  const RunFiles files(Dir("a"));
  const std::string archive = ReadFile(files.archive), best = ReadFile(files.best);
  // killed after its last checkpoint, before its results were written
  fs::remove(files.archive);
  fs::remove(files.best);
  EvolutionRun resumed(SmallRun(ScaffoldCase::kFree, 2), Dir("a"), StartMode::kResume, Threads(2));
  EXPECT_TRUE(resumed.done());
  EXPECT_EQ(ReadFile(files.archive), archive);
  EXPECT_EQ(ReadFile(files.best), best);
}

TEST_F(RunTest, AResumedRunCanBeExtended) {
  EvolutionRun(SmallRun(ScaffoldCase::kTime, 5), Dir("long"), StartMode::kNew, Threads(2)).Run();
  EvolutionRun(SmallRun(ScaffoldCase::kTime, 3), Dir("short"), StartMode::kNew, Threads(2)).Run();
  EvolutionRun extended(SmallRun(ScaffoldCase::kTime, 5), Dir("short"), StartMode::kResume, Threads(2));
  EXPECT_EQ(extended.completed_generations(), 3);
  extended.Run();
  ExpectSameRun(Dir("long"), Dir("short"));
}

TEST_F(RunTest, NeverOverwritesARunUnlessForced) {
  EvolutionRun(SmallRun(ScaffoldCase::kFree, 1), Dir("a"), StartMode::kNew, Threads(2)).Run();
  const std::string before = ReadFile(RunFiles(Dir("a")).evaluations);
  std::ofstream(Dir("a") + "/notes.txt") << "mine";
  try {
    EvolutionRun(SmallRun(), Dir("a"), StartMode::kNew, Threads(2));
    FAIL() << "opened an existing run without --resume or --force";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("--resume"), std::string::npos) << e.what();
  }
  EXPECT_EQ(ReadFile(RunFiles(Dir("a")).evaluations), before);
  // --force replaces the run's files, and only those
  RunConfig other = SmallRun(ScaffoldCase::kFree, 1);
  other.seed = 7;
  EvolutionRun(other, Dir("a"), StartMode::kForce, Threads(2)).Run();
  EXPECT_EQ(ReadFile(Dir("a") + "/notes.txt"), "mine");
  EXPECT_NE(ReadFile(RunFiles(Dir("a")).evaluations), before);
  EXPECT_FALSE(fs::exists(Dir("a") + "/replaced"));
}

// every run file's content, by name, and whether the set-aside folder exists
std::map<std::string, std::string> RunFileContents(const std::string& dir) {
  std::map<std::string, std::string> out;
  for (const std::string& name : RunFiles::Names()) {
    const fs::path path = fs::path(dir) / name;
    out[name] = fs::exists(path) ? ReadFile(path.string()) : "(absent)";
  }
  out["replaced/"] = fs::exists(fs::path(dir) / "replaced") ? "exists" : "(absent)";
  return out;
}

TEST_F(RunTest, ForceKeepsTheOldRunAsideUntilTheNewRunsFirstCheckpoint) {
  EvolutionRun(SmallRun(ScaffoldCase::kFree, 2), Dir("a"), StartMode::kNew, Threads(2)).Run();
  const auto old_run = RunFileContents(Dir("a"));
  RunConfig other = SmallRun(ScaffoldCase::kFree, 2);
  other.seed = 7;
  {
    EvolutionRun forced(other, Dir("a"), StartMode::kForce, Threads(2));
    // the old run is aside, whole; the new one has begun
    EXPECT_EQ(ReadFile(Dir("a") + "/replaced/evaluations.csv"), old_run.at("evaluations.csv"));
    EXPECT_EQ(ReadFile(Dir("a") + "/replaced/checkpoint.json"), old_run.at("checkpoint.json"));
    EXPECT_FALSE(fs::exists(RunFiles(Dir("a")).checkpoint));
  }
  // abandoned before its first generation: the old run is back, as it was
  EXPECT_EQ(RunFileContents(Dir("a")), old_run);

  EvolutionRun forced(other, Dir("a"), StartMode::kForce, Threads(2));
  int generations = 0;
  forced.Run([&](const GenerationSummary&) {
    ++generations;
    EXPECT_FALSE(fs::exists(Dir("a") + "/replaced")) << "kept after the first checkpoint";
  });
  EXPECT_EQ(generations, 2);
}

TEST_F(RunTest, ForceWithAnImpossibleConfigurationLeavesTheOldRunIntact) {
  EvolutionRun(SmallRun(ScaffoldCase::kFree, 2), Dir("a"), StartMode::kNew, Threads(2)).Run();
  const auto old_run = RunFileContents(Dir("a"));
  // one child a generation: generation 1 could not breed from an archive of one
  RunConfig impossible = SmallRun(ScaffoldCase::kFree, 3);
  impossible.ga.population = 1;
  impossible.ga.mutation_children = 1;
  try {
    EvolutionRun(impossible, Dir("a"), StartMode::kForce, Threads(2));
    FAIL() << "started a run that cannot breed";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "population = 1 is outside its allowed range [2, 100000]");
  }
  EXPECT_EQ(RunFileContents(Dir("a")), old_run);
}

TEST_F(RunTest, ValidateChecksEveryConstraintOfARun) {
  const auto error = [](RunConfig c) -> std::string {
    try {
      c.Validate();
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(error(SmallRun()), "");
  RunConfig c = SmallRun();
  c.ga.mutation_children = 9;
  EXPECT_EQ(error(c), "mutation_children = 9 is outside its allowed range [0, 8]");
  c = SmallRun();
  c.ga.mutation_probability = 0.0;  // every mutant would repeat its parent
  EXPECT_EQ(error(c), "mutation_probability = 0 is outside its allowed range (0, 1]");
  c = SmallRun();
  c.seed = kMaxSeed + 1;
  EXPECT_EQ(error(c), "seed = 4294967296 is outside its allowed range [0, 4294967295]");
  c = SmallRun();
  c.generations = 0;
  EXPECT_EQ(error(c), "generations = 0 is outside its allowed range [1, 10000000]");
  c = SmallRun();
  c.evaluation.duration = -1;
  EXPECT_EQ(error(c), "evaluation.duration = -1 is outside its allowed range (0, 3600]");
}

TEST_F(RunTest, OneWriterPerRunDirectory) {
  EvolutionRun(SmallRun(ScaffoldCase::kFree, 1), Dir("a"), StartMode::kNew, Threads(2)).Run();
  {
    EvolutionRun first(SmallRun(ScaffoldCase::kFree, 2), Dir("a"), StartMode::kResume, Threads(2));
    const auto before = RunFileContents(Dir("a"));
    for (StartMode mode : {StartMode::kResume, StartMode::kForce, StartMode::kNew}) {
      try {
        EvolutionRun second(SmallRun(ScaffoldCase::kFree, 2), Dir("a"), mode, Threads(2));
        FAIL() << "two writers on one run";
      } catch (const std::runtime_error& e) {
        const std::string expected =
            Dir("a") + ": another walkers process (pid " + std::to_string(::getpid()) + ") is writing this run";
        EXPECT_EQ(std::string(e.what()).rfind(expected, 0), 0u) << e.what();
      }
    }
    EXPECT_EQ(RunFileContents(Dir("a")), before);
  }
  // released with its holder
  EvolutionRun(SmallRun(ScaffoldCase::kFree, 2), Dir("a"), StartMode::kResume, Threads(2)).Run();
}

// the file with `change` applied to its text
void EditFile(const std::string& path, const std::function<void(std::string*)>& change) {
  std::string text = ReadFile(path);
  change(&text);
  std::ofstream(path, std::ios::trunc) << text;
}

class CheckpointTest : public RunTest {
 protected:
  void SetUp() override {
    RunTest::SetUp();
    EvolutionRun(SmallRun(ScaffoldCase::kFree, 3), Dir("a"), StartMode::kNew, Threads(2)).Run();
    files_ = RunFileContents(Dir("a"));
  }
  // the message of resuming the run, which must leave its files as they were
  std::string ResumeError() {
    try {
      EvolutionRun(SmallRun(ScaffoldCase::kFree, 5), Dir("a"), StartMode::kResume, Threads(2));
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "";
  }
  void ExpectRefusedNaming(const std::string& file, const std::string& text) {
    const auto edited = RunFileContents(Dir("a"));
    const std::string error = ResumeError();
    EXPECT_EQ(error.rfind(Dir("a") + "/" + file + ": ", 0), 0u) << error;
    EXPECT_NE(error.find(text), std::string::npos) << error;
    EXPECT_EQ(RunFileContents(Dir("a")), edited) << "a refused resume changed the files";
  }
  std::string Checkpoint() const { return RunFiles(Dir("a")).checkpoint; }
  std::map<std::string, std::string> files_;
};

TEST_F(CheckpointTest, ANegativeGenerationCountIsRefusedNamingTheField) {
  EditFile(Checkpoint(), [](std::string* t) {
    const std::size_t at = t->find("\"completed_generations\":3");
    ASSERT_NE(at, std::string::npos) << *t;
    t->replace(at, 25, "\"completed_generations\":-3");
  });
  ExpectRefusedNaming("checkpoint.json", "field 'completed_generations' = -3 is outside its allowed range [1, 3]");
}

TEST_F(CheckpointTest, AMissingFieldIsNamedNotALibraryMessage) {
  EditFile(Checkpoint(), [](std::string* t) { t->replace(t->find("\"format\":1,"), 11, ""); });
  ExpectRefusedNaming("checkpoint.json", "missing field 'format'");
}

TEST_F(CheckpointTest, ADuplicatedKeyIsRefused) {
  EditFile(Checkpoint(), [](std::string* t) { t->insert(1, "\"completed_generations\":1,"); });
  ExpectRefusedNaming("checkpoint.json", "key 'completed_generations' appears twice");
}

TEST_F(CheckpointTest, AnArchiveThatTheRunCannotHaveIsRefused) {
  EditFile(Checkpoint(), [](std::string* t) {
    const std::size_t at = t->find("\"gait\":\"");
    t->replace(at, 8, "\"gait\":\"x");
  });
  ExpectRefusedNaming("checkpoint.json", "field 'archive[0].gait' = \"x");
}

TEST_F(CheckpointTest, AnArchiveGenomeOutOfRangeIsRefusedNamingIt) {
  EditFile(Checkpoint(), [](std::string* t) {
    const std::size_t at = t->find("\"kStep\":");
    t->replace(at, 8, "\"kStep\":9000,\"x\":");
  });
  ExpectRefusedNaming("checkpoint.json", "archive[0].genome: unknown gene 'x'");
}

TEST_F(CheckpointTest, AnArchiveMembersLineageThatIsNoneIsRefusedNamingIt) {
  EditFile(Checkpoint(), [](std::string* t) {
    const std::size_t at = t->find("\"parents\":\"");
    t->replace(at, 11, "\"parents\":\"0/0 mutated");
  });
  ExpectRefusedNaming("checkpoint.json", "field 'archive[0].parents' = \"0/0 mutated");
}

// an evaluation has one outcome: it falls or fails, not both
TEST_F(CheckpointTest, AnArchiveMemberThatFellAndFailedIsRefusedNamingIt) {
  EditFile(Checkpoint(), [](std::string* t) {
    t->replace(t->find("\"failure\":\"\""), 12, "\"failure\":\"CVODE failed\"");
    t->replace(t->find("\"fell\":false"), 12, "\"fell\":true");
  });
  ExpectRefusedNaming("checkpoint.json",
                      "field 'archive[0].failure' = \"CVODE failed\" names a failure, but the walker fell");
}

TEST_F(CheckpointTest, CsvFilesThatDisagreeWithTheCheckpointAreRefused) {
  // a gene of row 3 is no number
  EditFile(RunFiles(Dir("a")).evaluations, [](std::string* t) {
    std::size_t at = 0;
    for (int line = 0; line < 3; ++line) at = t->find('\n', at) + 1;
    at = t->find(',', t->find(',', t->find(',', at) + 1) + 1) + 1;  // the first gene
    t->replace(at, 3, "abc");
  });
  ExpectRefusedNaming("evaluations.csv", "row 4, column 'halfBodyX': 'abc");
}

TEST_F(CheckpointTest, AShortenedCsvIsRefused) {
  const std::string path = RunFiles(Dir("a")).generations;
  TruncateFile(path, FileSize(path) - 5);
  ExpectRefusedNaming("generations.csv", "shorter than the");
}

TEST_F(CheckpointTest, ADeletedCheckpointBesideResultsIsAnErrorNotARestart) {
  fs::remove(Checkpoint());
  const std::string error = ResumeError();
  EXPECT_NE(error.find("checkpoint.json: missing, but the run has results (generations.csv has 3 rows)"),
            std::string::npos)
      << error;
  EXPECT_NE(error.find("--force"), std::string::npos) << error;
  auto expected = files_;
  expected["checkpoint.json"] = "(absent)";
  EXPECT_EQ(RunFileContents(Dir("a")), expected);
}

TEST_F(CheckpointTest, AConfigWithADuplicatedOrUnknownKeyIsRefused) {
  const std::string config = RunFiles(Dir("a")).config;
  EditFile(config, [](std::string* t) { t->insert(1, "\"seed\": 1,"); });
  ExpectRefusedNaming("config.json", "key 'seed' appears twice");
  std::ofstream(config, std::ios::trunc) << files_.at("config.json");
  EditFile(config, [](std::string* t) { t->insert(1, "\"seeds\": 1,"); });
  ExpectRefusedNaming("config.json", "unknown field 'seeds'");
  std::ofstream(config, std::ios::trunc) << files_.at("config.json");
  EditFile(config, [](std::string* t) { t->replace(t->find("\"population\": 8"), 15, "\"population\": 1"); });
  ExpectRefusedNaming("config.json", "population = 1 is outside its allowed range [2, 100000]");
}

TEST_F(RunTest, ResumingNeverCreatesTheDirectory) {
  EXPECT_THROW(EvolutionRun(SmallRun(), Dir("absent"), StartMode::kResume, Threads(2)), std::runtime_error);
  EXPECT_FALSE(fs::exists(Dir("absent")));
}

TEST_F(RunTest, AForceStoppedBeforeItsFirstCheckpointIsRecovered) {
  EvolutionRun(SmallRun(ScaffoldCase::kFree, 2), Dir("a"), StartMode::kNew, Threads(2)).Run();
  const auto old_run = RunFileContents(Dir("a"));
  // stopped while setting the old run aside: half of it in replaced.partial/
  fs::create_directory(Dir("a") + "/replaced.partial");
  for (const char* name : {"checkpoint.json", "evaluations.csv"}) {
    fs::rename(Dir("a") + "/" + name, Dir("a") + "/replaced.partial/" + name);
  }
  EvolutionRun(SmallRun(ScaffoldCase::kFree, 2), Dir("a"), StartMode::kResume, Threads(2));  // moved back first
  EXPECT_EQ(RunFileContents(Dir("a")), old_run);
  EXPECT_FALSE(fs::exists(Dir("a") + "/replaced.partial"));

  // stopped after setting it aside, before the new run's first checkpoint
  fs::create_directory(Dir("a") + "/replaced");
  for (const std::string& name : RunFiles::Names()) {
    if (fs::exists(Dir("a") + "/" + name)) fs::rename(Dir("a") + "/" + name, Dir("a") + "/replaced/" + name);
  }
  EvolutionRun(SmallRun(ScaffoldCase::kFree, 1), Dir("fresh"), StartMode::kNew, Threads(2));
  fs::copy_file(Dir("fresh") + "/config.json", Dir("a") + "/config.json");
  try {
    EvolutionRun(SmallRun(ScaffoldCase::kFree, 2), Dir("a"), StartMode::kResume, Threads(2));
    FAIL() << "resumed a stub, hiding the run it replaces";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("a --force was stopped"), std::string::npos) << e.what();
  }
  // --force again: the stub goes, the old run stays aside until the new checkpoint
  {
    EvolutionRun forced(SmallRun(ScaffoldCase::kFree, 2), Dir("a"), StartMode::kForce, Threads(2));
    EXPECT_EQ(ReadFile(Dir("a") + "/replaced/evaluations.csv"), old_run.at("evaluations.csv"));
  }
  EXPECT_EQ(RunFileContents(Dir("a")), old_run);
}

TEST_F(RunTest, StaleTemporaryFilesOfKilledWritersAreRemoved) {
  EvolutionRun(SmallRun(ScaffoldCase::kFree, 1), Dir("a"), StartMode::kNew, Threads(2)).Run();
  std::ofstream(Dir("a") + "/checkpoint.json.tmp.999999999") << "{";
  std::ofstream(Dir("a") + "/notes.tmp.txt") << "mine";
  EvolutionRun(SmallRun(ScaffoldCase::kFree, 2), Dir("a"), StartMode::kResume, Threads(2)).Run();
  EXPECT_FALSE(fs::exists(Dir("a") + "/checkpoint.json.tmp.999999999"));
  EXPECT_TRUE(fs::exists(Dir("a") + "/notes.tmp.txt"));
}

TEST_F(RunTest, ResumingWithOtherSettingsIsRefused) {
  EvolutionRun(SmallRun(ScaffoldCase::kFree, 1), Dir("a"), StartMode::kNew, Threads(2)).Run();
  RunConfig other = SmallRun(ScaffoldCase::kFree, 2);
  other.seed = 7;
  try {
    EvolutionRun(other, Dir("a"), StartMode::kResume, Threads(2));
    FAIL() << "resumed with another seed";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("seed"), std::string::npos) << e.what();
  }
  EXPECT_THROW(EvolutionRun(SmallRun(), Dir("nothing-here"), StartMode::kResume, Threads(2)), std::runtime_error);
  EXPECT_FALSE(fs::exists(Dir("nothing-here")));
}

// The run with each learner beside the GA: the same files on any number of
// threads and after a resume, its learner named in its files.
class LearnerRunTest : public RunTest, public ::testing::WithParamInterface<std::string> {
 protected:
  RunConfig LearnerRun(int generations = 4) const {
    RunConfig config = SmallRun(ScaffoldCase::kPerformance, generations);
    config.learner = GetParam();
    return config;
  }
};

std::vector<std::string> LearnersBesideTheGa() {
  std::vector<std::string> names = BuiltInLearnerNames();
  names.erase(names.begin());
  return names;
}

INSTANTIATE_TEST_SUITE_P(Learners, LearnerRunTest, ::testing::ValuesIn(LearnersBesideTheGa()),
                         [](const ::testing::TestParamInfo<std::string>& p) { return p.param; });

TEST_P(LearnerRunTest, SameSeedGivesIdenticalFilesWithOneAndTwoThreads) {
  EvolutionRun(LearnerRun(), Dir("one"), StartMode::kNew, Threads(1)).Run();
  EvolutionRun(LearnerRun(), Dir("two"), StartMode::kNew, Threads(2)).Run();
  ExpectSameRun(Dir("one"), Dir("two"));
  // the learner's children, not the GA's, from generation 1 on
  RunConfig ga = LearnerRun();
  ga.learner = "ga";
  EvolutionRun(ga, Dir("ga"), StartMode::kNew, Threads(2)).Run();
  EXPECT_NE(WithoutTimingColumn(RunFiles(Dir("one")).evaluations), WithoutTimingColumn(RunFiles(Dir("ga")).evaluations));
  std::istringstream rows(ReadFile(RunFiles(Dir("one")).evaluations));
  std::string line;
  int by_learner = 0;
  while (std::getline(rows, line)) by_learner += line.rfind("3,", 0) == 0 && line.find("," + GetParam()) != std::string::npos;
  EXPECT_EQ(by_learner, 8) << "generation 3's children name the learner";
  // the files say which learner it was
  const RunConfig again = RunConfigFromJson(nlohmann::json::parse(ReadFile(RunFiles(Dir("one")).config)), "config.json");
  EXPECT_EQ(again.learner, GetParam());
  EXPECT_EQ(nlohmann::json::parse(ReadFile(RunFiles(Dir("one")).archive)).at("learner"), GetParam());
}

TEST_P(LearnerRunTest, KilledAndResumedEndsIdenticalToAnUninterruptedRun) {
  EvolutionRun(LearnerRun(5), Dir("whole"), StartMode::kNew, Threads(2)).Run();
  // killed after generation 2's checkpoint, while generation 3's rows were written
  struct Killed {};
  try {
    EvolutionRun run(LearnerRun(5), Dir("killed"), StartMode::kNew, Threads(2));
    run.Run([](const GenerationSummary& s) {
      if (s.generation == 2) throw Killed{};
    });
  } catch (const Killed&) {
  }
  AppendDurably(RunFiles(Dir("killed")).evaluations, "3,0,cmaes,0.5,0.1");
  const nlohmann::json checkpoint = nlohmann::json::parse(ReadFile(RunFiles(Dir("killed")).checkpoint));
  EXPECT_TRUE(checkpoint.contains("learner")) << "the learner's state is in the checkpoint";
  EvolutionRun resumed(LearnerRun(5), Dir("killed"), StartMode::kResume, Threads(1));
  EXPECT_EQ(resumed.completed_generations(), 3);
  resumed.Run();
  ExpectSameRun(Dir("whole"), Dir("killed"));
}

TEST_P(LearnerRunTest, ResumingWithAnotherLearnerIsRefused) {
  EvolutionRun(LearnerRun(1), Dir("a"), StartMode::kNew, Threads(2)).Run();
  RunConfig ga = LearnerRun(2);
  ga.learner = "ga";
  try {
    EvolutionRun(ga, Dir("a"), StartMode::kResume, Threads(2));
    FAIL() << "resumed a " << GetParam() << " run with the GA";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("learner"), std::string::npos) << e.what();
  }
}

TEST_P(LearnerRunTest, ADamagedLearnerStateIsRefusedNamingTheField) {
  EvolutionRun(LearnerRun(2), Dir("a"), StartMode::kNew, Threads(2)).Run();
  const std::string path = RunFiles(Dir("a")).checkpoint;
  nlohmann::json checkpoint = nlohmann::json::parse(ReadFile(path));
  checkpoint["learner"]["unexpected"] = 1;
  std::ofstream(path) << checkpoint.dump();
  try {
    EvolutionRun(LearnerRun(3), Dir("a"), StartMode::kResume, Threads(2));
    FAIL() << "resumed with a damaged learner state";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path + ": "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("learner.unexpected"), std::string::npos) << e.what();
  }
}

TEST_F(RunTest, TheGasRunsDoNotNameTheirLearner) {
  EvolutionRun(SmallRun(ScaffoldCase::kFree, 1), Dir("a"), StartMode::kNew, Threads(2)).Run();
  EXPECT_FALSE(nlohmann::json::parse(ReadFile(RunFiles(Dir("a")).config)).contains("learner"));
  EXPECT_FALSE(nlohmann::json::parse(ReadFile(RunFiles(Dir("a")).checkpoint)).contains("learner"));
  RunConfig cmaes = SmallRun(ScaffoldCase::kFree, 2);
  cmaes.learner = "cmaes";
  EXPECT_THROW(EvolutionRun(cmaes, Dir("a"), StartMode::kResume, Threads(2)), std::runtime_error);
}

TEST_F(RunTest, AnUnwritableDirectoryIsAClearError) {
  std::ofstream(Dir("file")) << "x";
  try {
    EvolutionRun(SmallRun(), Dir("file") + "/run", StartMode::kNew, Threads(1));
    FAIL();
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("file/run"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace walkers
