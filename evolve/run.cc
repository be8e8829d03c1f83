#include "evolve/run.h"

#include <chrono>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "evolve/files.h"

namespace walkers {
namespace fs = std::filesystem;
using nlohmann::json;

const char* const kGenerationsHeader =
    "generation,best_fitness,ave_best3,archive_mean,ceiling_half_body_x,best_half_body_x,best_femur,best_tibia,"
    "best_gait,falls,evals_per_s";

std::string EvaluationsHeader() {
  std::string h = "generation,child,parents";
  for (const GeneSpec& spec : GeneTable()) h += std::string(",") + spec.name;
  return h + ",fitness,distance,fell,gait,footsteps,trunk_contact_fraction,cvode_steps,failure,wall_ms";
}

namespace {

constexpr int kCheckpointFormat = 1;

std::string CsvQuoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string EvaluationRow(const Individual& ind) {
  std::ostringstream row;
  row << ind.generation << ',' << ind.child << ',' << ind.parents;
  for (double g : ind.genome.genes) row << ',' << FormatExact(g);
  const EvaluationResult& r = ind.result;
  row << ',' << FormatExact(r.fitness) << ',' << FormatExact(r.distance) << ',' << (r.fell ? 1 : 0) << ','
      << GaitName(r.gait) << ',' << r.footsteps << ',' << FormatExact(r.trunk_contact_fraction) << ','
      << r.cvode_steps << ',' << (r.failure.empty() ? "" : CsvQuoted(r.failure)) << ',' << FormatExact(r.wall_ms)
      << '\n';
  return row.str();
}

std::string GenerationRow(const GenerationSummary& s) {
  std::ostringstream row;
  row << s.generation << ',' << FormatExact(s.best_fitness) << ',' << FormatExact(s.ave_best3) << ','
      << FormatExact(s.archive_mean) << ',' << FormatExact(s.ceiling) << ',' << FormatExact(s.best_half_body_x) << ','
      << FormatExact(s.best_femur) << ',' << FormatExact(s.best_tibia) << ',' << GaitName(s.best_gait) << ','
      << s.falls << ',' << FormatExact(s.evals_per_s) << '\n';
  return row.str();
}

json IndividualToJson(const Individual& ind) {
  const EvaluationResult& r = ind.result;
  return {{"id", ind.id()},
          {"generation", ind.generation},
          {"child", ind.child},
          {"parents", ind.parents},
          {"fitness", r.fitness},
          {"distance", r.distance},
          {"fell", r.fell},
          {"gait", GaitName(r.gait)},
          {"footsteps", r.footsteps},
          {"trunk_contact_fraction", r.trunk_contact_fraction},
          {"cvode_steps", r.cvode_steps},
          {"failure", r.failure},
          {"genome", GenomeToJson(ind.genome)}};
}

Individual IndividualFromJson(const json& j, const std::string& source) {
  Individual ind;
  ind.generation = j.at("generation").get<int>();
  ind.child = j.at("child").get<int>();
  ind.parents = j.at("parents").get<std::string>();
  ind.genome = GenomeFromJson(j.at("genome"), source);
  EvaluationResult& r = ind.result;
  r.fitness = j.at("fitness").get<double>();
  r.distance = j.at("distance").get<double>();
  r.fell = j.at("fell").get<bool>();
  r.gait = j.at("gait").get<std::string>() == "tripod" ? Gait::kTripod : Gait::kBiped;
  r.footsteps = j.at("footsteps").get<int>();
  r.trunk_contact_fraction = j.at("trunk_contact_fraction").get<double>();
  r.cvode_steps = j.at("cvode_steps").get<long>();
  r.failure = j.at("failure").get<std::string>();
  r.leg_length = ind.genome.leg_length();
  return ind;
}

json LoadJson(const std::string& path) {
  try {
    return json::parse(ReadFile(path));
  } catch (const json::exception& e) {
    throw std::runtime_error(path + ": not valid JSON (" + e.what() + ")");
  }
}

// the genes of every evaluated genome, from evaluations.csv (written exactly)
std::set<GenomeKey> KeysOfEvaluations(const std::string& path) {
  std::set<GenomeKey> keys;
  std::istringstream in(ReadFile(path));
  std::string line;
  std::getline(in, line);  // header
  for (int row = 2; std::getline(in, line); ++row) {
    std::istringstream fields(line);
    std::string field;
    for (int i = 0; i < 3; ++i) std::getline(fields, field, ',');  // generation, child, parents
    Genome g = DefaultGenome();
    for (int k = 0; k < kNumGenes; ++k) {
      if (!std::getline(fields, field, ',')) {
        throw std::runtime_error(path + ": row " + std::to_string(row) + " has too few columns");
      }
      g.genes[k] = std::stod(field);
    }
    keys.insert(KeyOf(g));
  }
  return keys;
}

void RequireSame(const json& stored, const json& requested, const std::string& source) {
  for (const auto& item : requested.items()) {
    if (item.key() == "generations") continue;  // a resumed run may be extended
    if (!stored.contains(item.key()) || stored.at(item.key()) != item.value()) {
      throw std::runtime_error(source + ": this run has " + item.key() + " = " +
                               (stored.contains(item.key()) ? stored.at(item.key()).dump() : std::string("(none)")) +
                               " but " + item.value().dump() + " was asked for; resume with the run's own settings");
    }
  }
}

}  // namespace

void RunConfig::Validate() const {
  if (generations < 1 || generations > 10000000) {
    throw std::invalid_argument("generations = " + std::to_string(generations) +
                                " is outside its allowed range [1, 10000000]");
  }
  ga.Validate();
}

json RunConfigToJson(const RunConfig& c) {
  const IntegratorSettings& i = c.evaluation.integrator;
  return {{"case", ScaffoldCaseName(c.scaffold_case)},
          {"preset", c.preset.name},
          {"generations", c.generations},
          {"seed", c.seed},
          {"population", c.ga.population},
          {"archive_size", c.ga.archive_size},
          {"mutation_children", c.ga.mutation_children},
          {"mutation_probability", c.ga.mutation_probability},
          {"evaluation",
           {{"duration", c.evaluation.duration},
            {"relative_tolerance", i.relative_tolerance},
            {"absolute_tolerance_position", i.absolute_tolerance_position},
            {"absolute_tolerance_velocity", i.absolute_tolerance_velocity},
            {"max_order", i.max_order},
            {"contact_stiffness", c.evaluation.contact.surface.stiffness},
            {"contact_dissipation", c.evaluation.contact.surface.dissipation},
            {"friction_transition_velocity", c.evaluation.contact.transition_velocity},
            {"weld_depth", c.evaluation.weld.depth},
            {"weld_stiffness", c.evaluation.weld.stiffness},
            {"weld_angular_stiffness", c.evaluation.weld.angular_stiffness}}}};
}

RunConfig RunConfigFromJson(const json& j, const std::string& source) {
  try {
    RunConfig c;
    c.scaffold_case = ScaffoldCaseByName(j.at("case").get<std::string>());
    c.preset = PresetByName(j.at("preset").get<std::string>());
    c.generations = j.at("generations").get<int>();
    c.seed = j.at("seed").get<std::uint64_t>();
    c.ga.population = j.at("population").get<int>();
    c.ga.archive_size = j.at("archive_size").get<int>();
    c.ga.mutation_children = j.at("mutation_children").get<int>();
    c.ga.mutation_probability = j.at("mutation_probability").get<double>();
    const json& e = j.at("evaluation");
    c.evaluation.duration = e.at("duration").get<double>();
    c.evaluation.integrator.relative_tolerance = e.at("relative_tolerance").get<double>();
    c.evaluation.integrator.absolute_tolerance_position = e.at("absolute_tolerance_position").get<double>();
    c.evaluation.integrator.absolute_tolerance_velocity = e.at("absolute_tolerance_velocity").get<double>();
    c.evaluation.integrator.max_order = e.at("max_order").get<int>();
    c.evaluation.contact.surface.stiffness = e.at("contact_stiffness").get<double>();
    c.evaluation.contact.surface.dissipation = e.at("contact_dissipation").get<double>();
    c.evaluation.contact.transition_velocity = e.at("friction_transition_velocity").get<double>();
    c.evaluation.weld.depth = e.at("weld_depth").get<double>();
    c.evaluation.weld.stiffness = e.at("weld_stiffness").get<double>();
    c.evaluation.weld.angular_stiffness = e.at("weld_angular_stiffness").get<double>();
    c.Validate();
    return c;
  } catch (const json::exception& e) {
    throw std::runtime_error(source + ": " + e.what());
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(source + ": " + e.what());
  }
}

RunFiles::RunFiles(const std::string& d)
    : dir(d),
      config((fs::path(d) / "config.json").string()),
      checkpoint((fs::path(d) / "checkpoint.json").string()),
      generations((fs::path(d) / "generations.csv").string()),
      evaluations((fs::path(d) / "evaluations.csv").string()),
      archive((fs::path(d) / "archive.json").string()),
      best((fs::path(d) / "best.json").string()) {}

EvolutionRun::EvolutionRun(const RunConfig& config, const std::string& dir, StartMode mode, int threads)
    : config_(config),
      files_(dir),
      threads_(std::max(1, threads)),
      scaffold_(MakeScaffold(config.scaffold_case, config.preset)),
      archive_(config.ga.archive_size) {
  config_.Validate();
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) {
    throw std::runtime_error(dir + ": cannot create the run directory (" + ec.message() + ")");
  }
  const bool has_run = fs::exists(files_.config) || fs::exists(files_.checkpoint) ||
                       fs::exists(files_.evaluations) || fs::exists(files_.generations);
  if (mode == StartMode::kResume) {
    if (!fs::exists(files_.config)) {
      throw std::runtime_error(dir + ": no run to resume (config.json is missing)");
    }
    Resume();
    return;
  }
  if (has_run && mode == StartMode::kNew) {
    throw std::runtime_error(dir + ": holds a run already; pass --resume to continue it or --force to replace it");
  }
  StartFresh();
}

EvolutionRun::~EvolutionRun() = default;

void EvolutionRun::StartFresh() {
  // only the run's own files go; anything else in the directory stays
  for (const std::string* f : {&files_.checkpoint, &files_.generations, &files_.evaluations, &files_.archive,
                               &files_.best, &files_.config}) {
    std::error_code ec;
    fs::remove(*f, ec);
  }
  WriteFileAtomically(files_.config, RunConfigToJson(config_).dump(2) + "\n");
  WriteFileAtomically(files_.generations, std::string(kGenerationsHeader) + "\n");
  WriteFileAtomically(files_.evaluations, EvaluationsHeader() + "\n");
  completed_ = 0;
}

void EvolutionRun::Resume() {
  const json stored = LoadJson(files_.config);
  RequireSame(stored, RunConfigToJson(config_), files_.config);
  if (!fs::exists(files_.checkpoint)) {
    // killed before its first generation completed: start it again
    StartFresh();
    return;
  }
  const json cp = LoadJson(files_.checkpoint);
  try {
    if (cp.at("format").get<int>() != kCheckpointFormat) {
      throw std::runtime_error(files_.checkpoint + ": unknown checkpoint format");
    }
    completed_ = cp.at("completed_generations").get<int>();
    initial_fitness_ = cp.at("initial_fitness").get<double>();
    std::vector<Individual> members;
    for (const json& j : cp.at("archive")) members.push_back(IndividualFromJson(j, files_.checkpoint));
    archive_.Restore(std::move(members));
    // drop what was written after the checkpoint
    const auto evaluations_bytes = cp.at("evaluations_bytes").get<std::uint64_t>();
    const auto generations_bytes = cp.at("generations_bytes").get<std::uint64_t>();
    if (FileSize(files_.evaluations) < evaluations_bytes || FileSize(files_.generations) < generations_bytes) {
      throw std::runtime_error(files_.dir + ": the CSV files are shorter than the checkpoint says");
    }
    TruncateFile(files_.evaluations, evaluations_bytes);
    TruncateFile(files_.generations, generations_bytes);
  } catch (const json::exception& e) {
    throw std::runtime_error(files_.checkpoint + ": " + e.what());
  }
  if (completed_ > config_.generations) {
    throw std::runtime_error(files_.dir + ": the run has " + std::to_string(completed_) +
                             " generations already, more than the " + std::to_string(config_.generations) +
                             " asked for");
  }
  seen_ = KeysOfEvaluations(files_.evaluations);
  // a longer run than first asked for: the config says so from now on
  WriteFileAtomically(files_.config, RunConfigToJson(config_).dump(2) + "\n");
}

void EvolutionRun::Run(const std::function<void(const GenerationSummary&)>& on_generation) {
  MutationRules rules;
  rules.probability = config_.ga.mutation_probability;
  rules.body_gene = config_.preset.body_gene_mutation;
  rules.scaffold_case = config_.scaffold_case;

  for (int g = completed_; g < config_.generations; ++g) {
    // the scaffold sets this generation's ceiling from what the archive
    // achieved so far; the authors' evolver starts that measure at InitF
    const double achieved = g == 0 ? initial_fitness_ : archive_.AverageOfBest(3);
    const double ceiling = scaffold_->Ceiling({g, achieved, initial_fitness_});
    std::vector<Individual> children = Breed(config_.ga, {config_.seed, g, ceiling, rules}, archive_, &seen_);

    const auto start = std::chrono::steady_clock::now();
    EvaluateAll(&children, config_.preset, config_.evaluation, threads_);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    archive_.Merge(children);

    GenerationSummary s;
    s.generation = g;
    s.generations = config_.generations;
    s.best_fitness = archive_.best().fitness();
    s.ave_best3 = archive_.AverageOfBest(3);
    s.archive_mean = archive_.Mean();
    s.ceiling = ceiling;
    s.best_half_body_x = archive_.best().genome[kHalfBodyX];
    s.best_femur = archive_.best().genome[kFemurLength];
    s.best_tibia = archive_.best().genome[kTibiaLength];
    s.best_gait = archive_.best().result.gait;
    for (const Individual& c : children) s.falls += c.result.fell ? 1 : 0;
    s.evaluations = static_cast<int>(children.size());
    s.evaluation_seconds = seconds;
    s.evals_per_s = seconds > 0 ? children.size() / seconds : 0.0;

    // the rows reach the disk first; the checkpoint then names them
    std::string rows;
    for (const Individual& c : children) rows += EvaluationRow(c);
    const std::uint64_t evaluations_bytes = AppendDurably(files_.evaluations, rows);
    const std::uint64_t generations_bytes = AppendDurably(files_.generations, GenerationRow(s));
    completed_ = g + 1;
    WriteCheckpoint(evaluations_bytes, generations_bytes);
    if (on_generation) on_generation(s);
  }
  WriteResults();
}

void EvolutionRun::WriteCheckpoint(std::uint64_t evaluations_bytes, std::uint64_t generations_bytes) {
  json members = json::array();
  for (const Individual& ind : archive_.members()) members.push_back(IndividualToJson(ind));
  const json cp = {{"format", kCheckpointFormat},
                   {"completed_generations", completed_},
                   {"initial_fitness", initial_fitness_},
                   {"evaluations_bytes", evaluations_bytes},
                   {"generations_bytes", generations_bytes},
                   {"archive", members}};
  WriteFileAtomically(files_.checkpoint, cp.dump() + "\n");
}

void EvolutionRun::WriteResults() {
  json members = json::array();
  for (const Individual& ind : archive_.members()) members.push_back(IndividualToJson(ind));
  const json out = {{"case", ScaffoldCaseName(config_.scaffold_case)},
                    {"preset", config_.preset.name},
                    {"generations", completed_},
                    {"initial_fitness", initial_fitness_},
                    {"archive", members}};
  WriteFileAtomically(files_.archive, out.dump(2) + "\n");
  WriteFileAtomically(files_.best, GenomeToJson(archive_.best().genome).dump(2) + "\n");
}

}  // namespace walkers
