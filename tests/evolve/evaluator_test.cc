#include "evolve/evaluator.h"

#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "tests/evolve/individuals.h"

namespace walkers {
namespace {

using testing::WithFitness;

// A slot that "evaluates" a genome by copying its kx gene into the fitness,
// and records the order in which it took the tasks.
struct RecordingSlot {
  std::mutex* mutex;
  std::vector<double>* taken;
  void operator()(const EvaluationTask& task) const {
    task.result->fitness = (*task.genome)[kKx];
    std::lock_guard<std::mutex> lock(*mutex);
    taken->push_back(task.expected_cost);
  }
};

TEST(SlotEvaluatorTest, HandsOutTheCostliestFirstAndFillsEveryResult) {
  std::mutex mutex;
  std::vector<double> taken;
  SlotEvaluator evaluator({RecordingSlot{&mutex, &taken}});
  std::vector<Individual> children;
  for (int c = 0; c < 6; ++c) children.push_back(WithFitness(1, c, -1.0));
  const Preset preset = OriginalPreset();
  const EvaluationSettings settings;
  EvaluateIndividuals(evaluator, &children, preset, settings, {3, 0, 7, 3, 1, 0});
  for (const Individual& c : children) EXPECT_EQ(c.fitness(), c.genome[kKx]);
  // one slot: strictly by cost, equal costs in the order given
  EXPECT_EQ(taken, (std::vector<double>{7, 3, 3, 1, 0, 0}));
}

TEST(SlotEvaluatorTest, ServesSeveralCallersAtOnceAndReportsAFailingTask) {
  std::mutex mutex;
  std::vector<double> taken;
  SlotEvaluator evaluator({RecordingSlot{&mutex, &taken}, RecordingSlot{&mutex, &taken}});
  EXPECT_EQ(evaluator.slots(), 2);
  const Preset preset = OriginalPreset();
  const EvaluationSettings settings;
  std::vector<std::vector<Individual>> batches(4);
  std::vector<std::thread> callers;
  for (int b = 0; b < 4; ++b) {
    for (int c = 0; c < 16; ++c) batches[b].push_back(WithFitness(b, c, -1.0));
    callers.emplace_back([&, b] { EvaluateIndividuals(evaluator, &batches[b], preset, settings); });
  }
  for (std::thread& t : callers) t.join();
  for (const auto& batch : batches) {
    for (const Individual& c : batch) EXPECT_EQ(c.fitness(), c.genome[kKx]);
  }
  EXPECT_EQ(taken.size(), 64u);

  SlotEvaluator failing({[](const EvaluationTask&) { throw std::runtime_error("rank 2 is gone"); }});
  std::vector<Individual> children = {WithFitness(0, 0, -1.0)};
  try {
    EvaluateIndividuals(failing, &children, preset, settings);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "rank 2 is gone");
  }
}

TEST(ThreadEvaluatorTest, GivesWhatEvaluateGives) {
  std::vector<Individual> children = {WithFitness(0, 0, -1.0), WithFitness(0, 1, -1.0)};
  children[1].genome = DefaultGenome();
  const Preset preset = OriginalPreset();
  EvaluationSettings settings;
  settings.duration = 0.5;
  EvaluateIndividuals(*MakeThreadEvaluator(2), &children, preset, settings);
  for (const Individual& c : children) {
    const EvaluationResult direct = Evaluate(c.genome, preset, settings);
    EXPECT_EQ(c.result.fitness, direct.fitness);
    EXPECT_EQ(c.result.integrator_stats.steps, direct.integrator_stats.steps);
    EXPECT_GT(c.result.integrator_stats.steps, 0);
  }
}

TEST(ExpectedCostTest, IsTheCostliestParentInTheArchive) {
  Archive archive(4);
  std::vector<Individual> members = {WithFitness(2, 0, 5.0), WithFitness(2, 1, 4.0), WithFitness(3, 5, 3.0)};
  members[0].result.integrator_stats.steps = 100;
  members[1].result.integrator_stats.steps = 900;
  members[2].result.integrator_stats.steps = 300;
  archive.Merge(members);
  Individual child = WithFitness(4, 0, -1.0);
  child.lineage = Lineage::Of({{2, 0}, {3, 5}});
  EXPECT_EQ(ExpectedCost(child, archive), 300.0);
  child.lineage = Lineage::Of({{2, 1}});
  EXPECT_EQ(ExpectedCost(child, archive), 900.0);
  // drawn again: a mutant of the proposal, still its parent's child
  child.lineage.admissions.push_back(Lineage::Admission::kRedrawn);
  EXPECT_EQ(ExpectedCost(child, archive), 900.0);
  for (const Lineage& unknown : {Lineage{}, Lineage::ProposedBy("cmaes"), Lineage::Of({{7, 7}})}) {
    child.lineage = unknown;
    EXPECT_EQ(ExpectedCost(child, archive), 0.0) << unknown.Text();
  }
}

}  // namespace
}  // namespace walkers
