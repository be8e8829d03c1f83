#include "evolve/external_learner.h"

#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "evolve/random.h"
#include "evolve/reproduction.h"
#include "evolve/run.h"
#include "tests/evolve/individuals.h"
#include "tests/evolve/small_runs.h"
#include "tests/temp_dir_test.h"

namespace walkers {
namespace {
using testing::ExpectSameRun;
using testing::SmallRun;
using testing::Threads;

// An outside program as the external learner sees it: every child a mutant of
// the fittest genome it was told, from a stream of the generation's; its state
// is that genome, its fitness and how many generations it was told, so that
// a resumed run proposes as the uninterrupted one only if the state came back.
class MutantSource : public ProposalSource {
 public:
  std::vector<Genome> Propose(const BreedingInputs& in, int children) override {
    EXPECT_EQ(in.generation, told_) << "asked before it was told the generation before";
    Random rng(7, static_cast<std::uint64_t>(in.generation), 0);
    std::vector<Genome> genomes;
    for (int c = 0; c < children + extra_children; ++c) {
      genomes.push_back(Mutate(parent_, in.body_ceiling, in.rules, &rng));
    }
    return genomes;
  }
  void Tell(const BreedingInputs&, const std::vector<Individual>& evaluated) override {
    for (const Individual& child : evaluated) {
      if (child.fitness() > best_) {
        best_ = child.fitness();
        parent_ = child.genome;
      }
    }
    ++told_;
  }
  nlohmann::json State() override { return {{"told", told_}, {"best", best_}, {"parent", parent_.genes}}; }
  void Load(const nlohmann::json& state) {
    if (state.is_null()) return;
    told_ = state.at("told").get<int>();
    best_ = state.at("best").get<double>();
    parent_.genes = state.at("parent").get<decltype(parent_.genes)>();
  }

  int extra_children = 0;  // proposals beyond the children asked for

 private:
  Genome parent_ = DefaultGenome();
  double best_ = std::numeric_limits<double>::lowest();
  int told_ = 0;
};

RunConfig ExternalRun(int generations) {
  RunConfig config = SmallRun(ScaffoldCase::kPerformance, generations);
  config.learner = "external";
  return config;
}

class ExternalLearnerTest : public TempDirTest {
 protected:
  // a run in `dir` of the external learner whose proposals come from `source`,
  // which takes the state the run was resumed with
  std::unique_ptr<EvolutionRun> Start(const std::string& dir, StartMode mode, int generations, MutantSource* source) {
    const LearnerSpec& spec = LearnerByName("external");
    auto learner = std::make_unique<ExternalLearner>(spec, ExternalRun(generations).ga.population, source);
    const ExternalLearner* external = learner.get();
    auto run = std::make_unique<EvolutionRun>(ExternalRun(generations), dir, mode, Threads(2), std::move(learner));
    source->Load(external->restored_state());
    return run;
  }
};

TEST_F(ExternalLearnerTest, KilledAndResumedEndsIdenticalToAnUninterruptedRun) {
  MutantSource whole_source;
  Start(Dir("whole"), StartMode::kNew, 5, &whole_source)->Run();
  // the proposals are the source's, named by the learner
  const std::string rows = ReadFile(RunFiles(Dir("whole")).evaluations);
  EXPECT_NE(rows.find("\n3,0,external,"), std::string::npos) << rows.substr(0, 400);

  struct Killed {};
  MutantSource killed_source;
  try {
    Start(Dir("killed"), StartMode::kNew, 5, &killed_source)->Run([](const GenerationSummary& s) {
      if (s.generation == 2) throw Killed{};
    });
  } catch (const Killed&) {
  }
  const nlohmann::json checkpoint = nlohmann::json::parse(ReadFile(RunFiles(Dir("killed")).checkpoint));
  EXPECT_EQ(checkpoint.at("learner").at("state").at("told"), 3) << "the source's state is in the checkpoint";

  MutantSource resumed_source;  // knows nothing until the run gives it its state
  auto resumed = Start(Dir("killed"), StartMode::kResume, 5, &resumed_source);
  EXPECT_EQ(resumed->completed_generations(), 3);
  resumed->Run();
  ExpectSameRun(Dir("whole"), Dir("killed"));
}

TEST_F(ExternalLearnerTest, ANullStateResumesAndADamagedOneIsRefusedNamingTheField) {
  struct NoState : MutantSource {
    nlohmann::json State() override { return nullptr; }
  } source;
  Start(Dir("a"), StartMode::kNew, 1, &source)->Run();
  MutantSource resumed;
  auto run = Start(Dir("a"), StartMode::kResume, 2, &resumed);
  EXPECT_TRUE(dynamic_cast<const ExternalLearner&>(run->learner()).restored_state().is_null());
  run.reset();
  const std::string path = RunFiles(Dir("a")).checkpoint;
  nlohmann::json checkpoint = nlohmann::json::parse(ReadFile(path));
  checkpoint["learner"] = {{"stat", 1}};
  std::ofstream(path) << checkpoint.dump();
  try {
    Start(Dir("a"), StartMode::kResume, 2, &resumed);
    FAIL() << "resumed with a damaged learner state";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("learner.stat"), std::string::npos) << e.what();
  }
}

TEST_F(ExternalLearnerTest, ARunWithoutItsOutsideProgramIsAClearError) {
  EvolutionRun run(ExternalRun(2), Dir("a"), StartMode::kNew, Threads(1));
  try {
    run.Run();
    FAIL() << "an external learner proposed without a source";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("walkers.Run"), std::string::npos) << e.what();
  }
}

TEST_F(ExternalLearnerTest, ProposalsNotOnePerChildAreRefused) {
  MutantSource source;
  source.extra_children = 1;
  try {
    Start(Dir("a"), StartMode::kNew, 2, &source)->Run();
    FAIL() << "took 9 proposals for 8 children";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("proposed 9 genomes for 8 children"), std::string::npos) << e.what();
  }
}

TEST_F(ExternalLearnerTest, TheLearnerGivenMustBeTheRunsKind) {
  MutantSource source;
  auto learner = std::make_unique<ExternalLearner>(LearnerByName("external"), 8, &source);
  EXPECT_THROW(EvolutionRun(SmallRun(), Dir("a"), StartMode::kNew, Threads(1), std::move(learner)),
               std::invalid_argument);
}

TEST(ExternalLearnerListTest, NeitherEvolveNorReproduceRunsIt) {
  for (const std::string& name : BuiltInLearnerNames()) EXPECT_NE(name, "external");
  ReproductionConfig config;
  config.learners = {"ga", "external"};
  try {
    config.Validate();
    FAIL() << "a reproduction took the external learner";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("walkers.Run"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace walkers
