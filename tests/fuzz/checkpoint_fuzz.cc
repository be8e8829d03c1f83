// libFuzzer target: checkpoint.json (evolve/run.h) of the run the seed
// corpus comes from (tests/fuzz/seeds/config/performance.json). Any bytes
// are either a checkpoint that run can have or refused with an InputError
// naming the file and field, never a crash or another exception; an
// accepted checkpoint written out reads back the same.
#include <cstddef>
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "evolve/run.h"
#include "files/errors.h"

namespace {

walkers::RunConfig SeedRun() {
  walkers::RunConfig config;
  config.scaffold_case = walkers::ScaffoldCase::kPerformance;
  config.generations = 3;
  config.seed = 5;
  config.ga.population = 4;
  config.ga.archive_size = 4;
  config.ga.mutation_children = 2;
  return config;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace walkers;
  static const RunConfig config = SeedRun();
  const std::string text(reinterpret_cast<const char*>(data), size);
  Checkpoint checkpoint;
  try {
    checkpoint = ParseCheckpoint(text, config, "checkpoint.json");
  } catch (const InputError&) {
    return 0;
  }
  const nlohmann::json written = CheckpointToJson(checkpoint);
  if (CheckpointToJson(ParseCheckpoint(written.dump(), config, "again.json")) != written) __builtin_trap();
  return 0;
}
