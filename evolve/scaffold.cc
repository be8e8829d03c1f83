#include "evolve/scaffold.h"

#include <algorithm>
#include <string>

#include "files/errors.h"
#include "files/input_file.h"

namespace walkers {
namespace {

// Case 1: the body length evolves freely up to its own ceiling.
class FreeScaffold : public Scaffold {
 public:
  ScaffoldCase id() const override { return ScaffoldCase::kFree; }
  double Ceiling(const ScaffoldInputs&) const override { return kBodyCeiling; }
};

// Case 2, paper eq. (7): 1.8 - 0.4 i in body length, i.e. halfBodyX ceilings
// 0.9, 0.7, 0.5, 0.3, 0.1 for generations [0,500), [500,1000), ... [2000, end).
class TimeScaffold : public Scaffold {
 public:
  ScaffoldCase id() const override { return ScaffoldCase::kTime; }
  double Ceiling(const ScaffoldInputs& in) const override {
    const int stage = std::min(in.generation / 500, 4);
    return kBodyCeiling - 0.2 * stage;
  }
};

// Case 3: the ceiling falls as the best three's fitness rises over InitF.
class PerformanceScaffold : public Scaffold {
 public:
  explicit PerformanceScaffold(PerformanceCeiling formula) : formula_(formula) {}
  ScaffoldCase id() const override { return ScaffoldCase::kPerformance; }
  double Ceiling(const ScaffoldInputs& in) const override {
    // no progress to measure yet (a non-walking default or best three): no scaffold removed
    if (!(in.initial_fitness > 0.0) || !(in.ave_best3 > 0.0)) return kBodyCeiling;
    const double ratio = in.ave_best3 / in.initial_fitness;
    if (formula_ == PerformanceCeiling::kPaperEq8) {
      // paper eq. (8): max(1.8 - 0.4 Ave/InitF, 0.05) in body length
      return std::max(kBodyCeiling - 0.2 * ratio, kBodyFloor);
    }
    // the authors' program: max(0.9 InitF/Ave - 0.2, 0). It may fall below
    // the floor, never below 0.01 here. While the best three average less
    // than about 0.82 InitF it exceeds 0.9: a scaffold only lowers the body's
    // ceiling, so it is capped there (genome files reject longer bodies)
    const double authors = std::max(kBodyCeiling / ratio - 0.2, 0.0);
    return std::clamp(authors, kMinimumCeiling, kBodyCeiling);
  }

 private:
  PerformanceCeiling formula_;
};

}  // namespace

const std::vector<ScaffoldSpec>& Scaffolds() {
  static const std::vector<ScaffoldSpec> scaffolds = {
      {ScaffoldCase::kFree, "free", "free", "tab:green", AuthorsBodyRedraw::kAfterEveryMutatedGene, 0,
       [](const Preset&) -> std::unique_ptr<Scaffold> { return std::make_unique<FreeScaffold>(); }},
      {ScaffoldCase::kTime, "time", "time-constrained", "tab:orange", AuthorsBodyRedraw::kOnceAtTheEnd, 2,
       [](const Preset&) -> std::unique_ptr<Scaffold> { return std::make_unique<TimeScaffold>(); }},
      {ScaffoldCase::kPerformance, "performance", "performance-based", "tab:purple",
       AuthorsBodyRedraw::kAfterEveryMutatedGene, 0, [](const Preset& preset) -> std::unique_ptr<Scaffold> {
         return std::make_unique<PerformanceScaffold>(preset.performance_ceiling);
       }},
  };
  return scaffolds;
}

int ScaffoldSpec::number() const { return static_cast<int>(this - Scaffolds().data()) + 1; }

const ScaffoldSpec& ScaffoldSpecOf(ScaffoldCase c) {
  for (const ScaffoldSpec& spec : Scaffolds()) {
    if (spec.id == c) return spec;
  }
  WALKERS_CHECK(false, "scaffold case " + std::to_string(static_cast<int>(c)) + " is none of Scaffolds()");
}

const char* ScaffoldCaseName(ScaffoldCase c) { return ScaffoldSpecOf(c).name; }

std::vector<std::string> ScaffoldCaseNames() {
  std::vector<std::string> names;
  for (const ScaffoldSpec& spec : Scaffolds()) names.push_back(spec.name);
  return names;
}

ScaffoldCase ScaffoldCaseByName(const std::string& name) {
  for (const ScaffoldSpec& spec : Scaffolds()) {
    if (name == spec.name) return spec.id;
  }
  FailUnknownName("case", name, ScaffoldCaseNames());
}

std::unique_ptr<Scaffold> MakeScaffold(ScaffoldCase c, const Preset& preset) { return ScaffoldSpecOf(c).make(preset); }

}  // namespace walkers
