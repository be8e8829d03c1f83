// libFuzzer target: a run's config.json (evolve/run.h). Any bytes are either
// a valid configuration or refused with an InputError naming the file,
// never a crash or another exception; an accepted configuration written out
// reads back the same.
#include <cstddef>
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "evolve/run.h"
#include "files/errors.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace walkers;
  const std::string text(reinterpret_cast<const char*>(data), size);
  RunConfig config;
  try {
    config = ParseRunConfig(text, "config.json");
  } catch (const InputError&) {
    return 0;
  }
  const nlohmann::json written = RunConfigToJson(config);
  if (RunConfigToJson(ParseRunConfig(written.dump(2), "again.json")) != written) __builtin_trap();
  return 0;
}
