#include "control/genome.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

namespace walkers {
namespace {

// MODEL.md §1: name, default, floor, ceiling; sigma = default / divisor
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

std::string Format(double x) {
  std::ostringstream out;
  out.precision(17);
  out << x;
  return out.str();
}

double ReadNumber(const nlohmann::json& json, const char* key, const std::string& source) {
  if (!json.contains(key)) throw GenomeError(source + ": missing gene '" + key + "'");
  const nlohmann::json& value = json.at(key);
  if (!value.is_number()) {
    throw GenomeError(source + ": gene '" + key + "' must be a number, got " + value.dump());
  }
  const double x = value.get<double>();
  if (!std::isfinite(x)) throw GenomeError(source + ": gene '" + key + "' is not finite");
  return x;
}

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
  if (!json.is_object()) throw GenomeError(source + ": a genome must be a JSON object of gene names to numbers");

  // every key must be a known gene or mass
  for (const auto& item : json.items()) {
    bool known = false;
    for (const GeneSpec& spec : GeneTable()) known = known || item.key() == spec.name;
    for (const MassKey& m : kMassKeys) known = known || item.key() == m.name;
    if (!known) throw GenomeError(source + ": unknown gene '" + item.key() + "'");
  }

  Genome genome;
  for (int i = 0; i < kNumGenes; ++i) {
    const GeneSpec& spec = GeneTable()[i];
    const double x = ReadNumber(json, spec.name, source);
    const double floor = i == kHalfBodyX ? kMinFileHalfBodyX : spec.floor;
    if (x < floor || x > spec.ceiling) {
      throw GenomeError(source + ": gene '" + spec.name + "' = " + Format(x) + " is outside its allowed range [" +
                        Format(floor) + ", " + Format(spec.ceiling) + "]");
    }
    genome.genes[i] = x;
  }
  for (const MassKey& m : kMassKeys) {
    const double x = ReadNumber(json, m.name, source);
    if (!(x > 0.0) || x > 1000.0) {
      throw GenomeError(source + ": gene '" + m.name + "' = " + Format(x) +
                        " is outside its allowed range (0, 1000] kg");
    }
    genome.*m.field = x;
  }
  return genome;
}

Genome LoadGenome(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw GenomeError(path + ": cannot open genome file");
  // remember the last key read, to name the gene of a number that overflows
  std::string last_key;
  auto track_keys = [&last_key](int /*depth*/, nlohmann::json::parse_event_t event, nlohmann::json& parsed) {
    if (event == nlohmann::json::parse_event_t::key) last_key = parsed.get<std::string>();
    return true;
  };
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(in, track_keys);
  } catch (const nlohmann::json::out_of_range& e) {
    throw GenomeError(path + ": gene '" + last_key + "' is not a finite number (" + e.what() + ")");
  } catch (const nlohmann::json::exception& e) {
    throw GenomeError(path + ": not valid JSON (" + e.what() + ")");
  }
  return GenomeFromJson(json, path);
}

void SaveGenome(const Genome& genome, const std::string& path) {
  std::ofstream out(path);
  if (!out) throw GenomeError(path + ": cannot write genome file");
  out << GenomeToJson(genome).dump(2) << "\n";
  if (!out) throw GenomeError(path + ": writing the genome file failed");
}

}  // namespace walkers
