#include "control/preset.h"

#include "files/input_file.h"

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

std::vector<std::string> PresetNames() { return {PaperPreset().name, OriginalPreset().name}; }

Preset PresetByName(const std::string& name) {
  for (const Preset& preset : {PaperPreset(), OriginalPreset()}) {
    if (name == preset.name) return preset;
  }
  FailUnknownName("preset", name, PresetNames());
}

}  // namespace walkers
