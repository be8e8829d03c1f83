// One individual: the 18 evolved genes of paper Table 1 and three fixed point
// masses (docs/model.md, "Genome"), with their bounds, JSON files and
// validation.
#pragma once

#include <array>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "dynamics/model.h"

namespace walkers {

enum Gene : int {
  kHalfBodyX,
  kHalfBodyY,
  kHalfBodyZ,
  kHalfFootX,
  kHalfFootY,
  kHalfFootZ,
  kKx,
  kKy,
  kLambdaX,
  kLambdaY,
  kKTheta,
  kLambdaTheta,
  kKStep,
  kStableTolerance,
  kTibiaLength,
  kFemurLength,
  kStandOffset,
  kStepOffset,
  kNumGenes
};

struct GeneSpec {
  const char* name;      // key in genome files, the paper's name
  double default_value;  // the initial individual
  double floor;          // mutation floor
  double ceiling;        // mutation ceiling (halfBodyX: lowered by scaffolds)
  double sigma;          // mutation standard deviation
};

const std::array<GeneSpec, kNumGenes>& GeneTable();

// Genome files accept halfBodyX down to this, below its mutation floor: the
// authors' case-3 formula left evolved genomes at 0.033–0.044 (docs/model.md,
// "Genome").
constexpr double kMinFileHalfBodyX = 0.01;

struct Genome {
  std::array<double, kNumGenes> genes{};
  double knee_mass = 0.7;   // [kg] fixed, not evolved
  double ankle_mass = 0.1;  // [kg]
  double hip_mass = 0.1;    // [kg]

  double operator[](Gene g) const { return genes[g]; }
  double& operator[](Gene g) { return genes[g]; }
  double leg_length() const { return genes[kTibiaLength] + genes[kFemurLength]; }
};

// The initial individual.
Genome DefaultGenome();

// The physical sizes the dynamics needs.
BodyParameters BodyOf(const Genome& genome);

// JSON object whose keys are exactly the gene and mass names.
nlohmann::json GenomeToJson(const Genome& genome);
// Validates every key and value: InputError (files/errors.h) naming `source`,
// the gene, the value and the allowed range.
Genome GenomeFromJson(const nlohmann::json& json, const std::string& source);

// Parses the file strictly (files/input_file.h: a key given twice is
// refused), then as GenomeFromJson.
Genome LoadGenome(const std::string& path);
// Writes a genome file atomically (files/durable_file.h); throws
// std::runtime_error naming the file on failure.
void SaveGenome(const Genome& genome, const std::string& path);

}  // namespace walkers
