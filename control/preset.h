// The two presets (docs/model.md, "Presets"): where the paper's text and the
// authors' program differ, as named switches in one value.
#pragma once

#include <string>
#include <vector>

namespace walkers {

// When the walker may leave double support.
enum class StableRule {
  kJointRateMagnitudes,        // paper: every joint rate's magnitude below stableTolerance
  kSignedRatesAndTrunkMotion,  // authors: every joint rate (signed) and the trunk's x' + y' (signed) below it
};

// The performance-based scaffold's ceiling for halfBodyX (docs/model.md,
// "Scaffolds").
enum class PerformanceCeiling {
  kPaperEq8,          // max(0.9 - 0.2 Ave / InitF, 0.05)
  kAuthorsFormula,    // max(0.9 InitF / Ave - 0.2, 0), clamped ceiling-first, never below 0.01
};

// How mutation treats the body-length gene halfBodyX.
enum class BodyGeneMutation {
  kLikeEveryGene,        // paper: mutated once, clamped to the scaffold ceiling
  kRedrawnPerMutation,   // authors: cases 1 and 3 redraw it after every gene that mutates;
                         // case 2 adds one extra draw clamped to the stage ceiling
};

struct Preset {
  std::string name;
  StableRule stable_rule = StableRule::kSignedRatesAndTrunkMotion;
  double fall_fraction = 1.0 / 3.0;  // [-] of the standing height L + halfFootY + halfBodyY
  PerformanceCeiling performance_ceiling = PerformanceCeiling::kAuthorsFormula;
  BodyGeneMutation body_gene_mutation = BodyGeneMutation::kRedrawnPerMutation;
};

Preset PaperPreset();
Preset OriginalPreset();  // the default

// The presets' names: "paper", "original".
std::vector<std::string> PresetNames();
// PresetNames()'s preset; throws InputError (files/errors.h) naming the
// allowed values.
Preset PresetByName(const std::string& name);

}  // namespace walkers
