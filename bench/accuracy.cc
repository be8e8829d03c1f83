// Accuracy of numerical settings: every genome of a set evaluated with the
// given tolerances and with all of them 100x tighter. Prints per genome the
// two fitnesses, gait classes, fall verdicts and times, then the median
// relative fitness difference. Not a Google Benchmark: a measurement for
// docs/performance.md.
//
//   accuracy DIR [VARIANT | rtol atol_position atol_velocity]   (variants: bench/variants.h)
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/variants.h"
#include "control/evaluation.h"

using namespace walkers;

int main(int argc, char** argv) {
  if (argc != 2 && argc != 3 && argc != 5) {
    std::fprintf(stderr, "usage: %s GENOME_DIR [VARIANT | rtol atol_position atol_velocity]\n", argv[0]);
    return 2;
  }
  EvaluationSettings production;
  if (argc == 3) {
    bool found = false;
    for (const bench::Variant& v : bench::Variants()) {
      if (v.name == argv[2]) {
        production = v.settings;
        found = true;
      }
    }
    if (!found) {
      std::fprintf(stderr, "unknown variant %s\n", argv[2]);
      return 2;
    }
  }
  if (argc == 5) {
    production.integrator.relative_tolerance = std::atof(argv[2]);
    production.integrator.absolute_tolerance_position = std::atof(argv[3]);
    production.integrator.absolute_tolerance_velocity = std::atof(argv[4]);
  }
  EvaluationSettings tight = production;
  tight.integrator.relative_tolerance /= 100.0;
  tight.integrator.absolute_tolerance_position /= 100.0;
  tight.integrator.absolute_tolerance_velocity /= 100.0;

  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(argv[1])) {
    if (entry.path().extension() == ".json") files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  std::vector<double> differences, walls;
  int gait_disagreements = 0, fall_disagreements = 0;
  std::printf("%-28s %10s %10s %8s %7s %7s %9s %9s\n", "genome", "fitness", "tight", "rel.diff", "gait", "fell",
              "ms", "tight ms");
  for (const std::string& file : files) {
    const Genome g = LoadGenome(file);
    const EvaluationResult a = Evaluate(g, OriginalPreset(), production);
    const EvaluationResult b = Evaluate(g, OriginalPreset(), tight);
    // relative to the tighter result; fitnesses near zero compare absolutely
    const double difference = std::abs(a.fitness - b.fitness) / std::max(1.0, std::abs(b.fitness));
    differences.push_back(difference);
    walls.push_back(a.wall_ms);
    gait_disagreements += a.gait != b.gait ? 1 : 0;
    fall_disagreements += a.fell != b.fell ? 1 : 0;
    std::printf("%-28s %10.4f %10.4f %7.2f%% %3s/%-3s %3d/%-3d %9.1f %9.1f\n",
                std::filesystem::path(file).stem().string().c_str(), a.fitness, b.fitness, 100.0 * difference,
                GaitName(a.gait), GaitName(b.gait), a.fell, b.fell, a.wall_ms, b.wall_ms);
  }
  auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]);
  };
  std::printf("median relative fitness difference %.2f%%; gait disagreements %d; fall disagreements %d; "
              "median wall %.1f ms\n",
              100.0 * median(differences), gait_disagreements, fall_disagreements, median(walls));
  return 0;
}
