#include "evolve/genetic_algorithm.h"

#include <algorithm>
#include <atomic>
#include <numeric>
#include <stdexcept>
#include <thread>

#include "control/input_file.h"
#include "evolve/random.h"

namespace walkers {
namespace {

constexpr int kMaxDraws = 100000;

// a mutant of `make()` that no earlier individual matches at 3 significant figures
template <typename MakeChild>
Genome Unseen(const MakeChild& make, std::set<GenomeKey>* seen) {
  for (int draw = 0; draw < kMaxDraws; ++draw) {
    Genome g = make();
    if (seen->insert(KeyOf(g)).second) return g;
  }
  throw std::runtime_error("no new genome in " + std::to_string(kMaxDraws) + " draws: every mutant was a duplicate");
}

// Parents drawn from a shuffled archive without replacement; the archive is
// shuffled again whenever `per_shuffle` children have drawn from it.
class ParentDraw {
 public:
  ParentDraw(int archive_size, Random rng) : size_(archive_size), rng_(std::move(rng)) {}
  int Next() {
    if (pool_.empty()) {
      pool_.resize(size_);
      std::iota(pool_.begin(), pool_.end(), 0);
      rng_.Shuffle(&pool_);
    }
    const int parent = pool_.back();
    pool_.pop_back();
    return parent;
  }

 private:
  int size_;
  Random rng_;
  std::vector<int> pool_;
};

}  // namespace

bool Fitter(const Individual& a, const Individual& b) {
  if (a.fitness() != b.fitness()) return a.fitness() > b.fitness();
  if (a.generation != b.generation) return a.generation < b.generation;
  return a.child < b.child;
}

void GeneticAlgorithmConfig::Validate() const {
  RequireInRange("population", population, kMinPopulation, kMaxPopulation);
  RequireInRange("archive_size", archive_size, kMinArchive, kMaxArchive);
  RequireInRange("mutation_children", mutation_children, 0, population);
  RequireInRange("mutation_probability", mutation_probability, {0.0, 1.0, true});
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

std::vector<Individual> Breed(const GeneticAlgorithmConfig& config, const BreedingInputs& in, const Archive& archive,
                              std::set<GenomeKey>* seen) {
  std::vector<Individual> children(config.population);
  for (int c = 0; c < config.population; ++c) {
    children[c].generation = in.generation;
    children[c].child = c;
  }

  if (in.generation == 0) {
    // the default genome and its mutants
    const Genome initial = DefaultGenome();
    children[0].genome = initial;
    seen->insert(KeyOf(initial));
    for (int c = 1; c < config.population; ++c) {
      Random rng(in.seed, 0, c);
      children[c].genome = Unseen([&] { return Mutate(initial, in.body_ceiling, in.rules, &rng); }, seen);
      children[c].parents = "0/0";
    }
    return children;
  }

  const std::vector<Individual>& parents = archive.members();
  if (parents.size() < 2) throw std::runtime_error("breeding needs an archive of at least 2 individuals");

  // mutation children: one parent each
  ParentDraw mutation_parents(static_cast<int>(parents.size()),
                              Random(in.seed, in.generation, Random::kMutationParents));
  for (int c = 0; c < config.mutation_children; ++c) {
    const Individual& p = parents[mutation_parents.Next()];
    Random rng(in.seed, in.generation, c);
    children[c].genome = Unseen([&] { return Mutate(p.genome, in.body_ceiling, in.rules, &rng); }, seen);
    children[c].parents = p.id();
  }
  // crossover children: the mean of two parents, then mutated
  ParentDraw crossover_parents(static_cast<int>(parents.size()),
                               Random(in.seed, in.generation, Random::kCrossoverParents));
  for (int c = config.mutation_children; c < config.population; ++c) {
    const Individual& a = parents[crossover_parents.Next()];
    const Individual& b = parents[crossover_parents.Next()];
    const Genome mean = Crossover(a.genome, b.genome);
    Random rng(in.seed, in.generation, c);
    children[c].genome = Unseen([&] { return Mutate(mean, in.body_ceiling, in.rules, &rng); }, seen);
    children[c].parents = a.id() + "+" + b.id();
  }
  return children;
}

void EvaluateAll(std::vector<Individual>* individuals, const Preset& preset, const EvaluationSettings& settings,
                 int threads) {
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t i = next++; i < individuals->size(); i = next++) {
      (*individuals)[i].result = Evaluate((*individuals)[i].genome, preset, settings);
    }
  };
  const int n = std::max(1, std::min<int>(threads, static_cast<int>(individuals->size())));
  std::vector<std::thread> pool;
  for (int t = 1; t < n; ++t) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
}

}  // namespace walkers
