// Accuracy of numerical settings: every genome of a set evaluated with the
// given tolerances and with all of them 100x tighter. Prints per genome the
// two fitnesses, gait classes, fall verdicts and times, then the median
// relative fitness difference. Not a Google Benchmark: a measurement for
// docs/performance.md.
//
// With --ensemble N, each genome is evaluated N times at each of the two
// settings, perturbed as control/accuracy.h says, and the medians are
// compared (docs/performance.md, "Accuracy").
//
//   accuracy DIR [--ensemble N] [VARIANT | rtol atol_position atol_velocity]   (variants: bench/variants.h)
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/variants.h"
#include "control/accuracy.h"

using namespace walkers;

namespace {

int Usage(const char* program) {
  std::fprintf(stderr, "usage: %s GENOME_DIR [--ensemble N] [VARIANT | rtol atol_position atol_velocity]\n",
               program);
  return 2;
}

// the genomes (*.json) of a directory, sorted by name
std::vector<std::string> GenomeFiles(const std::string& dir) {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().extension() == ".json") files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

void CompareSingle(const std::vector<std::string>& files, const EvaluationSettings& production,
                   const EvaluationSettings& tight) {
  std::vector<double> differences, walls;
  int gait_disagreements = 0, fall_disagreements = 0;
  std::printf("%-28s %10s %10s %8s %7s %7s %9s %9s\n", "genome", "fitness", "tight", "rel.diff", "gait", "fell",
              "ms", "tight ms");
  for (const std::string& file : files) {
    const Genome g = LoadGenome(file);
    const EvaluationResult a = Evaluate(g, OriginalPreset(), production);
    const EvaluationResult b = Evaluate(g, OriginalPreset(), tight);
    differences.push_back(RelativeFitnessDifference(a.fitness, b.fitness));
    walls.push_back(a.wall_ms);
    gait_disagreements += a.gait != b.gait ? 1 : 0;
    fall_disagreements += a.fell != b.fell ? 1 : 0;
    std::printf("%-28s %10.4f %10.4f %7.2f%% %3s/%-3s %3d/%-3d %9.1f %9.1f\n",
                std::filesystem::path(file).stem().string().c_str(), a.fitness, b.fitness,
                100.0 * differences.back(), GaitName(a.gait), GaitName(b.gait), a.fell, b.fell, a.wall_ms,
                b.wall_ms);
  }
  std::printf("median relative fitness difference %.2f%%; gait disagreements %d; fall disagreements %d; "
              "median wall %.1f ms\n",
              100.0 * Median(differences), gait_disagreements, fall_disagreements, Median(walls));
}

// Besides the criterion (the median over the set of the differences
// of the medians), the genomes whose fitness the tight tolerances pin down
// (every tight member within 1 % of their median): how far, at most, their
// production medians and their production members are from the tight medians
// (docs/performance.md, "Accuracy").
void CompareEnsembles(const std::vector<std::string>& files, const EvaluationSettings& production,
                      const EvaluationSettings& tight, int n) {
  constexpr double kPinned = 0.01;
  std::vector<double> differences;
  int pinned = 0;
  double worst_pinned_median = 0.0, worst_pinned_member = 0.0;
  std::printf("%-28s %28s %28s %8s %9s %9s %s\n", "genome", "fitness: median [min, max]",
              "tight: median [min, max]", "rel.diff", "bipeds", "falls", "pinned: worst member");
  for (const std::string& file : files) {
    const Genome g = LoadGenome(file);
    const FitnessEnsemble a = EvaluateEnsemble(g, OriginalPreset(), production, n);
    const FitnessEnsemble b = EvaluateEnsemble(g, OriginalPreset(), tight, n);
    differences.push_back(RelativeFitnessDifference(a.Median(), b.Median()));
    char pin[32] = "no";
    if (b.Pinned(kPinned)) {
      const double worst = a.WorstDifferenceFrom(b.Median());
      ++pinned;
      worst_pinned_median = std::max(worst_pinned_median, differences.back());
      worst_pinned_member = std::max(worst_pinned_member, worst);
      std::snprintf(pin, sizeof(pin), "%.2f%%", 100.0 * worst);
    }
    std::printf("%-28s %8.3f [%7.3f, %7.3f] %8.3f [%7.3f, %7.3f] %7.2f%% %4d/%-4d %4d/%-4d %s\n",
                std::filesystem::path(file).stem().string().c_str(), a.Median(), a.Min(), a.Max(), b.Median(),
                b.Min(), b.Max(),
                100.0 * differences.back(), a.bipeds, b.bipeds, a.falls, b.falls, pin);
  }
  std::printf("%d evaluations per genome and setting; median relative difference of the medians %.2f%%\n", n,
              100.0 * Median(differences));
  std::printf("pinned down by the tight tolerances (every tight member within %.0f%% of their median): %d of %zu; "
              "of those, production medians at most %.2f%% and production members at most %.2f%% from the tight "
              "medians\n",
              100.0 * kPinned, pinned, files.size(), 100.0 * worst_pinned_median, 100.0 * worst_pinned_member);
}

// A tolerance from the command line: a positive number, or an error naming it.
double ParseTolerance(const std::string& name, const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !(value > 0.0) || !std::isfinite(value)) {
    throw std::invalid_argument(name + " must be a positive number, got '" + text + "'");
  }
  return value;
}

// An ensemble size from the command line: a whole number in 1..1000 (the
// range of `walkers evaluate --ensemble`), or an error naming it.
int ParseEnsembleSize(const std::string& text) {
  char* end = nullptr;
  errno = 0;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno == ERANGE || value < 1 || value > 1000) {
    throw std::invalid_argument("--ensemble must be a whole number in 1..1000, got '" + text + "'");
  }
  return static_cast<int>(value);
}

int Run(const char* program, std::vector<std::string> args) {
  int ensemble = 0;
  if (args.size() >= 3 && args[1] == "--ensemble") {
    ensemble = ParseEnsembleSize(args[2]);
    args.erase(args.begin() + 1, args.begin() + 3);
  }
  if (args.size() != 1 && args.size() != 2 && args.size() != 4) return Usage(program);
  EvaluationSettings production;
  if (args.size() == 2) {
    bool found = false;
    for (const bench::Variant& v : bench::Variants()) {
      if (v.name == args[1]) {
        production = v.settings;
        found = true;
      }
    }
    if (!found) throw std::invalid_argument("unknown variant " + args[1] + " (bench/variants.h)");
  }
  if (args.size() == 4) {
    production.integrator.relative_tolerance = ParseTolerance("rtol", args[1]);
    production.integrator.absolute_tolerance_position = ParseTolerance("atol_position", args[2]);
    production.integrator.absolute_tolerance_velocity = ParseTolerance("atol_velocity", args[3]);
  }
  const EvaluationSettings tight = HundredTimesTighter(production);
  const std::vector<std::string> files = GenomeFiles(args[0]);
  if (ensemble > 0) {
    CompareEnsembles(files, production, tight, ensemble);
  } else {
    CompareSingle(files, production, tight);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return Run(argv[0], std::vector<std::string>(argv + 1, argv + argc));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "accuracy: %s\n", e.what());
    return 2;
  }
}
