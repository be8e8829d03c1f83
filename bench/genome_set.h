// The benchmark set of genomes, data/genomes/bench/ (its README says where each came from).
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "control/genome.h"

namespace walkers::bench {

inline std::vector<std::pair<std::string, Genome>> BenchmarkGenomes() {
  std::vector<std::pair<std::string, Genome>> out;
  for (const auto& entry : std::filesystem::directory_iterator(WALKERS_SOURCE_DIR "/data/genomes/bench")) {
    if (entry.path().extension() != ".json") continue;
    out.push_back({entry.path().stem().string(), LoadGenome(entry.path().string())});
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return out;
}

}  // namespace walkers::bench
