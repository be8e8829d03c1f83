// Small, quick runs for the run tests, and how two runs' files are compared.
#pragma once

#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "evolve/run_files.h"
#include "files/input_file.h"

namespace walkers::testing {

// A small, quick run: short evaluations, small population; the logic is the
// full one.
inline RunConfig SmallRun(ScaffoldCase c = ScaffoldCase::kPerformance, int generations = 4) {
  RunConfig config;
  config.scaffold_case = c;
  config.generations = generations;
  config.seed = 42;
  config.ga.population = 8;
  config.ga.archive_size = 8;
  config.ga.mutation_children = 5;
  config.evaluation.duration = 3.0;
  return config;
}

// a file with the last field of every line removed (the wall-clock columns:
// wall_ms of evaluations.csv, evals_per_s of generations.csv)
inline std::string WithoutTimingColumn(const std::string& path) {
  std::istringstream in(ReadFile(path));
  std::string line, out;
  while (std::getline(in, line)) out += line.substr(0, line.rfind(',')) + "\n";
  return out;
}

// The runs in directories a and b wrote the same files, timing aside.
inline void ExpectSameRun(const std::string& a, const std::string& b) {
  const RunFiles fa(a), fb(b);
  EXPECT_EQ(WithoutTimingColumn(fa.evaluations), WithoutTimingColumn(fb.evaluations));
  EXPECT_EQ(WithoutTimingColumn(fa.generations), WithoutTimingColumn(fb.generations));
  // checkpoint.json is internal: it records byte offsets, which the timing columns shift
  for (auto file : {&RunFiles::archive, &RunFiles::best, &RunFiles::config}) {
    EXPECT_EQ(ReadFile(fa.*file), ReadFile(fb.*file)) << fa.*file;
  }
}

}  // namespace walkers::testing
