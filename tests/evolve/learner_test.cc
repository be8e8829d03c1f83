#include "evolve/learner.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "evolve/genetic_algorithm.h"
#include "files/input_file.h"

namespace walkers {
namespace {

// A learner that proposes the genomes it is given, and draws a duplicate
// again as the seam does by default.
class FixedLearner : public Learner {
 public:
  explicit FixedLearner(std::vector<Genome> genomes) : Learner(DefaultLearner()), genomes_(std::move(genomes)) {}
  std::vector<Individual> Propose(const BreedingInputs& in, const Archive&) override {
    std::vector<Individual> children(genomes_.size());
    for (std::size_t c = 0; c < children.size(); ++c) {
      children[c].generation = in.generation;
      children[c].child = static_cast<int>(c);
      children[c].lineage = Lineage::ProposedBy("fixed");
      children[c].genome = genomes_[c];
    }
    return children;
  }
  void Tell(const BreedingInputs&, const std::vector<Individual>&) override {}

 private:
  std::vector<Genome> genomes_;
};

const MutationRules kRules{0.9, BodyGeneMutation::kLikeEveryGene, AuthorsBodyRedraw::kAfterEveryMutatedGene};

std::vector<Individual> Admitted(const std::vector<Genome>& genomes, const BreedingInputs& in,
                                 std::set<GenomeKey>* seen) {
  FixedLearner learner(genomes);
  std::vector<Individual> children = learner.Propose(in, Archive(2));
  AdmitChildren(learner, in, &children, seen);
  return children;
}

Genome Shifted(double kx) {
  Genome g = DefaultGenome();
  g[kKx] = kx;
  return g;
}

TEST(LearnersTest, TheListNamesEachLearnerOnceWithTheGaFirst) {
  EXPECT_EQ(LearnerNames(), (std::vector<std::string>{"ga", "cmaes", "sade", "pso", "external"}));
  EXPECT_EQ(BuiltInLearnerNames(), (std::vector<std::string>{"ga", "cmaes", "sade", "pso"}));
  EXPECT_STREQ(DefaultLearner().name, "ga");
  for (const LearnerSpec& spec : Learners()) {
    EXPECT_EQ(&LearnerByName(spec.name), &spec);
    EXPECT_GE(spec.min_population, kMinPopulation) << spec.name;
    EXPECT_EQ(MakeLearner(spec.name, GeneticAlgorithmConfig{}, 1)->spec().name, spec.name);
  }
  try {
    LearnerByName("nsga2");
    FAIL() << "accepted an unknown learner";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "unknown learner 'nsga2': allowed values are ga, cmaes, sade, pso, external");
  }
}

TEST(GeneBoundsTest, HalfBodyXTakesTheScaffoldsCeilingAndTheOthersTheirOwnBounds) {
  const GeneBounds body = ChildGeneBounds(kHalfBodyX, 0.5);
  EXPECT_EQ(body.lo, GeneTable()[kHalfBodyX].floor);
  EXPECT_EQ(body.hi, 0.5);
  // a ceiling below the floor: the interval spans both
  const GeneBounds low = ChildGeneBounds(kHalfBodyX, 0.02);
  EXPECT_EQ(low.lo, 0.02);
  EXPECT_EQ(low.hi, GeneTable()[kHalfBodyX].floor);
  for (int k = 1; k < kNumGenes; ++k) {
    EXPECT_EQ(ChildGeneBounds(k, 0.5).lo, GeneTable()[k].floor) << k;
    EXPECT_EQ(ChildGeneBounds(k, 0.5).hi, GeneTable()[k].ceiling) << k;
  }
}

TEST(AdmitChildrenTest, AGeneOutsideItsBoundsIsClampedIntoThem) {
  Genome wild = Shifted(1.0);
  wild[kHalfBodyX] = 0.8;                                 // above this generation's ceiling
  wild[kKStep] = GeneTable()[kKStep].ceiling + 100.0;     // above its own ceiling
  wild[kFemurLength] = GeneTable()[kFemurLength].floor - 1.0;  // below its floor
  std::set<GenomeKey> seen;
  const std::vector<Individual> children = Admitted({wild}, {7, 3, 0.4, kRules}, &seen);
  const Genome& g = children[0].genome;
  EXPECT_EQ(g[kHalfBodyX], 0.4);
  EXPECT_EQ(g[kKStep], GeneTable()[kKStep].ceiling);
  EXPECT_EQ(g[kFemurLength], GeneTable()[kFemurLength].floor);
  EXPECT_EQ(g[kKx], 1.0) << "a gene within its bounds is kept";
  EXPECT_EQ(children[0].lineage.Text(), "fixed clamped");
  EXPECT_EQ(seen.count(KeyOf(g)), 1u);
}

TEST(AdmitChildrenTest, TheInitialIndividualIsEvaluatedAsItIsInGenerationZero) {
  const Genome initial = DefaultGenome();
  std::set<GenomeKey> seen;
  // a ceiling below the default's halfBodyX clamps every genome but the initial one
  const double ceiling = initial[kHalfBodyX] / 2;
  const std::vector<Individual> first = Admitted({initial}, {7, 0, ceiling, kRules}, &seen);
  EXPECT_EQ(first[0].genome.genes, initial.genes);
  const std::vector<Individual> later = Admitted({initial}, {7, 1, ceiling, kRules}, &seen);
  EXPECT_EQ(later[0].genome[kHalfBodyX], ceiling);
}

TEST(AdmitChildrenTest, ADuplicateIsDrawnAgainFromTheChildsOwnStreamUntilItIsNew) {
  std::set<GenomeKey> seen;
  // child 1 repeats child 0 at 3 significant figures; child 2 repeats an earlier generation's
  const Genome a = Shifted(1.0), a_again = Shifted(1.0004), earlier = Shifted(2.0);
  seen.insert(KeyOf(earlier));
  const BreedingInputs in{7, 3, 0.9, kRules};
  const std::vector<Individual> children = Admitted({a, a_again, earlier}, in, &seen);
  EXPECT_EQ(children[0].genome.genes, a.genes);
  EXPECT_EQ(children[0].lineage.Text(), "fixed");
  for (int c : {1, 2}) {
    EXPECT_EQ(children[c].lineage.Text(), "fixed redrawn") << c;
    EXPECT_NE(KeyOf(children[c].genome), KeyOf(a)) << c;
    EXPECT_NE(KeyOf(children[c].genome), KeyOf(earlier)) << c;
  }
  EXPECT_EQ(seen.size(), 4u);
  // the redraw is a mutant of the proposal from the child's stream of redraws
  Random rng(7, 3, Random::kRedraws + 1);
  EXPECT_EQ(children[1].genome.genes, Mutate(a_again, 0.9, kRules, &rng).genes);
  // and the same proposals are admitted alike again
  std::set<GenomeKey> seen_again = {KeyOf(earlier)};
  const std::vector<Individual> again = Admitted({a, a_again, earlier}, in, &seen_again);
  for (int c = 0; c < 3; ++c) EXPECT_EQ(again[c].genome.genes, children[c].genome.genes) << c;
}

TEST(AdmitChildrenTest, AGeneThatIsNotANumberIsTheLearnersError) {
  Genome broken = Shifted(1.0);
  broken[kLambdaY] = std::numeric_limits<double>::quiet_NaN();
  std::set<GenomeKey> seen;
  try {
    Admitted({Shifted(3.0), broken}, {7, 4, 0.9, kRules}, &seen);
    FAIL() << "admitted a NaN gene";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "the learner ga proposed nan for gene 'lambdaY' of child 4/1: a gene must be a finite number"),
              std::string::npos)
        << e.what();
  }
}

TEST(LearnerStateTest, TheGaKeepsNoStateAndRefusesOne) {
  const std::unique_ptr<Learner> ga = MakeLearner("ga", GeneticAlgorithmConfig{}, 1);
  EXPECT_FALSE(ga->KeepsState());
  EXPECT_TRUE(ga->State().is_null());
  EXPECT_THROW(ga->Restore(nlohmann::json::object(), 3, "cp.json"), InputError);
}

}  // namespace
}  // namespace walkers
