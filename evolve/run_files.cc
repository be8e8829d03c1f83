#include "evolve/run_files.h"

#include <algorithm>
#include <set>
#include <filesystem>
#include <limits>
#include <optional>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "files/csv.h"
#include "files/input_file.h"
#include "files/number_text.h"
#include "files/results_folder.h"

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

}  // namespace

std::string EvaluationRow(const Individual& ind) {
  std::ostringstream row;
  row << ind.generation << ',' << ind.child << ',' << ind.lineage.Text();
  for (double g : ind.genome.genes) row << ',' << FormatExact(g);
  const EvaluationResult& r = ind.result;
  row << ',' << FormatExact(r.fitness) << ',' << FormatExact(r.distance) << ','
      << (r.outcome == Outcome::kFell ? 1 : 0) << ',' << GaitName(r.gait) << ',' << r.footsteps << ','
      << FormatExact(r.trunk_contact_fraction) << ',' << r.integrator_stats.steps << ','
      << (r.outcome == Outcome::kFailed ? CsvQuoted(r.reason) : "") << ',' << FormatExact(r.wall_ms) << '\n';
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

namespace {

json IndividualToJson(const Individual& ind) {
  const EvaluationResult& r = ind.result;
  return {{"id", ind.id()},
          {"generation", ind.generation},
          {"child", ind.child},
          {"parents", ind.lineage.Text()},
          {"fitness", r.fitness},
          {"distance", r.distance},
          {"fell", r.outcome == Outcome::kFell},
          {"gait", GaitName(r.gait)},
          {"footsteps", r.footsteps},
          {"trunk_contact_fraction", r.trunk_contact_fraction},
          {"cvode_steps", r.integrator_stats.steps},
          {"failure", r.reason},
          {"genome", GenomeToJson(ind.genome)}};
}

json MembersToJson(const std::vector<Individual>& members) {
  json out = json::array();
  for (const Individual& ind : members) out.push_back(IndividualToJson(ind));
  return out;
}


}  // namespace

json ArchiveFileJson(const RunConfig& c, int completed, double initial_fitness, const std::vector<Individual>& members) {
  json out = {{"case", ScaffoldCaseName(c.scaffold_case)},
              {"preset", c.preset.name},
              {"generations", completed},
              {"initial_fitness", initial_fitness},
              {"archive", MembersToJson(members)}};
  if (NamesLearner(c)) out["learner"] = c.learner;
  return out;
}

namespace {

// The gaits files may name.
constexpr Gait kGaits[] = {Gait::kBiped, Gait::kTripod, Gait::kNone};

Gait GaitFromName(const JsonFields& f, const std::string& key) {
  std::vector<std::string> names;
  for (Gait g : kGaits) names.push_back(GaitName(g));
  const std::string name = f.OneOf(key, names);
  for (Gait g : kGaits) {
    if (name == GaitName(g)) return g;
  }
  return Gait::kBiped;  // not reached: OneOf refused it
}

// The outcome a member's fields spell: "fell", a "failure"'s reason, or a
// cut-off's fitness (control/evaluation.h).
Outcome OutcomeFromFields(const JsonFields& f, double fitness) {
  const bool fell = f.Bool("fell");
  const bool failed = !f.String("failure").empty();
  if (fell && failed) {
    f.Fail("failure", "= " + f.Get("failure").dump() + " names a failure, but the walker fell: an evaluation falls or "
                      "fails, not both");
  }
  if (fell) return Outcome::kFell;
  if (failed) return Outcome::kFailed;
  return fitness == kCutOffFitness ? Outcome::kCutOff : Outcome::kWalked;
}

// An archive member of a run of `generations` generations of `population` children.
Individual IndividualFromJson(const JsonFields& f, int generations, int population) {
  f.RequireOnly(KeysOf(IndividualToJson(Individual{})));
  Individual ind;
  ind.generation = static_cast<int>(f.Integer("generation", 0, generations - 1));
  ind.child = static_cast<int>(f.Integer("child", 0, population - 1));
  if (f.String("id") != ind.id()) f.Fail("id", "is not \"" + ind.id() + "\", its generation and child");
  const std::optional<Lineage> lineage = Lineage::FromText(f.String("parents"));
  if (!lineage) {
    f.Fail("parents", "= " + f.Get("parents").dump() +
                          " is not a lineage: \"\", \"g/c\", \"g/c+g/c\" or a learner's name, then \" clamped\" or "
                          "\" redrawn\" any number of times");
  }
  ind.lineage = *lineage;
  ind.genome = GenomeFromJson(f.Get("genome"), f.source() + ": " + f.Name("genome"));
  EvaluationResult& r = ind.result;
  r.fitness = f.Number("fitness");
  r.distance = f.Number("distance");
  r.outcome = OutcomeFromFields(f, r.fitness);
  r.reason = f.String("failure");
  r.gait = GaitFromName(f, "gait");
  r.footsteps = static_cast<int>(f.Integer("footsteps", 0, std::numeric_limits<int>::max()));
  r.trunk_contact_fraction = f.Number("trunk_contact_fraction", {0.0, 1.0});
  r.integrator_stats.steps = static_cast<long>(f.Integer("cvode_steps", 0, std::numeric_limits<long>::max()));
  r.leg_length = ind.genome.leg_length();
  return ind;
}

// InitF of the performance scaffold: positive (kAuthorsInitialFitness)
constexpr NumberRange kInitialFitnessRange{0, 1000, true};

// The rows a checkpoint names: the first `bytes` bytes of a CSV file, whose
// header must be `header`; calls row(reader, index) for each. Returns how many.
template <typename OnRow>
long CheckedRows(const std::string& path, std::uint64_t bytes, const std::string& header, const OnRow& row) {
  std::string text = ReadFile(path);
  if (text.size() < bytes) {
    throw InputError(path + ": " + std::to_string(text.size()) + " bytes, shorter than the " + std::to_string(bytes) +
                     " the checkpoint says");
  }
  text.resize(bytes);
  if (text.empty() || text.back() != '\n') {
    throw InputError(path + ": the checkpoint's size of " + std::to_string(bytes) + " bytes ends within a row");
  }
  if (text.compare(0, header.size() + 1, header + "\n") != 0) {
    throw InputError(path + ": its header is not this program's (" + header.substr(0, 40) + "...)");
  }
  CsvReader reader(std::move(text), path);
  long rows = 0;
  while (reader.Next()) row(reader, rows++);
  return rows;
}

// data rows (lines after the header) of a file, 0 if there is none
long DataRows(const std::string& path) {
  if (!fs::exists(path)) return 0;
  const std::string text = ReadFile(path);
  const long lines = static_cast<long>(std::count(text.begin(), text.end(), '\n'));
  return std::max(0L, lines - 1);
}

// The archive of f's "archive" after `completed` generations: as large as
// they make it, best first, each member's generation and child within them.
std::vector<Individual> ArchiveFromJson(const JsonFields& f, int completed, const GeneticAlgorithmConfig& ga) {
  const json& members = f.Array("archive");
  const long size = std::min<long>(ga.archive_size, static_cast<long>(completed) * ga.population);
  if (static_cast<long>(members.size()) != size) {
    f.Fail("archive", "has " + std::to_string(members.size()) + " members; " + std::to_string(completed) +
                          " generations of " + std::to_string(ga.population) + " children fill " +
                          std::to_string(size));
  }
  std::vector<Individual> archive;
  for (std::size_t i = 0; i < members.size(); ++i) {
    const std::string where = "archive[" + std::to_string(i) + "]";
    Individual ind = IndividualFromJson(JsonFields(members[i], f.source(), where + "."), completed, ga.population);
    if (!archive.empty() && !Fitter(archive.back(), ind)) {
      f.Fail(where, "(" + ind.id() + ") is not after archive[" + std::to_string(i - 1) +
                        "] in the archive's order: fitter first, then older");
    }
    archive.push_back(std::move(ind));
  }
  return archive;
}

}  // namespace


json CheckpointToJson(const Checkpoint& cp) {
  json out = {{"format", kCheckpointFormat},
              {"completed_generations", cp.completed_generations},
              {"initial_fitness", cp.initial_fitness},
              {"evaluations_bytes", cp.evaluations_bytes},
              {"generations_bytes", cp.generations_bytes},
              {"archive", MembersToJson(cp.archive)}};
  if (!cp.learner.is_null()) out["learner"] = cp.learner;
  return out;
}

Checkpoint ParseCheckpoint(const std::string& text, const RunConfig& config, const std::string& source) {
  const json j = ParseJson(text, source);
  const JsonFields f(j, source);
  // a learner with a state of its own keeps it here; the GA has none
  const std::unique_ptr<Learner> learner = MakeLearner(config.learner, config.ga, config.seed);
  std::vector<std::string> known = KeysOf(CheckpointToJson(Checkpoint{}));
  if (learner->KeepsState()) known.push_back("learner");
  f.RequireOnly(known);
  const std::int64_t format = f.Integer("format", std::numeric_limits<std::int64_t>::min(),
                                        std::numeric_limits<std::int64_t>::max());
  if (format != kCheckpointFormat) {
    f.Fail("format", "= " + std::to_string(format) + ": this program reads format " +
                         std::to_string(kCheckpointFormat) + " only");
  }
  Checkpoint cp;
  cp.completed_generations = static_cast<int>(f.Integer("completed_generations", 1, config.generations));
  cp.initial_fitness = f.Number("initial_fitness", kInitialFitnessRange);
  cp.evaluations_bytes = f.Unsigned("evaluations_bytes", std::numeric_limits<std::int64_t>::max());
  cp.generations_bytes = f.Unsigned("generations_bytes", std::numeric_limits<std::int64_t>::max());
  cp.archive = ArchiveFromJson(f, cp.completed_generations, config.ga);
  if (learner->KeepsState()) {
    cp.learner = f.Get("learner");
    learner->Restore(cp.learner, cp.completed_generations, source);
  }
  return cp;
}

std::vector<Individual> LoadArchive(const std::string& path, const RunConfig& config) {
  const json j = LoadJsonFile(path);
  const JsonFields f(j, path);
  f.RequireOnly(KeysOf(ArchiveFileJson(config, 0, 0.0, {})));
  if (f.String("case") != ScaffoldCaseName(config.scaffold_case) || f.String("preset") != config.preset.name) {
    f.Fail("case", "and 'preset' are not the run's (" + std::string(ScaffoldCaseName(config.scaffold_case)) + ", " +
                       config.preset.name + ")");
  }
  if (NamesLearner(config) && f.String("learner") != config.learner) {
    f.Fail("learner", "is not the run's (" + config.learner + ")");
  }
  const int completed = static_cast<int>(f.Integer("generations", 1, config.generations));
  f.Number("initial_fitness", kInitialFitnessRange);
  return ArchiveFromJson(f, completed, config.ga);
}

RunFiles::RunFiles(const std::string& d)
    : dir(d),
      config((fs::path(d) / "config.json").string()),
      checkpoint((fs::path(d) / "checkpoint.json").string()),
      generations((fs::path(d) / "generations.csv").string()),
      evaluations((fs::path(d) / "evaluations.csv").string()),
      archive((fs::path(d) / "archive.json").string()),
      best((fs::path(d) / "best.json").string()),
      finals((fs::path(d) / "finals.json").string()) {}

const std::vector<std::string RunFiles::*>& RunFiles::All() {
  static const std::vector<std::string RunFiles::*> all = {&RunFiles::config,      &RunFiles::checkpoint,
                                                           &RunFiles::generations, &RunFiles::evaluations,
                                                           &RunFiles::archive,     &RunFiles::best,
                                                           &RunFiles::finals};
  return all;
}

std::vector<std::string> RunFiles::Names() {
  const RunFiles files("");
  std::vector<std::string> names;
  for (auto file : All()) names.push_back(fs::path(files.*file).filename().string());
  return names;
}

std::set<GenomeKey> CheckRunFilesUpTo(const RunFiles& files, const Checkpoint& cp, const RunConfig& config) {
  // the CSV files up to the checkpoint: its generations, in order, every row whole
  const int population = config.ga.population;
  std::set<GenomeKey> seen;
  const long evaluations = CheckedRows(
      files.evaluations, cp.evaluations_bytes, EvaluationsHeader(), [&](const CsvReader& row, long index) {
        row.Integer(0, index / population, index / population);  // generation
        row.Integer(1, index % population, index % population);  // child
        Genome g = DefaultGenome();
        for (int k = 0; k < kNumGenes; ++k) g.genes[k] = row.Number(3 + k);
        seen.insert(KeyOf(g));
      });
  const long expected = static_cast<long>(cp.completed_generations) * population;
  if (evaluations != expected) {
    throw InputError(files.evaluations + ": " + std::to_string(evaluations) +
                     " rows up to the checkpoint, which says " + std::to_string(cp.completed_generations) +
                     " generations of " + std::to_string(population) + " (" + std::to_string(expected) + ")");
  }
  const long generations = CheckedRows(files.generations, cp.generations_bytes, kGenerationsHeader,
                                       [](const CsvReader& row, long index) { row.Integer(0, index, index); });
  if (generations != cp.completed_generations) {
    throw InputError(files.generations + ": " + std::to_string(generations) +
                     " rows up to the checkpoint, which says " + std::to_string(cp.completed_generations));
  }
  for (const Individual& ind : cp.archive) {
    if (!seen.count(KeyOf(ind.genome))) {
      throw InputError(files.checkpoint + ": archive member " + ind.id() + " is not in " + files.evaluations);
    }
  }
  return seen;
}

void CheckNoResultsWithoutCheckpoint(const RunFiles& files, const RunConfig& config) {
  // a run killed before its first checkpoint has written at most generation
  // 0's rows; anything more had a checkpoint, and starting again would hide
  // that it went missing
  const long generation_rows = DataRows(files.generations), evaluation_rows = DataRows(files.evaluations);
  std::string results;
  if (generation_rows > 1) results = "generations.csv has " + std::to_string(generation_rows) + " rows";
  if (results.empty() && evaluation_rows > config.ga.population) {
    results = "evaluations.csv has " + std::to_string(evaluation_rows) + " rows";
  }
  for (const std::string* f : {&files.archive, &files.best}) {
    if (results.empty() && fs::exists(*f)) results = fs::path(*f).filename().string() + " exists";
  }
  if (!results.empty()) {
    throw InputError(files.checkpoint + ": missing, but the run has results (" + results +
                     "); restore checkpoint.json to resume the run, or pass --force to start it again "
                     "(the old files are kept in " + SetAside::FolderIn(files.dir) +
                     " until the new run's first generation is written)");
  }
}

}  // namespace walkers
