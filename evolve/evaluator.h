// Where evaluations are made: a run hands its generation's children to an
// Evaluator and gets their results back. Implementations differ in where the
// work goes (worker threads of this process, MPI ranks: evolve/mpi_evaluator.h),
// never in what it computes: a result depends only on its task.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <queue>
#include <thread>
#include <vector>

#include "control/evaluation.h"
#include "control/genome.h"
#include "control/preset.h"
#include "evolve/individual.h"

namespace walkers {

// One evaluation to make: what Evaluate needs, and where its result goes.
struct EvaluationTask {
  const Genome* genome = nullptr;
  const Preset* preset = nullptr;
  const EvaluationSettings* settings = nullptr;
  EvaluationResult* result = nullptr;
  // what it is expected to cost, in any unit (CVODE steps, say): the costly
  // are handed out first, so that a batch does not wait for a long one
  // started last; 0 when unknown
  double expected_cost = 0;
};

class Evaluator {
 public:
  virtual ~Evaluator() = default;
  // Evaluates every task, writing task.result, and returns when all are done.
  // Several threads may call it at once (runs side by side share one
  // evaluator); their tasks share its workers. Throws std::runtime_error when
  // a worker fails (an MPI rank that stops answering, say).
  virtual void EvaluateAll(const std::vector<EvaluationTask>& tasks) = 0;
  // How many evaluations it makes at once.
  virtual int slots() const = 0;
};

// An evaluator of slots, each served by a thread of its own that takes the
// most costly task waiting (of any caller's) and makes it with its slot's
// function: Evaluate itself for a thread of this process, a message to a rank
// and its answer for an MPI rank.
class SlotEvaluator : public Evaluator {
 public:
  using Slot = std::function<void(const EvaluationTask&)>;
  explicit SlotEvaluator(std::vector<Slot> slots);
  // stops and joins the slots' threads (no call may be under way)
  ~SlotEvaluator() override;
  SlotEvaluator(const SlotEvaluator&) = delete;
  SlotEvaluator& operator=(const SlotEvaluator&) = delete;

  void EvaluateAll(const std::vector<EvaluationTask>& tasks) override;
  int slots() const override { return static_cast<int>(threads_.size()); }

 private:
  struct Batch {
    std::size_t remaining = 0;
    std::exception_ptr error;  // the first failure of one of its tasks
  };
  struct Queued {
    EvaluationTask task;
    std::uint64_t order;  // first come, first served at equal cost
    Batch* batch;
  };
  struct LessUrgent {
    bool operator()(const Queued& a, const Queued& b) const {
      if (a.task.expected_cost != b.task.expected_cost) return a.task.expected_cost < b.task.expected_cost;
      return a.order > b.order;
    }
  };
  void Serve(const Slot& slot);

  std::mutex mutex_;
  std::condition_variable work_;  // a task is waiting, or the end
  std::condition_variable done_;  // a task is done
  std::priority_queue<Queued, std::vector<Queued>, LessUrgent> queue_;
  std::uint64_t next_order_ = 0;
  bool stopping_ = false;
  std::vector<std::thread> threads_;
};

// Evaluations on `threads` threads of this process, started once and kept
// until destruction.
std::unique_ptr<Evaluator> MakeThreadEvaluator(int threads);

// Evaluates the individuals' genomes into their results.
void EvaluateIndividuals(Evaluator& evaluator, std::vector<Individual>* individuals, const Preset& preset,
                         const EvaluationSettings& settings, const std::vector<double>& expected_costs = {});

// What a child is expected to cost: the most CVODE steps of its parents in
// the archive (a child walks much as its parents do); 0 when none of them is
// there (the first generation, another learner's children).
double ExpectedCost(const Individual& child, const Archive& archive);

}  // namespace walkers
