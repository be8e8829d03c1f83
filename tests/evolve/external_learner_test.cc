#include "evolve/external_learner.h"

#include <fstream>
#include <functional>
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

// An outside program driving a run of the external learner, as the Python
// module's walkers.Run drives one: every child a mutant of the fittest genome
// it was told, from a stream of the generation's; its state is that genome,
// its fitness and how many generations it was told, so that a resumed run
// proposes as the uninterrupted one only if the state came back.
class MutantSource {
 public:
  // Its state, as the run was resumed with it (null: a fresh run).
  void Load(const nlohmann::json& state) {
    if (state.is_null()) return;
    told_ = state.at("told").get<int>();
    best_ = state.at("best").get<double>();
    parent_.genes = state.at("parent").get<decltype(parent_.genes)>();
  }
  // Drives the run's remaining generations, calling after(generation) after each.
  void Drive(EvolutionRun& run, const std::function<void(int)>& after = nullptr) {
    const auto& learner = dynamic_cast<const ExternalLearner&>(run.learner());
    while (!run.done()) {
      const BreedingInputs in = run.BeginGeneration();
      EXPECT_EQ(in.generation, told_) << "asked before it was told the generation before";
      Random rng(7, static_cast<std::uint64_t>(in.generation), 0);
      std::vector<Genome> genomes;
      for (int c = 0; c < run.config().ga.population + extra_children; ++c) {
        genomes.push_back(Mutate(parent_, in.body_ceiling, in.rules, &rng));
      }
      const EvaluatedChildren evaluated = run.EvaluateChildren(in, learner.Children(in, genomes));
      for (const Individual& child : evaluated.children) {
        if (child.fitness() > best_) {
          best_ = child.fitness();
          parent_ = child.genome;
        }
      }
      ++told_;
      run.FinishGeneration(in, evaluated, ExternalLearner::StateOf(State()));
      if (after) after(in.generation);
    }
  }
  virtual nlohmann::json State() const { return {{"told", told_}, {"best", best_}, {"parent", parent_.genes}}; }
  virtual ~MutantSource() = default;

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
  // a run in `dir` of the external learner; `source` takes the state the run
  // was resumed with
  std::unique_ptr<EvolutionRun> Start(const std::string& dir, StartMode mode, int generations, MutantSource* source) {
    auto run = std::make_unique<EvolutionRun>(ExternalRun(generations), dir, mode, Threads(2));
    source->Load(dynamic_cast<const ExternalLearner&>(run->learner()).restored_state());
    return run;
  }
};

TEST_F(ExternalLearnerTest, KilledAndResumedEndsIdenticalToAnUninterruptedRun) {
  MutantSource whole_source;
  whole_source.Drive(*Start(Dir("whole"), StartMode::kNew, 5, &whole_source));
  // the proposals are the source's, named by the learner
  const std::string rows = ReadFile(RunFiles(Dir("whole")).evaluations);
  EXPECT_NE(rows.find("\n3,0,external,"), std::string::npos) << rows.substr(0, 400);

  struct Killed {};
  MutantSource killed_source;
  try {
    killed_source.Drive(*Start(Dir("killed"), StartMode::kNew, 5, &killed_source), [](int generation) {
      if (generation == 2) throw Killed{};
    });
  } catch (const Killed&) {
  }
  const nlohmann::json checkpoint = nlohmann::json::parse(ReadFile(RunFiles(Dir("killed")).checkpoint));
  EXPECT_EQ(checkpoint.at("learner").at("state").at("told"), 3) << "the source's state is in the checkpoint";

  MutantSource resumed_source;  // knows nothing until the run gives it its state
  auto resumed = Start(Dir("killed"), StartMode::kResume, 5, &resumed_source);
  EXPECT_EQ(resumed->completed_generations(), 3);
  resumed_source.Drive(*resumed);
  ExpectSameRun(Dir("whole"), Dir("killed"));
}

TEST_F(ExternalLearnerTest, ANullStateResumesAndADamagedOneIsRefusedNamingTheField) {
  struct NoState : MutantSource {
    nlohmann::json State() const override { return nullptr; }
  } source;
  source.Drive(*Start(Dir("a"), StartMode::kNew, 1, &source));
  EXPECT_EQ(nlohmann::json::parse(ReadFile(RunFiles(Dir("a")).checkpoint)).at("learner"),
            nlohmann::json({{"state", nullptr}}));
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
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("learner.stat"), std::string::npos) << e.what();
  }
}

TEST_F(ExternalLearnerTest, ItsRunIsDrivenFromOutsideNeverByItsOwnLoop) {
  EvolutionRun run(ExternalRun(2), Dir("a"), StartMode::kNew, Threads(1));
  try {
    run.Run();
    FAIL() << "an external learner proposed by itself";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("walkers.Run"), std::string::npos) << e.what();
  }
  EXPECT_EQ(run.completed_generations(), 0);
}

TEST_F(ExternalLearnerTest, ProposalsNotOnePerChildAreRefused) {
  MutantSource source;
  source.extra_children = 1;
  try {
    source.Drive(*Start(Dir("a"), StartMode::kNew, 2, &source));
    FAIL() << "took 9 proposals for 8 children";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("proposed 9 genomes for 8 children"), std::string::npos) << e.what();
  }
}

TEST_F(ExternalLearnerTest, TheLearnerGivenMustBeTheRunsKind) {
  auto learner = std::make_unique<ExternalLearner>(LearnerByName("external"), 8);
  EXPECT_THROW(EvolutionRun(SmallRun(), Dir("a"), StartMode::kNew, Threads(1), std::move(learner)),
               std::logic_error);
}

TEST(ExternalLearnerListTest, NeitherEvolveNorReproduceRunsIt) {
  for (const std::string& name : BuiltInLearnerNames()) EXPECT_NE(name, "external");
  ReproductionConfig config;
  config.learners = {"ga", "external"};
  try {
    config.Validate();
    FAIL() << "a reproduction took the external learner";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("walkers.Run"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace walkers
