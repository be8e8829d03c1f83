// The three scaffolds (paper §2.5; docs/model.md, "Scaffolds"): each bounds
// the body-length gene halfBodyX from above, by generation or by
// performance. Scaffolds() is the one list of them: the command line and the
// run plan read it, and the statistics and the figures through
// reproduction.json.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "control/preset.h"

namespace walkers {

enum class ScaffoldCase { kFree, kTime, kPerformance };

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

// When the authors' program draws halfBodyX again under the scaffold's
// ceiling (the `original` preset's body-gene mutation; docs/model.md,
// "Presets"): their
// case-2 evolver does it once per child, the others after every gene that
// mutated.
enum class AuthorsBodyRedraw { kAfterEveryMutatedGene, kOnceAtTheEnd };

// Everything the program knows of one scaffold.
struct ScaffoldSpec {
  ScaffoldCase id;
  const char* name;    // on the command line and in files: "time"
  const char* label;   // for people: "time-constrained"
  const char* colour;  // its colour in the figures (a matplotlib colour name)
  AuthorsBodyRedraw authors_body_redraw;
  int paper_tripod_finals;  // of the paper's three runs of the case, those that ended as tripods (paper §3)
  std::unique_ptr<Scaffold> (*make)(const Preset& preset);

  int number() const;  // the paper's case number: 1, 2, 3
};

// The scaffolds in the paper's order: case 1, 2, 3.
const std::vector<ScaffoldSpec>& Scaffolds();
const ScaffoldSpec& ScaffoldSpecOf(ScaffoldCase c);

// "free", "time", "performance"
const char* ScaffoldCaseName(ScaffoldCase c);
std::vector<std::string> ScaffoldCaseNames();
// Throws InputError (files/errors.h) naming the allowed values.
ScaffoldCase ScaffoldCaseByName(const std::string& name);

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
