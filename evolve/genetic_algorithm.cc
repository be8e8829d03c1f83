#include "evolve/genetic_algorithm.h"

#include <numeric>
#include <stdexcept>

#include "files/errors.h"
#include "files/input_file.h"

namespace walkers {
namespace {

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

void GeneticAlgorithmConfig::Validate(const std::string& source) const {
  RequireInRange(FieldOf(source, "population"), population, kMinPopulation, kMaxPopulation);
  RequireInRange(FieldOf(source, "archive_size"), archive_size, kMinArchive, kMaxArchive);
  RequireInRange(FieldOf(source, "mutation_children"), mutation_children, 0, population);
  RequireInRange(FieldOf(source, "mutation_probability"), mutation_probability, {0.0, 1.0, true});
}

std::vector<Individual> GeneticAlgorithm::Propose(const BreedingInputs& in, const Archive& archive) {
  std::vector<Individual> children(config_.population);
  draws_.clear();
  draws_.reserve(config_.population);
  for (int c = 0; c < config_.population; ++c) {
    children[c].generation = in.generation;
    children[c].child = c;
  }
  // child c's first draw from `base`, on its own stream
  const auto draw = [&](int c, const Genome& base) {
    draws_.push_back({base, Random(in.seed, in.generation, c)});
    children[c].genome = Mutate(base, in.body_ceiling, in.rules, &draws_.back().rng);
  };

  if (in.generation == 0) {
    // the default genome and its mutants
    const Genome initial = DefaultGenome();
    children[0].genome = initial;
    draws_.push_back({initial, Random(in.seed, 0, 0)});
    for (int c = 1; c < config_.population; ++c) {
      draw(c, initial);
      children[c].lineage = Lineage::Of({{0, 0}});
    }
    return children;
  }

  const std::vector<Individual>& parents = archive.members();
  WALKERS_CHECK(parents.size() >= 2, "breeding needs an archive of at least 2 individuals, not " +
                                         std::to_string(parents.size()));

  // mutation children: one parent each
  ParentDraw mutation_parents(static_cast<int>(parents.size()),
                              Random(in.seed, in.generation, Random::kMutationParents));
  for (int c = 0; c < config_.mutation_children; ++c) {
    const Individual& p = parents[mutation_parents.Next()];
    draw(c, p.genome);
    children[c].lineage = Lineage::Of({{p.generation, p.child}});
  }
  // crossover children: the mean of two parents, then mutated
  ParentDraw crossover_parents(static_cast<int>(parents.size()),
                               Random(in.seed, in.generation, Random::kCrossoverParents));
  for (int c = config_.mutation_children; c < config_.population; ++c) {
    const Individual& a = parents[crossover_parents.Next()];
    const Individual& b = parents[crossover_parents.Next()];
    draw(c, Crossover(a.genome, b.genome));
    children[c].lineage = Lineage::Of({{a.generation, a.child}, {b.generation, b.child}});
  }
  return children;
}

void GeneticAlgorithm::Redraw(const BreedingInputs& in, const Genome&, Random*, Individual* child) {
  Draw& d = draws_.at(child->child);
  child->genome = Mutate(d.base, in.body_ceiling, in.rules, &d.rng);
}

std::unique_ptr<Learner> MakeGeneticAlgorithm(const LearnerSpec& spec, const GeneticAlgorithmConfig& config,
                                              std::uint64_t) {
  return std::make_unique<GeneticAlgorithm>(spec, config);
}

std::vector<Individual> Breed(const GeneticAlgorithmConfig& config, const BreedingInputs& in, const Archive& archive,
                              std::set<GenomeKey>* seen) {
  GeneticAlgorithm ga(DefaultLearner(), config);
  std::vector<Individual> children = ga.Propose(in, archive);
  AdmitChildren(ga, in, &children, seen);
  return children;
}

}  // namespace walkers
