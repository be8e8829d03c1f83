// The three scaffolds (paper §2.5, MODEL.md §5): each bounds the body-length
// gene halfBodyX from above, by generation or by performance.
#pragma once

#include <memory>
#include <string>

#include "control/preset.h"

namespace walkers {

enum class ScaffoldCase { kFree, kTime, kPerformance };

// "free", "time", "performance"
const char* ScaffoldCaseName(ScaffoldCase c);
// Throws std::invalid_argument naming the allowed values.
ScaffoldCase ScaffoldCaseByName(const std::string& name);

// What a scaffold may look at when it sets a generation's ceiling.
struct ScaffoldInputs {
  int generation = 0;
  double ave_best3 = 0;     // mean fitness of the best three in the archive so far
  double initial_fitness = 0;  // InitF (kAuthorsInitialFitness)
};

class Scaffold {
 public:
  virtual ~Scaffold() = default;
  virtual ScaffoldCase id() const = 0;
  // The ceiling of halfBodyX for the children of a generation [m].
  virtual double Ceiling(const ScaffoldInputs& in) const = 0;
};

std::unique_ptr<Scaffold> MakeScaffold(ScaffoldCase c, const Preset& preset);

constexpr double kBodyCeiling = 0.9;     // [m] halfBodyX's own ceiling (case 1 throughout)
constexpr double kBodyFloor = 0.05;      // [m] halfBodyX's mutation floor
constexpr double kMinimumCeiling = 0.01; // [m] the authors' formula never goes lower (genome files' floor)

// InitF of the performance scaffold: the initial individual's fitness as the
// authors measured it, the constant of their evolver. The default genome is
// chaotic: it scores 0.6-0.7 in this simulator and in the authors' own
// program built as they built it (docs/fidelity.md), 4.9-5.7 in optimised
// builds of it; evolved walkers score alike in both. So the scaffold keeps
// the authors' InitF, and with it their schedule (docs/model.md).
constexpr double kAuthorsInitialFitness = 4.8763;

}  // namespace walkers
