#include "evolve/reproduction.h"

#include <filesystem>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "control/walk_record.h"
#include "evolve/files.h"

namespace walkers {
namespace fs = std::filesystem;
using nlohmann::json;

void ReproductionConfig::Validate() const {
  if (replicates < 1 || replicates > 1000) {
    throw std::invalid_argument("replicates = " + std::to_string(replicates) + " is outside its allowed range [1, 1000]");
  }
  RunConfig probe;
  probe.generations = generations;
  probe.ga = ga;
  probe.Validate();
}

std::vector<PlannedRun> PlanRuns(const ReproductionConfig& config) {
  std::vector<PlannedRun> runs;
  for (ScaffoldCase c : {ScaffoldCase::kFree, ScaffoldCase::kTime, ScaffoldCase::kPerformance}) {
    for (int r = 1; r <= config.replicates; ++r) {
      PlannedRun run{c, r, std::string(ScaffoldCaseName(c)) + "-" + std::to_string(r), RunConfig{}};
      run.config.scaffold_case = c;
      run.config.preset = config.preset;
      run.config.generations = config.generations;
      run.config.seed = config.seed + static_cast<std::uint64_t>(r - 1);
      run.config.ga = config.ga;
      run.config.evaluation = config.evaluation;
      runs.push_back(run);
    }
  }
  return runs;
}

ReproductionSummary Reproduce(const ReproductionConfig& config, const std::string& dir, bool resume, int threads,
                              const ReproductionObserver& observer) {
  config.Validate();
  const std::vector<PlannedRun> plan = PlanRuns(config);
  if (!resume) {
    for (const PlannedRun& run : plan) {
      if (fs::exists(fs::path(dir) / run.name)) {
        throw std::runtime_error(dir + ": holds runs already (" + run.name + "); pass --resume to continue them");
      }
    }
  }
  for (const PlannedRun& run : plan) {
    const std::string run_dir = (fs::path(dir) / run.name).string();
    const bool started = fs::exists(RunFiles(run_dir).config);
    EvolutionRun evolution(run.config, run_dir, started ? StartMode::kResume : StartMode::kNew, threads);
    if (observer.on_run_start) observer.on_run_start(run, evolution.completed_generations());
    evolution.Run([&](const GenerationSummary& s) {
      if (observer.on_generation) observer.on_generation(run, s);
    });
  }
  return WriteReproductionResults(config, dir);
}

ReproductionSummary WriteReproductionResults(const ReproductionConfig& config, const std::string& dir) {
  const std::vector<PlannedRun> plan = PlanRuns(config);
  std::vector<RunData> data;
  json runs = json::array();
  json gallery = json::array();
  for (const PlannedRun& run : plan) {
    const std::string run_dir = (fs::path(dir) / run.name).string();
    data.push_back(LoadRunData(run_dir, run.scaffold_case, run.replicate, run.name));
    // the gallery, standing: the run's final best and, when that is a biped,
    // the best tripod the run evaluated
    const json archive = json::parse(ReadFile(RunFiles(run_dir).archive));
    const json& best = archive.at("archive").at(0);
    const auto add_to_gallery = [&](const std::string& label, const json& id, const std::string& gait,
                                    double fitness, const Genome& genome) {
      gallery.push_back({{"label", label},
                         {"run", run.name},
                         {"id", id},
                         {"gait", gait},
                         {"fitness", fitness},
                         {"body", BodyJson(BuildModel(BodyOf(genome)))},
                         {"pose", StartPoseJson(genome)}});
    };
    add_to_gallery(run.name + " best", best.at("id"), best.at("gait"), best.at("fitness"),
                   GenomeFromJson(best.at("genome"), RunFiles(run_dir).archive));
    const std::optional<EvaluatedSummary>& tripod = data.back().best_tripod;
    if (best.at("gait") != "tripod" && tripod) {
      add_to_gallery(run.name + " tripod", tripod->id, "tripod", tripod->fitness, tripod->genome);
    }
    runs.push_back({{"case", ScaffoldCaseName(run.scaffold_case)},
                    {"replicate", run.replicate},
                    {"dir", run.name},
                    {"seed", run.config.seed},
                    {"final_best_fitness", data.back().best_fitness.back()},
                    {"final_best_gait", data.back().best_is_tripod.back() ? "tripod" : "biped"},
                    {"evaluations", data.back().evaluations},
                    {"evaluation_seconds", data.back().evaluation_seconds}});
  }
  const ReproductionSummary summary = Summarize(data);

  // the best biped's and the best tripod's walks, again, frame by frame
  json walks = {{"biped", nullptr}, {"tripod", nullptr}};
  for (const auto& [key, best] : {std::pair{"biped", summary.best_biped}, std::pair{"tripod", summary.best_tripod}}) {
    if (!best) continue;
    RecordedWalk walk = RecordWalk(best->genome, config.preset,
                                   std::string("best ") + key + ": " + best->run + " " + best->id, config.evaluation);
    walk.json["run"] = best->run;
    walk.json["id"] = best->id;
    walks[key] = walk.json;
  }

  json out = SummaryToJson(summary);
  out["preset"] = config.preset.name;
  out["generations"] = config.generations;
  out["replicates"] = config.replicates;
  out["seed"] = config.seed;
  out["runs"] = runs;
  WriteFileAtomically((fs::path(dir) / "summary.json").string(), out.dump(2) + "\n");
  WriteFileAtomically((fs::path(dir) / "walks.json").string(), walks.dump() + "\n");
  WriteFileAtomically((fs::path(dir) / "gallery.json").string(), json{{"individuals", gallery}}.dump(2) + "\n");

  std::string md = SummaryToMarkdown(summary, "Reproduction: " + std::to_string(config.replicates) + " replicate(s) x " +
                                                  std::to_string(config.generations) + " generations, preset " +
                                                  config.preset.name);
  md += "\n## Figures\n\n";
  for (const char* fig : {"fig4a", "fig4b", "fig5", "fig6", "fig7", "fig8", "fig9"}) {
    md += std::string("![") + fig + "](figures/" + fig + ".png)\n";
  }
  WriteFileAtomically((fs::path(dir) / "summary.md").string(), md);
  return summary;
}

}  // namespace walkers
