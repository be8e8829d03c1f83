#include "evolve/variation.h"

#include <cmath>
#include <ostream>

#include <gtest/gtest.h>

namespace walkers {
namespace {

struct Variant {
  Preset preset;
  ScaffoldCase scaffold_case;
};
void PrintTo(const Variant& v, std::ostream* os) { *os << v.preset.name << " preset, " << ScaffoldCaseName(v.scaffold_case); }

class MutationTest : public ::testing::TestWithParam<Variant> {
 protected:
  MutationRules Rules() const {
    MutationRules r;
    r.body_gene = GetParam().preset.body_gene_mutation;
    r.body_redraw = ScaffoldSpecOf(GetParam().scaffold_case).authors_body_redraw;
    return r;
  }
};

TEST_P(MutationTest, RespectsEveryGenesBoundsAndTheScaffoldCeiling) {
  Random rng(7, 3, 1);
  Genome parent = DefaultGenome();
  for (double ceiling : {0.9, 0.5, 0.1}) {
    for (int i = 0; i < 300; ++i) {
      const Genome child = Mutate(parent, ceiling, Rules(), &rng);
      for (int k = 0; k < kNumGenes; ++k) {
        const GeneSpec& spec = GeneTable()[k];
        ASSERT_GE(child.genes[k], spec.floor) << spec.name;
        ASSERT_LE(child.genes[k], k == kHalfBodyX ? ceiling : spec.ceiling) << spec.name;
      }
      EXPECT_EQ(child.knee_mass, parent.knee_mass);
      parent = child;  // a random walk, so bounds are met from everywhere
    }
  }
}

TEST_P(MutationTest, MutatesAboutNineGenesInTen) {
  Random rng(11, 0, 0);
  const Genome parent = DefaultGenome();
  int changed = 0, total = 0;
  for (int i = 0; i < 200; ++i) {
    const Genome child = Mutate(parent, 0.9, Rules(), &rng);
    for (int k = 1; k < kNumGenes; ++k, ++total) changed += child.genes[k] != parent.genes[k] ? 1 : 0;
  }
  // clamping at a bound can keep a mutated value equal (kTheta sits at its ceiling)
  EXPECT_NEAR(static_cast<double>(changed) / total, 0.9, 0.06);
}

INSTANTIATE_TEST_SUITE_P(PresetsAndScaffolds, MutationTest,
                         ::testing::Values(Variant{PaperPreset(), ScaffoldCase::kFree},
                                           Variant{PaperPreset(), ScaffoldCase::kTime},
                                           Variant{PaperPreset(), ScaffoldCase::kPerformance},
                                           Variant{OriginalPreset(), ScaffoldCase::kFree},
                                           Variant{OriginalPreset(), ScaffoldCase::kTime},
                                           Variant{OriginalPreset(), ScaffoldCase::kPerformance}),
                         [](const ::testing::TestParamInfo<Variant>& variant) {
                           return variant.param.preset.name + "_" + ScaffoldCaseName(variant.param.scaffold_case);
                         });

// one mutation's change of halfBodyX from the middle of its range: its rms
// and how often it ends on a bound (0.05 or 0.9)
struct BodyStep {
  double rms = 0, at_bound = 0;
};
BodyStep MeasureBodyStep(const MutationRules& rules) {
  Random rng(3, 1, 4);
  Genome parent = DefaultGenome();
  parent[kHalfBodyX] = 0.45;
  BodyStep out;
  const int n = 4000;
  for (int i = 0; i < n; ++i) {
    const double x = Mutate(parent, 0.9, rules, &rng)[kHalfBodyX];
    out.rms += (x - 0.45) * (x - 0.45);
    out.at_bound += x == 0.05 || x == 0.9 ? 1 : 0;
  }
  out.rms = std::sqrt(out.rms / n);
  out.at_bound /= n;
  return out;
}

TEST(BodyGeneTest, PresetsTreatTheBodyGeneAsMODELSectionSixSays) {
  const double sigma = GeneTable()[kHalfBodyX].sigma;
  const auto rules = [](BodyGeneMutation body_gene, ScaffoldCase c) {
    return MutationRules{0.9, body_gene, ScaffoldSpecOf(c).authors_body_redraw};
  };
  const BodyStep paper = MeasureBodyStep(rules(BodyGeneMutation::kLikeEveryGene, ScaffoldCase::kFree));
  const BodyStep authors_free = MeasureBodyStep(rules(BodyGeneMutation::kRedrawnPerMutation, ScaffoldCase::kFree));
  const BodyStep authors_time = MeasureBodyStep(rules(BodyGeneMutation::kRedrawnPerMutation, ScaffoldCase::kTime));
  // paper: one draw with probability 0.9, clamped to [0.05, 0.9]
  EXPECT_LT(paper.rms, sigma);
  EXPECT_GT(paper.rms, 0.6 * sigma);
  // authors, case 2: one extra draw after the loop; cases 1 and 3: drawn
  // again after each of ~16 mutated genes, a random walk that mostly ends on a bound
  EXPECT_GT(authors_time.rms, paper.rms);
  EXPECT_GT(authors_free.rms, authors_time.rms);
  EXPECT_GT(authors_time.at_bound, 1.5 * paper.at_bound);
  EXPECT_GT(authors_free.at_bound, 2.0 * paper.at_bound);
}

TEST(BodyGeneTest, AuthorsClampCeilingFirstBelowTheFloor) {
  // ceiling 0.03 below the floor 0.05: the gene ends at the ceiling or the floor
  EXPECT_DOUBLE_EQ(Saturate(0.05, 0.03, 0.5), 0.03);
  EXPECT_DOUBLE_EQ(Saturate(0.05, 0.03, 0.04), 0.03);
  EXPECT_DOUBLE_EQ(Saturate(0.05, 0.03, 0.01), 0.05);
  EXPECT_DOUBLE_EQ(Saturate(0.05, 0.9, 0.3), 0.3);
  Random rng(1, 2, 3);
  const MutationRules rules{0.9, BodyGeneMutation::kRedrawnPerMutation, AuthorsBodyRedraw::kAfterEveryMutatedGene};
  bool saw_ceiling = false;
  for (int i = 0; i < 100; ++i) {
    const double x = Mutate(DefaultGenome(), 0.03, rules, &rng)[kHalfBodyX];
    EXPECT_TRUE(x == 0.03 || x == 0.05) << x;
    saw_ceiling = saw_ceiling || x == 0.03;
  }
  EXPECT_TRUE(saw_ceiling);
}

TEST(CrossoverTest, IsTheMeanOfTheParents) {
  Genome a = DefaultGenome(), b = DefaultGenome();
  b[kKx] = 3000.0;
  b[kStepOffset] = 0.2;
  const Genome c = Crossover(a, b);
  EXPECT_DOUBLE_EQ(c[kKx], 0.5 * (a[kKx] + 3000.0));
  EXPECT_DOUBLE_EQ(c[kStepOffset], 0.5 * (a[kStepOffset] + 0.2));
  EXPECT_DOUBLE_EQ(c[kKy], a[kKy]);
}

TEST(DuplicateKeyTest, RoundsToThreeSignificantFigures) {
  EXPECT_DOUBLE_EQ(RoundToSignificant(1572.4184, 3), 1570.0);
  EXPECT_DOUBLE_EQ(RoundToSignificant(0.0021358, 3), 0.00214);
  EXPECT_DOUBLE_EQ(RoundToSignificant(-0.00213586, 3), -0.00214);
  EXPECT_DOUBLE_EQ(RoundToSignificant(0.0, 3), 0.0);
  Genome a = DefaultGenome(), b = DefaultGenome();
  b[kKy] += 0.4;  // 6980.007 -> 6980.407: same at 3 figures
  EXPECT_EQ(KeyOf(a), KeyOf(b));
  b[kKy] += 10.0;  // 6990.4
  EXPECT_NE(KeyOf(a), KeyOf(b));
}

}  // namespace
}  // namespace walkers
