#include "evolve/pagmo_learners.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <boost/crc.hpp>
#include <nlohmann/json.hpp>
#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/cmaes.hpp>
#include <pagmo/algorithms/pso_gen.hpp>
#include <pagmo/algorithms/sade.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>
#include <pagmo/s11n.hpp>

#include "evolve/genetic_algorithm.h"
#include "files/errors.h"
#include "files/input_file.h"
#include "files/number_text.h"

namespace walkers {

const char* const kCmaesAbout =
    "pagmo2's cmaes: step size 0.5 of the bounds' width at the start, its learning rates automatic, samples "
    "clamped into the bounds; mean, covariance, paths and step size kept from generation to generation";
const char* const kSadeAbout =
    "pagmo2's sade: DE/rand/1/exp with jDE's self-adaptation of F and CR, kept from generation to generation";
const char* const kParticleSwarmAbout =
    "pagmo2's pso_gen: Clerc's constriction (0.7298, eta1 = eta2 = 2.05), velocities up to 0.5 of the bounds' "
    "width, a ring of 4 neighbours; velocities kept from generation to generation, each particle starting a "
    "generation at its best position";

namespace {

using pagmo::vector_double;

// Answers the fitness calls of pagmo's algorithm during one generation with
// the objective it minimises: -fitness (paper eq. 6).
class Oracle {
 public:
  virtual ~Oracle() = default;
  virtual double Objective(const vector_double& x) = 0;
};

// The walker as pagmo's problem (its user-defined problem): the genome's
// genes, bounded as this generation's children are; the run evaluates them,
// the oracle answers.
struct WalkerProblem {
  vector_double lb, ub;
  Oracle* oracle = nullptr;

  vector_double fitness(const vector_double& x) const { return {oracle->Objective(x)}; }
  std::pair<vector_double, vector_double> get_bounds() const { return {lb, ub}; }
  std::string get_name() const { return "scaffolded bipedal walker"; }
};

// While the algorithm is asked what to evaluate: records the genomes it asks
// for and answers 0; what the answers make of the algorithm is thrown away.
class Recorder : public Oracle {
 public:
  double Objective(const vector_double& x) override {
    asked.push_back(x);
    return 0.0;
  }
  std::vector<vector_double> asked;
};

// While the algorithm is told: the k-th call gets the k-th evaluation. With
// `proposals` (the generation as it was asked for), the k-th call must ask
// for the k-th proposal; without (a replay from a checkpoint), the calls are
// answered in order.
class Answers : public Oracle {
 public:
  Answers(const std::vector<vector_double>* proposals, std::vector<double> objectives, std::string what)
      : proposals_(proposals), objectives_(std::move(objectives)), what_(std::move(what)) {}

  double Objective(const vector_double& x) override {
    WALKERS_CHECK(next_ < objectives_.size() && (!proposals_ || x == (*proposals_)[next_]),
                  what_ + ": call " + std::to_string(next_) + " of the algorithm asked for another genome " +
                      "than it proposed; its generation is not one batch");
    return objectives_[next_++];
  }
  bool AllAnswered() const { return next_ == objectives_.size(); }

 private:
  const std::vector<vector_double>* proposals_;
  std::vector<double> objectives_;
  std::string what_;
  std::size_t next_ = 0;
};

// A member of pagmo's population: its decision vector (the genes) and objective.
struct Member {
  vector_double x;
  double objective = 0;
};

// What one generation told the algorithm: its bounds on halfBodyX and the
// children's objectives, in the order it asked for them.
struct Told {
  double body_ceiling = kBodyCeiling;
  std::vector<double> objectives;
};

// halfBodyX as any generation may bound it, the other genes by Table 1
GeneBounds WidestGeneBounds(int gene) {
  const GeneBounds low = ChildGeneBounds(gene, kMinimumCeiling), high = ChildGeneBounds(gene, kBodyCeiling);
  return {std::min(low.lo, high.lo), std::max(low.hi, high.hi)};
}

std::uint32_t Crc32(const std::string& text) {
  boost::crc_32_type crc;
  crc.process_bytes(text.data(), text.size());
  return crc.checksum();
}

// How a learner's state between generations reaches the checkpoint.
enum class Keeping {
  // pagmo's own serialisation of the algorithm (Boost text archive), and the
  // population: for cmaes and sade, whose serialisations hold everything
  // they adapt and their random engine
  kSerialised,
  // generation 0's population and what every later generation told the
  // algorithm, replayed on a fresh algorithm of the same seed: for pso_gen,
  // whose serialisation leaves out its velocities and its memory flag
  kReplayed,
};

// One of pagmo's population-based algorithms, run one generation at a time.
// Between generations its state is the algorithm (pagmo's object, with its
// random engine and whatever it adapts) and the population it returned. A
// generation is two calls of the algorithm on that state: one on a copy,
// whose fitness calls record what it would evaluate (the proposals, all
// decided before any evaluation in these generational algorithms), and,
// once the run has evaluated them, the real one, whose calls are answered
// with the evaluations. Generation 0 is the GA's.
class PagmoLearner : public Learner {
 public:
  PagmoLearner(const LearnerSpec& spec, pagmo::algorithm algorithm, Keeping keeping, const GeneticAlgorithmConfig& ga,
               std::uint64_t seed)
      : Learner(spec),
        fresh_algorithm_(algorithm),
        algorithm_(std::move(algorithm)),
        keeping_(keeping),
        first_generation_(DefaultLearner(), ga),
        population_size_(static_cast<std::size_t>(ga.population)),
        seed_(static_cast<unsigned>(seed)) {}

  std::vector<Individual> Propose(const BreedingInputs& in, const Archive& archive) override {
    if (in.generation == 0) return first_generation_.Propose(in, archive);
    WALKERS_CHECK(population_.size() == population_size_, What(in) + ": asked before it was told generation 0");
    pagmo::algorithm asking = algorithm_;
    Recorder recorder;
    asking.evolve(Population(in.body_ceiling, &recorder));
    WALKERS_CHECK(recorder.asked.size() == population_size_,
                  What(in) + ": the algorithm asked for " + std::to_string(recorder.asked.size()) +
                      " evaluations, not one per child (" + std::to_string(population_size_) + ")");
    proposals_ = std::move(recorder.asked);
    std::vector<Individual> children(population_size_);
    for (std::size_t c = 0; c < children.size(); ++c) {
      children[c].generation = in.generation;
      children[c].child = static_cast<int>(c);
      children[c].lineage = Lineage::ProposedBy(spec().name);
      children[c].genome = DefaultGenome();
      for (int k = 0; k < kNumGenes; ++k) children[c].genome.genes[k] = proposals_[c][k];
    }
    return children;
  }

  void Redraw(const BreedingInputs& in, const Genome& proposal, Random* rng, Individual* child) override {
    if (in.generation == 0) return first_generation_.Redraw(in, proposal, rng, child);
    Learner::Redraw(in, proposal, rng, child);
  }

  void Tell(const BreedingInputs& in, const std::vector<Individual>& evaluated) override {
    std::vector<double> objectives;
    for (const Individual& child : evaluated) {
      WALKERS_CHECK(std::isfinite(child.fitness()), What(in) + ": child " + child.id() + " has no finite fitness");
      objectives.push_back(-child.fitness());
    }
    if (in.generation == 0) {
      // the GA's generation 0 is the algorithm's first population
      population_.clear();
      for (std::size_t c = 0; c < evaluated.size(); ++c) {
        const auto& genes = evaluated[c].genome.genes;
        population_.push_back({vector_double(genes.begin(), genes.end()), objectives[c]});
      }
      initial_ = population_;
      told_.clear();
      return;
    }
    WALKERS_CHECK(evaluated.size() == proposals_.size(), What(in) + ": told " + std::to_string(evaluated.size()) +
                                                             " children, proposed " +
                                                             std::to_string(proposals_.size()));
    // each proposal gets the evaluation of the child that stood for it (the
    // proposal itself unless the GA's rules clamped or redrew it)
    Told told{in.body_ceiling, std::move(objectives)};
    Advance(told, &proposals_, What(in));
    if (keeping_ == Keeping::kReplayed) told_.push_back(std::move(told));
    proposals_.clear();
  }

  bool KeepsState() const override { return true; }

  // kSerialised: {"algorithm": pagmo's Boost text archive of it, "crc32":
  //   that text's, "population": [{"x": the 18 genes, "objective": -fitness}]}
  // kReplayed: {"initial": generation 0's population, as "population" above,
  //   "told": [{"body_ceiling": m, "objectives": [-fitness, ...]}, ...], one
  //   per generation from generation 1}
  nlohmann::json State() const override {
    if (keeping_ == Keeping::kReplayed) {
      nlohmann::json told = nlohmann::json::array();
      for (const Told& t : told_) told.push_back({{"body_ceiling", t.body_ceiling}, {"objectives", t.objectives}});
      return {{"initial", MembersJson(initial_)}, {"told", told}};
    }
    std::ostringstream text;
    {
      boost::archive::text_oarchive archive(text);
      archive << algorithm_;
    }
    return {{"algorithm", text.str()}, {"crc32", Crc32(text.str())}, {"population", MembersJson(population_)}};
  }

  void Restore(const nlohmann::json& state, int completed_generations, const std::string& source) override {
    const JsonFields f(state, source, "learner.");
    if (keeping_ == Keeping::kReplayed) {
      f.RequireOnly({"initial", "told"});
      std::vector<Member> initial = MembersFromJson(f, "initial");
      const nlohmann::json& told = f.Array("told");
      if (told.size() + 1 != static_cast<std::size_t>(completed_generations)) {
        f.Fail("told", "has " + std::to_string(told.size()) + " generations, not one per generation after the first (" +
                           std::to_string(completed_generations - 1) + ")");
      }
      std::vector<Told> history;
      for (std::size_t g = 0; g < told.size(); ++g) {
        const JsonFields t(told[g], source, "learner.told[" + std::to_string(g) + "].");
        t.RequireOnly({"body_ceiling", "objectives"});
        Told entry;
        entry.body_ceiling = t.Number("body_ceiling", {kMinimumCeiling, kBodyCeiling});
        const nlohmann::json& objectives = t.Array("objectives");
        if (objectives.size() != population_size_) {
          t.Fail("objectives", "has " + std::to_string(objectives.size()) + " values, not one per child (" +
                                   std::to_string(population_size_) + ")");
        }
        for (std::size_t c = 0; c < objectives.size(); ++c) {
          if (!objectives[c].is_number() || !std::isfinite(objectives[c].get<double>())) {
            t.Fail("objectives[" + std::to_string(c) + "]", "must be a finite number, got " + objectives[c].dump());
          }
          entry.objectives.push_back(objectives[c].get<double>());
        }
        history.push_back(std::move(entry));
      }
      // the algorithm again: a fresh one of the same seed, told it all again
      algorithm_ = fresh_algorithm_;
      population_ = initial;
      for (std::size_t g = 0; g < history.size(); ++g) {
        Advance(history[g], nullptr, source + ": replaying learner.told[" + std::to_string(g) + "]");
      }
      initial_ = std::move(initial);
      told_ = std::move(history);
      proposals_.clear();
      return;
    }
    f.RequireOnly({"algorithm", "crc32", "population"});
    // the algorithm: pagmo's own serialisation, read only when intact
    const std::string text = f.String("algorithm");
    if (f.Unsigned("crc32", 0xffffffffu) != Crc32(text)) {
      f.Fail("algorithm", "does not match its 'crc32': the learner's state is damaged");
    }
    pagmo::algorithm restored;
    try {
      std::istringstream in(text);
      boost::archive::text_iarchive archive(in);
      archive >> restored;
    } catch (const std::exception& e) {
      f.Fail("algorithm", std::string("is not pagmo's saved algorithm (") + e.what() + ")");
    }
    if (restored.get_name() != algorithm_.get_name()) {
      f.Fail("algorithm", "is pagmo's " + restored.get_name() + ", not this run's " + spec().name);
    }
    if (restored.get_extra_info() != algorithm_.get_extra_info()) {
      f.Fail("algorithm", "has other settings than this run's " + std::string(spec().name) + " (seed " +
                              std::to_string(seed_) + ")");
    }
    std::vector<Member> population = MembersFromJson(f, "population");
    algorithm_ = std::move(restored);
    population_ = std::move(population);
    proposals_.clear();
  }

 private:
  // "learner cmaes, generation 12"
  std::string What(const BreedingInputs& in) const {
    return std::string("learner ") + spec().name + ", generation " + std::to_string(in.generation);
  }

  // One generation of the algorithm on its state, its fitness calls answered
  // with `told`'s objectives (checked against `proposals` when given).
  void Advance(const Told& told, const std::vector<vector_double>* proposals, const std::string& what) {
    Answers answers(proposals, told.objectives, what);
    const pagmo::population evolved = algorithm_.evolve(Population(told.body_ceiling, &answers));
    WALKERS_CHECK(answers.AllAnswered(), what + ": the algorithm evaluated fewer children than it proposed");
    population_.clear();
    for (std::size_t i = 0; i < evolved.size(); ++i) population_.push_back({evolved.get_x()[i], evolved.get_f()[i][0]});
  }

  // the population the algorithm returned last, as pagmo's population of a
  // problem bounded as this generation's children are
  pagmo::population Population(double body_ceiling, Oracle* oracle) const {
    WalkerProblem walker;
    for (int k = 0; k < kNumGenes; ++k) {
      const GeneBounds b = ChildGeneBounds(k, body_ceiling);
      walker.lb.push_back(b.lo);
      walker.ub.push_back(b.hi);
    }
    walker.oracle = oracle;
    pagmo::population pop(pagmo::problem(walker), 0u, seed_);
    for (const Member& m : population_) pop.push_back(m.x, {m.objective});
    return pop;
  }

  static nlohmann::json MembersJson(const std::vector<Member>& members) {
    nlohmann::json out = nlohmann::json::array();
    for (const Member& m : members) out.push_back({{"x", m.x}, {"objective", m.objective}});
    return out;
  }

  // f's `key`: one member per child, each gene within the widest bounds any
  // generation gives it
  std::vector<Member> MembersFromJson(const JsonFields& f, const std::string& key) const {
    const nlohmann::json& members = f.Array(key);
    if (members.size() != population_size_) {
      f.Fail(key, "has " + std::to_string(members.size()) + " members, not one per child (" +
                      std::to_string(population_size_) + ")");
    }
    std::vector<Member> population;
    for (std::size_t i = 0; i < members.size(); ++i) {
      const JsonFields m(members[i], f.source(), f.Name(key) + "[" + std::to_string(i) + "].");
      m.RequireOnly({"x", "objective"});
      Member member;
      const nlohmann::json& x = m.Array("x");
      if (x.size() != kNumGenes) {
        m.Fail("x", "has " + std::to_string(x.size()) + " genes, not " + std::to_string(kNumGenes));
      }
      for (int k = 0; k < kNumGenes; ++k) {
        const std::string name = "x[" + std::to_string(k) + "]";
        const GeneBounds b = WidestGeneBounds(k);
        if (!x[k].is_number()) m.Fail(name, "must be a number, got " + x[k].dump());
        const double value = x[k].get<double>();
        if (!(value >= b.lo && value <= b.hi)) {
          m.Fail(name, "= " + FormatExact(value) + " is outside its allowed range " +
                           NumberRange{b.lo, b.hi}.ToString() + " (gene '" + GeneTable()[k].name + "')");
        }
        member.x.push_back(value);
      }
      member.objective = m.Number("objective");
      population.push_back(std::move(member));
    }
    return population;
  }

  const pagmo::algorithm fresh_algorithm_;  // as constructed: what a replay starts from
  pagmo::algorithm algorithm_;
  Keeping keeping_;
  GeneticAlgorithm first_generation_;
  std::size_t population_size_;
  unsigned seed_;
  std::vector<Member> population_;
  std::vector<vector_double> proposals_;  // this generation's, between Propose and Tell
  std::vector<Member> initial_;           // kReplayed: generation 0's population
  std::vector<Told> told_;                // kReplayed: every later generation's
};

// Every algorithm: one generation per call (the run loops), what it adapts
// kept from call to call (memory), never stopped by its own tolerances (0:
// the run decides when to stop), pagmo's defaults otherwise.
constexpr unsigned kOneGeneration = 1;
constexpr double kNeverStop = 0.0;
constexpr bool kMemory = true;

}  // namespace

std::unique_ptr<Learner> MakeCmaes(const LearnerSpec& spec, const GeneticAlgorithmConfig& ga, std::uint64_t seed) {
  // cc, cs, c1, cmu automatic (-1); sigma0 0.5; samples clamped into the
  // bounds (force_bounds), so that every proposal respects the scaffold
  const pagmo::cmaes cmaes(kOneGeneration, -1, -1, -1, -1, 0.5, kNeverStop, kNeverStop, kMemory,
                           /*force_bounds=*/true, static_cast<unsigned>(seed));
  return std::make_unique<PagmoLearner>(spec, pagmo::algorithm(cmaes), Keeping::kSerialised, ga, seed);
}

std::unique_ptr<Learner> MakeSade(const LearnerSpec& spec, const GeneticAlgorithmConfig& ga, std::uint64_t seed) {
  // variant 2: DE/rand/1/exp; self-adaptation 1: jDE
  const pagmo::sade sade(kOneGeneration, 2u, 1u, kNeverStop, kNeverStop, kMemory, static_cast<unsigned>(seed));
  return std::make_unique<PagmoLearner>(spec, pagmo::algorithm(sade), Keeping::kSerialised, ga, seed);
}

std::unique_ptr<Learner> MakeParticleSwarm(const LearnerSpec& spec, const GeneticAlgorithmConfig& ga,
                                           std::uint64_t seed) {
  // omega 0.7298, eta1 = eta2 = 2.05, max_vel 0.5, variant 5 (constriction),
  // neighbourhood 2 (lbest ring) of 4
  const pagmo::pso_gen pso(kOneGeneration, 0.7298, 2.05, 2.05, 0.5, 5u, 2u, 4u, kMemory, static_cast<unsigned>(seed));
  return std::make_unique<PagmoLearner>(spec, pagmo::algorithm(pso), Keeping::kReplayed, ga, seed);
}

}  // namespace walkers
