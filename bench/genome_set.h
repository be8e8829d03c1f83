// The genome sets of the benchmarks: data/genomes/bench/ (its README says
// where each came from) and the authors' final archives, data/genomes/authors/.
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "control/genome.h"

namespace walkers::bench {

// Every genome file of data/genomes/<set>/, by name.
inline std::vector<std::pair<std::string, Genome>> GenomeSet(const std::string& set) {
  std::vector<std::pair<std::string, Genome>> out;
  for (const auto& entry : std::filesystem::directory_iterator(WALKERS_SOURCE_DIR "/data/genomes/" + set)) {
    if (entry.path().extension() != ".json") continue;
    out.push_back({entry.path().stem().string(), LoadGenome(entry.path().string())});
  }
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return out;
}

inline std::vector<std::pair<std::string, Genome>> BenchmarkGenomes() { return GenomeSet("bench"); }

}  // namespace walkers::bench
