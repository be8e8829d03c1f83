#include "evolve/reproduction.h"

#include <algorithm>
#include <exception>
#include <filesystem>
#include <mutex>
#include <numeric>
#include <stdexcept>
#include <thread>

#include <nlohmann/json.hpp>

#include "control/walk_record.h"
#include "evolve/source_commit.h"
#include "files/durable_file.h"
#include "files/input_file.h"

namespace walkers {
namespace fs = std::filesystem;
using nlohmann::json;

void ReproductionConfig::Validate() const {
  if (learners.empty()) throw InputError("learners: at least one learner is needed");
  for (std::size_t i = 0; i < learners.size(); ++i) {
    if (LearnerByName(learners[i]).external) {
      throw InputError("learners: '" + learners[i] +
                       "' proposes from a program outside walkers; a reproduction runs the built-in learners only "
                       "(the Python module's walkers.Run drives an external one)");
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (learners[j] == learners[i]) throw InputError("learners: '" + learners[i] + "' is given twice");
    }
  }
  RequireInRange("replicates", replicates, 1, kMaxReplicates);
  RequireInRange("ensemble", ensemble, 1, kMaxEnsemble);
  if (seed > kMaxSeed - static_cast<std::uint64_t>(replicates - 1)) {
    throw InputError("seed = " + std::to_string(seed) + " is outside its allowed range [0, " +
                     std::to_string(kMaxSeed - (replicates - 1)) + "] for " + std::to_string(replicates) +
                     " replicates (replicate r uses seed + r - 1)");
  }
  for (const PlannedRun& run : PlanRuns(*this)) run.config.Validate();
}

ReproductionFiles::ReproductionFiles(const std::string& dir)
    : manifest((fs::path(dir) / "reproduction.json").string()),
      rescores((fs::path(dir) / "rescores.json").string()),
      walks((fs::path(dir) / "walks.json").string()),
      gallery((fs::path(dir) / "gallery.json").string()),
      summary_json((fs::path(dir) / "summary.json").string()),
      summary_md((fs::path(dir) / "summary.md").string()),
      figures((fs::path(dir) / "figures").string()) {}

std::vector<std::string> ReproductionFiles::Names() {
  const ReproductionFiles files("");
  std::vector<std::string> names;
  for (const std::string* f : {&files.manifest, &files.rescores, &files.walks, &files.gallery, &files.summary_json,
                               &files.summary_md, &files.figures}) {
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

}  // namespace

json ScaffoldsJson() {
  json out = json::array();
  for (const ScaffoldSpec& s : Scaffolds()) {
    out.push_back(
        {{"name", s.name}, {"label", s.label}, {"colour", s.colour}, {"paper_tripod_finals", s.paper_tripod_finals}});
  }
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

std::vector<std::size_t> StartOrder(const std::vector<PlannedRun>& plan) {
  std::vector<std::size_t> order(plan.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return plan[a].replicate < plan[b].replicate; });
  return order;
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
  folder_.emplace(dir, "reproduction", mode, RunFiles((fs::path(dir) / plan_.front().name).string()).checkpoint,
                  contents, lock_runs);
}

Reproduction::~Reproduction() = default;

void Reproduction::Run(Evaluator& evaluator, const ReproductionObserver& observer, int runs_at_once) {
  // Runs side by side: each of `runs_at_once` threads takes the next run of
  // the plan in StartOrder and advances it generation by generation, all of them handing
  // their children to the one evaluator, so that its workers have another
  // run's children while a generation waits for its slowest. Every run is
  // deterministic on its own, so its files do not depend on how many run at
  // once. The observer is called by one thread at a time.
  std::mutex mutex;  // the observer, folder_, the first error
  const std::vector<std::size_t> order = StartOrder(plan_);
  std::size_t next = 0;
  std::exception_ptr error;
  struct Stopped {};  // another run failed: this one stops after its generation
  const auto runner = [&] {
    for (;;) {
      std::size_t index;
      {
        std::lock_guard<std::mutex> lock(mutex);
        if (error || next == order.size()) return;
        index = order[next++];
      }
      const PlannedRun& run = plan_[index];
      try {
        const std::string run_dir = (fs::path(dir_) / run.name).string();
        if (KeptWithoutEvaluations(run_dir, run.config)) {
          // finished, its statistics made from its finals.json
          std::lock_guard<std::mutex> lock(mutex);
          if (observer.on_run_start) observer.on_run_start(run, run.config.generations);
          continue;
        }
        const bool started = fs::exists(RunFiles(run_dir).config);
        EvolutionRun evolution(run.config, run_dir, started ? StartMode::kResume : StartMode::kNew, evaluator);
        {
          std::lock_guard<std::mutex> lock(mutex);
          if (observer.on_run_start) observer.on_run_start(run, evolution.completed_generations());
        }
        evolution.Run([&](const GenerationSummary& s) {
          std::lock_guard<std::mutex> lock(mutex);
          folder_->DiscardReplaced();  // the first new run has its first checkpoint
          if (observer.on_generation) observer.on_generation(run, s);
          if (error) throw Stopped{};
        });
        // its finals now, not when every run has finished: a finished run can
        // be kept (committed) without its evaluations while the others go on
        WriteRunFinals(run_dir, run.config, LoadRunFinals(run_dir, run.config));
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
  WriteReproductionData(config_, dir_, evaluator, observer.on_rescore);
}

namespace {

// The finals' re-scores and walks measure how far a walker walks: without
// the cut-off that the runs' evaluations had
EvaluationSettings Uncut(EvaluationSettings settings) {
  settings.cut_off_rhs = 0;
  return settings;
}

// A finalist for reproduction.json: {"id", "fitness" (recorded), "gait", "rescore"}
json FinalistJson(const Individual& finalist, const RescoreCache& rescores) {
  return {{"id", finalist.id()},
          {"fitness", finalist.fitness()},
          {"gait", GaitName(finalist.result.gait)},
          {"rescore", RescoreJson(*rescores.Find(finalist.genome), finalist.fitness())}};
}

// the better of two finalists by their re-scores' medians (the first of equals)
bool RescoredAbove(const Individual& a, const Individual& b, const RescoreCache& rescores) {
  return rescores.Find(a.genome)->Median() > rescores.Find(b.genome)->Median();
}

}  // namespace

void WriteReproductionData(const ReproductionConfig& config, const std::string& dir, Evaluator& evaluator,
                           const std::function<void(int done, int needed)>& on_rescore) {
  const std::vector<PlannedRun> plan = PlanRuns(config);
  const ReproductionFiles files(dir);
  std::vector<RunFinals> finals;
  std::vector<Genome> genomes;
  for (const PlannedRun& run : plan) {
    const std::string run_dir = (fs::path(dir) / run.name).string();
    finals.push_back(LoadRunFinals(run_dir, run.config));  // its finals.json was written as it finished
    for (const std::optional<Individual>& f : {std::optional<Individual>(finals.back().final_best),
                                               finals.back().best_biped, finals.back().best_tripod}) {
      if (f) genomes.push_back(f->genome);
    }
  }
  // every run's three finals again, but those re-scored before
  RescoreCache rescores(files.rescores, config.preset, Uncut(config.evaluation), config.ensemble);
  rescores.Rescore(genomes, evaluator, std::max(1, evaluator.slots()), on_rescore);

  const std::string& primary = config.learners.front();
  json runs = json::array(), gallery = json::array();
  std::optional<std::pair<std::string, Individual>> best_biped, best_tripod;  // (run, finalist) of the first learner
  for (std::size_t i = 0; i < plan.size(); ++i) {
    const PlannedRun& run = plan[i];
    const RunFinals& f = finals[i];
    const auto finalist_or_null = [&](const std::optional<Individual>& x) {
      return x ? FinalistJson(*x, rescores) : json(nullptr);
    };
    runs.push_back({{"learner", run.config.learner},
                    {"case", ScaffoldCaseName(run.scaffold_case)},
                    {"replicate", run.replicate},
                    {"dir", run.name},
                    {"seed", run.config.seed},
                    {"final_best", FinalistJson(f.final_best, rescores)},
                    {"best_biped", finalist_or_null(f.best_biped)},
                    {"best_tripod", finalist_or_null(f.best_tripod)}});
    // the walks and the gallery: the first learner's
    if (run.config.learner != primary) continue;
    for (auto [best, of_run] : {std::pair{&best_biped, &f.best_biped}, std::pair{&best_tripod, &f.best_tripod}}) {
      if (*of_run && (!*best || RescoredAbove(**of_run, (*best)->second, rescores))) {
        *best = std::make_pair(run.name, **of_run);
      }
    }
    // the gallery, standing: the run's final best and, when that is a biped,
    // the best tripod the run evaluated
    const auto add_to_gallery = [&](const std::string& label, const Individual& who) {
      gallery.push_back({{"label", label},
                         {"run", run.name},
                         {"id", who.id()},
                         {"gait", GaitName(who.result.gait)},
                         {"fitness", who.fitness()},
                         {"body", BodyJson(BuildModel(BodyOf(who.genome)))},
                         {"pose", StartPoseJson(who.genome)}});
    };
    add_to_gallery(run.name + " best", f.final_best);
    if (f.final_best.result.gait != Gait::kTripod && f.best_tripod) add_to_gallery(run.name + " tripod", *f.best_tripod);
  }

  // the best biped's and the best tripod's walks, again, frame by frame
  json walks = {{"biped", nullptr}, {"tripod", nullptr}};
  json picks = {{"biped", nullptr}, {"tripod", nullptr}};
  for (const auto& [key, best] : {std::pair{"biped", &best_biped}, std::pair{"tripod", &best_tripod}}) {
    if (!*best) continue;
    const auto& [run, who] = **best;
    RecordedWalk walk =
        RecordWalk(who.genome, config.preset, std::string("best ") + key + ": " + run + " " + who.id(),
                   Uncut(config.evaluation));
    walk.json["run"] = run;
    walk.json["id"] = who.id();
    walks[key] = walk.json;
    picks[key] = {{"run", run}, {"id", who.id()}};
  }

  const json manifest = {{"preset", config.preset.name},
                         {"generations", config.generations},
                         {"replicates", config.replicates},
                         {"seed", config.seed},
                         {"population", config.ga.population},
                         {"ensemble", config.ensemble},
                         // the commit of the program that wrote this file, and the runs' evaluation settings
                         {"program", {{"commit", SourceCommit()},
                                      {"evaluation", EvaluationSettingsToJson(config.evaluation)}}},
                         {"scaffolds", ScaffoldsJson()},
                         {"learners", LearnersJson(config.learners)},
                         {"runs", runs},
                         {"best_biped", picks["biped"]},
                         {"best_tripod", picks["tripod"]}};
  WriteFileAtomically(files.manifest, manifest.dump(2) + "\n");
  WriteFileAtomically(files.walks, walks.dump() + "\n");
  WriteFileAtomically(files.gallery, json{{"individuals", gallery}}.dump(2) + "\n");
}

}  // namespace walkers
