#include "evolve/evaluator.h"

#include <algorithm>
#include <string>

namespace walkers {

SlotEvaluator::SlotEvaluator(std::vector<Slot> slots) {
  for (Slot& slot : slots) threads_.emplace_back([this, s = std::move(slot)] { Serve(s); });
}

SlotEvaluator::~SlotEvaluator() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  work_.notify_all();
  for (std::thread& t : threads_) t.join();
}

void SlotEvaluator::Serve(const Slot& slot) {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    work_.wait(lock, [this] { return stopping_ || !queue_.empty(); });
    if (queue_.empty()) return;  // stopping, nothing left
    const Queued next = queue_.top();
    queue_.pop();
    lock.unlock();
    std::exception_ptr error;
    try {
      slot(next.task);
    } catch (...) {
      error = std::current_exception();
    }
    lock.lock();
    if (error && !next.batch->error) next.batch->error = error;
    --next.batch->remaining;
    done_.notify_all();
  }
}

void SlotEvaluator::EvaluateAll(const std::vector<EvaluationTask>& tasks) {
  if (tasks.empty()) return;
  Batch batch;
  std::unique_lock<std::mutex> lock(mutex_);
  batch.remaining = tasks.size();
  for (const EvaluationTask& task : tasks) queue_.push({task, next_order_++, &batch});
  work_.notify_all();
  done_.wait(lock, [&] { return batch.remaining == 0; });
  if (batch.error) std::rethrow_exception(batch.error);
}

std::unique_ptr<Evaluator> MakeThreadEvaluator(int threads) {
  const auto evaluate = [](const EvaluationTask& task) {
    *task.result = Evaluate(*task.genome, *task.preset, *task.settings);
  };
  return std::make_unique<SlotEvaluator>(std::vector<SlotEvaluator::Slot>(std::max(1, threads), evaluate));
}

void EvaluateIndividuals(Evaluator& evaluator, std::vector<Individual>* individuals, const Preset& preset,
                         const EvaluationSettings& settings, const std::vector<double>& expected_costs) {
  std::vector<EvaluationTask> tasks;
  for (std::size_t i = 0; i < individuals->size(); ++i) {
    Individual& ind = (*individuals)[i];
    tasks.push_back({&ind.genome, &preset, &settings, &ind.result,
                     i < expected_costs.size() ? expected_costs[i] : 0.0});
  }
  evaluator.EvaluateAll(tasks);
}

double ExpectedCost(const Individual& child, const Archive& archive) {
  double cost = 0;
  for (const Lineage::Parent& parent : child.lineage.parents) {
    for (const Individual& member : archive.members()) {
      if (member.generation == parent.generation && member.child == parent.child) {
        cost = std::max(cost, static_cast<double>(member.result.integrator_stats.steps));
      }
    }
  }
  return cost;
}

}  // namespace walkers
