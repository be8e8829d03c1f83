#include "control/genome.h"

#include <nlohmann/json.hpp>

#include "files/durable_file.h"
#include "files/input_file.h"

namespace walkers {
namespace {

// paper Table 1 (docs/model.md, "Genome"): name, default, floor, ceiling;
// sigma = default / divisor
struct GeneRow {
  const char* name;
  double default_value, floor, ceiling, sigma_divisor;
};

// clang-format off
constexpr GeneRow kGeneRows[kNumGenes] = {
    {"halfBodyX",       0.8822120184545844,    0.05,   0.9,   3},
    {"halfBodyY",       0.1353015130243578,    0.05,   0.3,   3},
    {"halfBodyZ",       0.329704208858325,     0.25,   0.4,   3},
    {"halfFootX",       0.22018185203456214,   0.05,   0.4,   3},
    {"halfFootY",       0.05,                  0.05,   0.4,   3},
    {"halfFootZ",       0.06957592968690621,   0.05,   0.23,  3},
    {"kx",              1572.4184169068672,    0,      20000, 5},
    {"ky",              6980.007289620993,     3000,   24000, 5},
    {"lambdaX",         756.2758489218877,     0,      2000,  5},
    {"lambdaY",         1930.5445286783713,    0,      2000,  5},
    {"kTheta",          300,                   0,      300,   5},
    {"lambdaTheta",     103.77362891303223,    0,      300,   11},
    {"kStep",           206.62152951267495,    0,      800,   5},
    {"stableTolerance", 0.23297511065336013,   0,      0.25,  5},
    {"tibiaLength",     0.6845846448329076,    0.1,    1.9,   5},
    {"femurLength",     0.5301194705959408,    0.1,    1.9,   5},
    {"standOffset",     0.014009581796928235,  -0.2,   0.35,  5},
    {"stepOffset",      -0.00213586038101777,  -1.0,   0.3,   5},
};
// clang-format on

struct MassKey {
  const char* name;
  double Genome::*field;
};
constexpr MassKey kMassKeys[] = {
    {"kneeMass", &Genome::knee_mass}, {"ankleMass", &Genome::ankle_mass}, {"hipMass", &Genome::hip_mass}};

constexpr NumberRange kMassRange{0.0, 1000.0, true};  // [kg]

}  // namespace

const std::array<GeneSpec, kNumGenes>& GeneTable() {
  static const std::array<GeneSpec, kNumGenes> table = [] {
    std::array<GeneSpec, kNumGenes> t{};
    for (int i = 0; i < kNumGenes; ++i) {
      const GeneRow& r = kGeneRows[i];
      t[i] = {r.name, r.default_value, r.floor, r.ceiling, r.default_value / r.sigma_divisor};
    }
    return t;
  }();
  return table;
}

Genome DefaultGenome() {
  Genome g;
  for (int i = 0; i < kNumGenes; ++i) g.genes[i] = GeneTable()[i].default_value;
  return g;
}

BodyParameters BodyOf(const Genome& g) {
  BodyParameters b;
  b.half_body_x = g[kHalfBodyX];
  b.half_body_y = g[kHalfBodyY];
  b.half_body_z = g[kHalfBodyZ];
  b.half_foot_x = g[kHalfFootX];
  b.half_foot_y = g[kHalfFootY];
  b.half_foot_z = g[kHalfFootZ];
  b.femur_length = g[kFemurLength];
  b.tibia_length = g[kTibiaLength];
  b.knee_mass = g.knee_mass;
  b.ankle_mass = g.ankle_mass;
  b.hip_mass = g.hip_mass;
  return b;
}

nlohmann::json GenomeToJson(const Genome& genome) {
  nlohmann::json json = nlohmann::json::object();
  for (int i = 0; i < kNumGenes; ++i) json[GeneTable()[i].name] = genome.genes[i];
  for (const MassKey& m : kMassKeys) json[m.name] = genome.*m.field;
  return json;
}

Genome GenomeFromJson(const nlohmann::json& json, const std::string& source) {
  if (!json.is_object()) throw InputError(source + ": a genome must be a JSON object of gene names to numbers");
  const JsonFields genes(json, source, "", "gene");
  // every key must be a known gene or mass
  std::vector<std::string> known;
  for (const GeneSpec& spec : GeneTable()) known.push_back(spec.name);
  for (const MassKey& m : kMassKeys) known.push_back(m.name);
  genes.RequireOnly(known);

  Genome genome;
  for (int i = 0; i < kNumGenes; ++i) {
    const GeneSpec& spec = GeneTable()[i];
    genome.genes[i] = genes.Number(spec.name, {i == kHalfBodyX ? kMinFileHalfBodyX : spec.floor, spec.ceiling});
  }
  for (const MassKey& m : kMassKeys) genome.*m.field = genes.Number(m.name, kMassRange);
  return genome;
}

Genome LoadGenome(const std::string& path) { return GenomeFromJson(LoadJsonFile(path), path); }

void SaveGenome(const Genome& genome, const std::string& path) {
  WriteFileAtomically(path, GenomeToJson(genome).dump(2) + "\n");
}

}  // namespace walkers
