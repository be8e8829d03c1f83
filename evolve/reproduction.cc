#include "evolve/reproduction.h"

#include <algorithm>
#include <exception>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <thread>

#include <nlohmann/json.hpp>

#include "control/walk_record.h"
#include "evolve/files.h"

namespace walkers {
namespace fs = std::filesystem;
using nlohmann::json;

void ReproductionConfig::Validate() const {
  if (learners.empty()) throw std::invalid_argument("learners: at least one learner is needed");
  for (std::size_t i = 0; i < learners.size(); ++i) {
    LearnerByName(learners[i]);
    for (std::size_t j = 0; j < i; ++j) {
      if (learners[j] == learners[i]) throw std::invalid_argument("learners: '" + learners[i] + "' is given twice");
    }
  }
  RequireInRange("replicates", replicates, 1, kMaxReplicates);
  if (seed > kMaxSeed - static_cast<std::uint64_t>(replicates - 1)) {
    throw std::invalid_argument("seed = " + std::to_string(seed) + " is outside its allowed range [0, " +
                                std::to_string(kMaxSeed - (replicates - 1)) + "] for " + std::to_string(replicates) +
                                " replicates (replicate r uses seed + r - 1)");
  }
  for (const PlannedRun& run : PlanRuns(*this)) run.config.Validate();
}

ReproductionFiles::ReproductionFiles(const std::string& dir)
    : summary_json((fs::path(dir) / "summary.json").string()),
      summary_md((fs::path(dir) / "summary.md").string()),
      walks((fs::path(dir) / "walks.json").string()),
      gallery((fs::path(dir) / "gallery.json").string()),
      figures((fs::path(dir) / "figures").string()) {}

std::vector<std::string> ReproductionFiles::Names() {
  const ReproductionFiles files("");
  std::vector<std::string> names;
  for (const std::string* f : {&files.summary_json, &files.summary_md, &files.walks, &files.gallery, &files.figures}) {
    names.push_back(fs::path(*f).filename().string());
  }
  return names;
}

namespace {

// "<case>-<replicate>" or "<learner>-<case>-<replicate>"
bool IsRunName(const std::string& name) {
  std::vector<std::string> prefixes;
  for (const ScaffoldSpec& scaffold : Scaffolds()) {
    prefixes.push_back(std::string(scaffold.name) + "-");
    for (const LearnerSpec& learner : Learners()) {
      prefixes.push_back(std::string(learner.name) + "-" + scaffold.name + "-");
    }
  }
  for (const std::string& prefix : prefixes) {
    if (name.size() > prefix.size() && name.compare(0, prefix.size(), prefix) == 0 &&
        name.find_first_not_of("0123456789", prefix.size()) == std::string::npos) {
      return true;
    }
  }
  return false;
}

// what a reproduction in `dir` consists of: its results and every run folder
std::vector<std::string> ReproductionNames(const std::string& dir) {
  std::vector<std::string> names = ReproductionFiles::Names();
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_directory() && IsRunName(name)) names.push_back(name);
  }
  return names;
}

// "ga, cmaes"
std::string Joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace

json ScaffoldsJson() {
  json out = json::array();
  for (const ScaffoldSpec& s : Scaffolds()) out.push_back({{"name", s.name}, {"label", s.label}, {"colour", s.colour}});
  return out;
}

json LearnersJson(const std::vector<std::string>& learners) {
  json out = json::array();
  for (const std::string& name : learners) {
    const LearnerSpec& l = LearnerByName(name);
    out.push_back({{"name", l.name}, {"label", l.label}, {"colour", l.colour}});
  }
  return out;
}

std::vector<PlannedRun> PlanRuns(const ReproductionConfig& config) {
  std::vector<PlannedRun> runs;
  for (const std::string& learner : config.learners) {
    // the GA's runs keep the names of the paper's reproduction
    const std::string prefix = learner == DefaultLearner().name ? "" : learner + "-";
    for (const ScaffoldSpec& scaffold : Scaffolds()) {
      for (int r = 1; r <= config.replicates; ++r) {
        PlannedRun run{scaffold.id, r, prefix + scaffold.name + "-" + std::to_string(r), RunConfig{}};
        run.config.learner = learner;
        run.config.scaffold_case = scaffold.id;
        run.config.preset = config.preset;
        run.config.generations = config.generations;
        run.config.seed = config.seed + static_cast<std::uint64_t>(r - 1);
        run.config.ga = config.ga;
        run.config.evaluation = config.evaluation;
        runs.push_back(run);
      }
    }
  }
  return runs;
}

Reproduction::Reproduction(const ReproductionConfig& config, const std::string& dir, StartMode mode)
    : config_(config), dir_(dir) {
  // the whole configuration first: nothing is touched for one that cannot run
  config_.Validate();
  plan_ = PlanRuns(config_);
  const auto contents = [&] {
    FolderContents held{ReproductionNames(dir), "", false};
    for (const std::string& name : held.names) {
      const std::string path = (fs::path(dir) / name).string();
      if (!held.any && fs::exists(path)) held.any = true, held.found = " (" + path + ")";
    }
    return held;
  };
  // no run may be moved while another process writes it
  const auto lock_runs = [&](const FolderContents& held) {
    std::vector<FolderLock> runs;
    for (const std::string& name : held.names) {
      const fs::path run = fs::path(dir) / name;
      if (IsRunName(name) && fs::is_directory(run)) runs.emplace_back(run.string(), "run");
    }
    return runs;
  };
  StartedFolder started =
      StartResultsFolder(dir, "reproduction", mode, RunFiles((fs::path(dir) / plan_.front().name).string()).checkpoint,
                         contents, lock_runs);
  lock_.emplace(std::move(started.lock));
  replaced_ = std::move(started.replaced);
}

// replaced_ goes first, while the lock is still held
Reproduction::~Reproduction() = default;

ReproductionSummary Reproduction::Run(Evaluator& evaluator, const ReproductionObserver& observer, int runs_at_once) {
  // Runs side by side: each of `runs_at_once` threads takes the next run of
  // the plan and advances it generation by generation, all of them handing
  // their children to the one evaluator, so that its workers have another
  // run's children while a generation waits for its slowest. Every run is
  // deterministic on its own, so its files do not depend on how many run at
  // once. The observer is called by one thread at a time.
  std::mutex mutex;  // the observer, replaced_, the first error
  std::size_t next = 0;
  std::exception_ptr error;
  struct Stopped {};  // another run failed: this one stops after its generation
  const auto runner = [&] {
    for (;;) {
      std::size_t index;
      {
        std::lock_guard<std::mutex> lock(mutex);
        if (error || next == plan_.size()) return;
        index = next++;
      }
      const PlannedRun& run = plan_[index];
      try {
        const std::string run_dir = (fs::path(dir_) / run.name).string();
        const bool started = fs::exists(RunFiles(run_dir).config);
        EvolutionRun evolution(run.config, run_dir, started ? StartMode::kResume : StartMode::kNew, evaluator);
        {
          std::lock_guard<std::mutex> lock(mutex);
          if (observer.on_run_start) observer.on_run_start(run, evolution.completed_generations());
        }
        evolution.Run([&](const GenerationSummary& s) {
          std::lock_guard<std::mutex> lock(mutex);
          if (replaced_) {
            replaced_->Discard();  // the first new run has its first checkpoint
            replaced_.reset();
          }
          if (observer.on_generation) observer.on_generation(run, s);
          if (error) throw Stopped{};
        });
      } catch (const Stopped&) {
        return;
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex);
        if (!error) error = std::current_exception();
        return;
      }
    }
  };
  const int threads = std::max(1, std::min<int>(runs_at_once, static_cast<int>(plan_.size())));
  std::vector<std::thread> side_by_side;
  for (int t = 1; t < threads; ++t) side_by_side.emplace_back(runner);
  runner();
  for (std::thread& t : side_by_side) t.join();
  if (error) std::rethrow_exception(error);
  return WriteReproductionResults(config_, dir_);
}

ReproductionSummary WriteReproductionResults(const ReproductionConfig& config, const std::string& dir) {
  const std::vector<PlannedRun> plan = PlanRuns(config);
  const std::string& primary = config.learners.front();
  std::vector<RunData> data, primary_data;
  const auto fitness_or_null = [](const std::optional<EvaluatedSummary>& best) {
    return best ? json(best->fitness) : json(nullptr);
  };
  json runs = json::array(), learner_runs = json::array();
  json gallery = json::array();
  for (const PlannedRun& run : plan) {
    const std::string run_dir = (fs::path(dir) / run.name).string();
    data.push_back(LoadRunData(run_dir, run.scaffold_case, run.replicate, run.name));
    data.back().learner = run.config.learner;
    const json run_json = {{"case", ScaffoldCaseName(run.scaffold_case)},
                           {"replicate", run.replicate},
                           {"dir", run.name},
                           {"seed", run.config.seed},
                           {"final_best_fitness", data.back().best_fitness.back()},
                           {"final_best_gait", data.back().best_is_tripod.back() ? "tripod" : "biped"},
                           // the best of all the run's evaluations, by gait (null: none that did not fall)
                           {"best_biped_fitness", fitness_or_null(data.back().best_biped)},
                           {"best_tripod_fitness", fitness_or_null(data.back().best_tripod)},
                           {"evaluations", data.back().evaluations},
                           {"evaluation_seconds", data.back().evaluation_seconds}};
    json with_learner = run_json;
    with_learner["learner"] = run.config.learner;
    learner_runs.push_back(with_learner);
    // the paper's statistics, walks, gallery and figures 4-9: the first learner's
    if (run.config.learner != primary) continue;
    primary_data.push_back(data.back());
    runs.push_back(run_json);
    // the gallery, standing: the run's final best and, when that is a biped,
    // the best tripod the run evaluated
    const Individual best = LoadArchive(RunFiles(run_dir).archive, run.config).front();
    const auto add_to_gallery = [&](const std::string& label, const std::string& id, const std::string& gait,
                                    double fitness, const Genome& genome) {
      gallery.push_back({{"label", label},
                         {"run", run.name},
                         {"id", id},
                         {"gait", gait},
                         {"fitness", fitness},
                         {"body", BodyJson(BuildModel(BodyOf(genome)))},
                         {"pose", StartPoseJson(genome)}});
    };
    add_to_gallery(run.name + " best", best.id(), GaitName(best.result.gait), best.fitness(), best.genome);
    const std::optional<EvaluatedSummary>& tripod = data.back().best_tripod;
    if (best.result.gait != Gait::kTripod && tripod) {
      add_to_gallery(run.name + " tripod", tripod->id, "tripod", tripod->fitness, tripod->genome);
    }
  }
  const ReproductionSummary summary = Summarize(primary_data);
  // every learner's runs, each learner's apart
  std::vector<LearnerSummary> by_learner;
  for (const std::string& learner : config.learners) {
    std::vector<RunData> of_learner;
    for (const RunData& d : data) {
      if (d.learner == learner) of_learner.push_back(d);
    }
    by_learner.push_back({learner, Summarize(of_learner)});
  }

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
  out["scaffolds"] = ScaffoldsJson();  // the figures' list of cases
  out["runs"] = runs;                  // the first learner's
  out["learners"] = LearnersJson(config.learners);
  out["learner_comparison"] = LearnersToJson(by_learner);
  out["learner_runs"] = learner_runs;  // every learner's
  const ReproductionFiles files(dir);
  WriteFileAtomically(files.summary_json, out.dump(2) + "\n");
  WriteFileAtomically(files.walks, walks.dump() + "\n");
  WriteFileAtomically(files.gallery, json{{"individuals", gallery}}.dump(2) + "\n");

  const bool compared = config.learners.size() > 1;
  std::string title = "Reproduction: " + std::to_string(config.replicates) + " replicate(s) x " +
                      std::to_string(config.generations) + " generations, preset " + config.preset.name;
  if (compared) title += ", learners " + Joined(config.learners);
  std::string md = SummaryToMarkdown(summary, title);
  if (compared) {
    md += "\nThe tables above are the " + std::string(LearnerByName(primary).label) + "'s (" + primary +
          "): its runs alone.\n\n" + LearnersToMarkdown(by_learner) + "\n![learners](figures/learners.png)\n";
  }
  md += "\n## Figures\n\n";
  for (const char* fig : {"fig4a", "fig4b", "fig5", "fig6", "fig7", "fig8", "fig9", "finals"}) {
    md += std::string("![") + fig + "](figures/" + fig + ".png)\n";
  }
  WriteFileAtomically(files.summary_md, md);
  // the evaluations of every learner's runs
  ReproductionSummary returned = summary;
  returned.evaluations = returned.falls = 0;
  returned.evaluation_seconds = 0;
  for (const RunData& d : data) {
    returned.evaluations += d.evaluations;
    returned.falls += d.falls;
    returned.evaluation_seconds += d.evaluation_seconds;
  }
  return returned;
}

}  // namespace walkers
