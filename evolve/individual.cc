#include "evolve/individual.h"

#include <algorithm>

namespace walkers {

bool Fitter(const Individual& a, const Individual& b) {
  if (a.fitness() != b.fitness()) return a.fitness() > b.fitness();
  if (a.generation != b.generation) return a.generation < b.generation;
  return a.child < b.child;
}

void Archive::Merge(const std::vector<Individual>& children) {
  members_.insert(members_.end(), children.begin(), children.end());
  std::stable_sort(members_.begin(), members_.end(), Fitter);
  if (static_cast<int>(members_.size()) > capacity_) members_.resize(capacity_);
}

double Archive::AverageOfBest(int n) const {
  const int count = std::min<int>(n, members_.size());
  if (count == 0) return 0.0;
  double sum = 0.0;
  for (int i = 0; i < count; ++i) sum += members_[i].fitness();
  return sum / count;
}

double Archive::Mean() const { return AverageOfBest(static_cast<int>(members_.size())); }

}  // namespace walkers
