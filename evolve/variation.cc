#include "evolve/variation.h"

#include <cmath>

namespace walkers {

double Saturate(double floor, double ceiling, double x) {
  if (x > ceiling) return ceiling;
  if (x < floor) return floor;
  return x;
}

Genome Mutate(const Genome& parent, double body_ceiling, const MutationRules& rules, Random* rng) {
  const auto& table = GeneTable();
  const GeneSpec& body = table[kHalfBodyX];
  auto redraw_body = [&](Genome* g) {
    (*g)[kHalfBodyX] = Saturate(body.floor, body_ceiling, rng->Normal((*g)[kHalfBodyX], body.sigma));
  };
  const bool authors = rules.body_gene == BodyGeneMutation::kRedrawnPerMutation;
  const bool redraw_per_gene = authors && rules.body_redraw == AuthorsBodyRedraw::kAfterEveryMutatedGene;

  Genome child = parent;
  for (int k = 0; k < kNumGenes; ++k) {
    if (!rng->Bernoulli(rules.probability)) continue;
    const GeneSpec& spec = table[k];
    // the paper clamps the body gene to the scaffold; the authors clamp it to
    // its own ceiling here and apply the scaffold in their extra draws
    const double ceiling =
        k == kHalfBodyX && rules.body_gene == BodyGeneMutation::kLikeEveryGene ? body_ceiling : spec.ceiling;
    child.genes[k] = Saturate(spec.floor, ceiling, rng->Normal(child.genes[k], spec.sigma));
    if (redraw_per_gene) redraw_body(&child);
  }
  if (authors && rules.body_redraw == AuthorsBodyRedraw::kOnceAtTheEnd) redraw_body(&child);
  // a child never keeps a body longer than this generation allows
  child[kHalfBodyX] = Saturate(body.floor, body_ceiling, child[kHalfBodyX]);
  return child;
}

Genome Crossover(const Genome& a, const Genome& b) {
  Genome child = a;
  for (int k = 0; k < kNumGenes; ++k) child.genes[k] = 0.5 * (a.genes[k] + b.genes[k]);
  return child;
}

double RoundToSignificant(double x, int digits) {
  if (x == 0.0 || !std::isfinite(x)) return x;
  const int decimals = digits - 1 - static_cast<int>(std::floor(std::log10(std::abs(x))));
  const double scale = std::pow(10.0, decimals);
  return std::round(x * scale) / scale;
}

GenomeKey KeyOf(const Genome& genome) {
  GenomeKey key;
  for (int k = 0; k < kNumGenes; ++k) key[k] = RoundToSignificant(genome.genes[k], 3);
  return key;
}

}  // namespace walkers
