// How children are made (docs/model.md, "Genetic algorithm"): per-gene
// Gaussian mutation clamped to the bounds, the preset's treatment of the
// body-length gene, arithmetic crossover, and the 3-significant-figure keys
// that reject duplicates.
#pragma once

#include <array>

#include "control/genome.h"
#include "control/preset.h"
#include "evolve/random.h"
#include "evolve/scaffold.h"

namespace walkers {

struct MutationRules {
  double probability = 0.9;  // per evolved gene
  BodyGeneMutation body_gene = BodyGeneMutation::kRedrawnPerMutation;
  // under kRedrawnPerMutation: when halfBodyX is drawn again (the scaffold's property)
  AuthorsBodyRedraw body_redraw = AuthorsBodyRedraw::kAfterEveryMutatedGene;
};

// The authors' clamp, ceiling first: x > ceiling gives the ceiling, else
// x < floor gives the floor. With a ceiling below the floor (the authors'
// case-3 formula allows it) a value ends at the ceiling or at the floor.
double Saturate(double floor, double ceiling, double x);

// A mutant of `parent` whose halfBodyX respects `body_ceiling` (the
// scaffold's ceiling for this generation) in the preset's way:
// - kLikeEveryGene (paper): halfBodyX mutates like every gene, clamped to
//   [floor, body_ceiling];
// - kRedrawnPerMutation (authors): every gene mutates within its own bounds;
//   in cases 1 and 3 halfBodyX is then drawn again, clamped to the body
//   ceiling, after every gene that mutated or once at the end, as the
//   scaffold's authors_body_redraw says (case 2: once).
// Either way the result is finally clamped (Saturate) to the body ceiling.
Genome Mutate(const Genome& parent, double body_ceiling, const MutationRules& rules, Random* rng);

// The arithmetic mean of two genomes (mutated afterwards by the caller).
Genome Crossover(const Genome& a, const Genome& b);

// The genes rounded to 3 significant figures: two genomes with equal keys are
// duplicates.
using GenomeKey = std::array<double, kNumGenes>;
GenomeKey KeyOf(const Genome& genome);
double RoundToSignificant(double x, int digits);

}  // namespace walkers
