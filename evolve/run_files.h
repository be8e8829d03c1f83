// A run's files and their formats: checkpoint.json, the CSV files' rows and
// archive.json (config.json's is evolve/run_config.h's); what they must hold
// to be read back, and the checks a resume makes of them before anything is
// written.
//
// DIR/config.json       everything needed to rerun
// DIR/generations.csv   one row per generation
// DIR/evaluations.csv   one row per evaluation
// DIR/checkpoint.json   the last complete generation (atomic; names the CSVs' sizes)
// DIR/archive.json      the final archive, best first, with fitness
// DIR/best.json         the best genome (a genome file)
#pragma once

#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evolve/individual.h"
#include "evolve/run_config.h"

namespace walkers {

// What checkpoint.json holds: the run after its last complete generation.
struct Checkpoint {
  int completed_generations = 0;
  double initial_fitness = 0;
  std::uint64_t evaluations_bytes = 0;  // the CSV files' sizes after that generation
  std::uint64_t generations_bytes = 0;
  std::vector<Individual> archive;      // best first
  nlohmann::json learner;               // the learner's state (Learner::State); null for the GA
};

nlohmann::json CheckpointToJson(const Checkpoint& checkpoint);
// Parses a checkpoint of the run configured as `config` (its config.json)
// strictly: every field present, typed and in range; at least one and at most
// config.generations generations; the archive as large as that many
// generations of config.ga fill it, best first, each member's generation and
// child within the run and its genome valid; the learner's state, for a
// learner that keeps one, one that learner restores (Learner::Restore).
// Throws InputError whose message starts with `source` and names the field.
Checkpoint ParseCheckpoint(const std::string& text, const RunConfig& config, const std::string& source);

// archive.json of a finished run configured as `config`, checked as a
// checkpoint's archive is. Throws InputError naming the file.
std::vector<Individual> LoadArchive(const std::string& path, const RunConfig& config);

// The file names of a run, inside its directory.
struct RunFiles {
  explicit RunFiles(const std::string& dir);
  std::string dir, config, checkpoint, generations, evaluations, archive, best;
  // a finished run's finals (evolve/finals.h), for readers without evaluations.csv
  std::string finals;

  // every run file above (not dir)
  static const std::vector<std::string RunFiles::*>& All();
  // their names inside dir: "config.json", ...
  static std::vector<std::string> Names();
};

// The CSV headers, for readers of the files.
extern const char* const kGenerationsHeader;
std::string EvaluationsHeader();

// The rows a generation adds to evaluations.csv (one per child) and to
// generations.csv.
std::string EvaluationRow(const Individual& individual);
std::string GenerationRow(const GenerationSummary& summary);

// archive.json's content for a run of `completed` generations.
nlohmann::json ArchiveFileJson(const RunConfig& config, int completed, double initial_fitness,
                               const std::vector<Individual>& members);

// The CSV files of the run in `files` up to the checkpoint's sizes, for a
// resume: this program's headers, whole rows, the checkpoint's generations
// in order, every archive member among the evaluations. Returns the genomes
// evaluated so far. Throws InputError naming the file.
std::set<GenomeKey> CheckRunFilesUpTo(const RunFiles& files, const Checkpoint& checkpoint, const RunConfig& config);

// A run folder without checkpoint.json may start again only if the run had
// not completed a generation: throws InputError saying what to do if
// it has results beyond that.
void CheckNoResultsWithoutCheckpoint(const RunFiles& files, const RunConfig& config);

}  // namespace walkers
