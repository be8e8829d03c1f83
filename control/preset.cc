#include "control/preset.h"

#include <stdexcept>

namespace walkers {

Preset PaperPreset() {
  Preset p;
  p.name = "paper";
  p.stable_rule = StableRule::kJointRateMagnitudes;
  p.fall_fraction = 1.0 / 2.0;
  p.performance_ceiling = PerformanceCeiling::kPaperEq8;
  p.body_gene_mutation = BodyGeneMutation::kLikeEveryGene;
  return p;
}

Preset OriginalPreset() {
  Preset p;
  p.name = "original";
  p.stable_rule = StableRule::kSignedRatesAndTrunkMotion;
  p.fall_fraction = 1.0 / 3.0;
  p.performance_ceiling = PerformanceCeiling::kAuthorsFormula;
  p.body_gene_mutation = BodyGeneMutation::kRedrawnPerMutation;
  return p;
}

Preset PresetByName(const std::string& name) {
  if (name == "paper") return PaperPreset();
  if (name == "original") return OriginalPreset();
  throw std::invalid_argument("unknown preset '" + name + "': allowed values are paper, original");
}

}  // namespace walkers
