// libFuzzer target: genome files (control/genome.h). Any bytes are either a
// genome or refused with an InputError, never a crash or
// another exception; an accepted genome written out reads back bit for bit.
#include <cstddef>
#include <cstdint>
#include <string>

#include "control/genome.h"
#include "files/input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace walkers;
  const std::string text(reinterpret_cast<const char*>(data), size);
  Genome genome;
  try {
    genome = GenomeFromJson(ParseJson(text, "genome.json"), "genome.json");
  } catch (const InputError&) {
    return 0;
  }
  const Genome again = GenomeFromJson(ParseJson(GenomeToJson(genome).dump(), "again.json"), "again.json");
  if (again.genes != genome.genes || again.knee_mass != genome.knee_mass || again.ankle_mass != genome.ankle_mass ||
      again.hip_mass != genome.hip_mass) {
    __builtin_trap();
  }
  return 0;
}
