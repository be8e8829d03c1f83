// walkers reproduce: the paper's three cases with replicates, their finals
// re-scored, then the statistics beside the paper's (and beside the authors'
// own runs, given a checkout of their repository) and its figures.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/evaluators.h"
#include "app/progress.h"
#include "app/statistics.h"
#include "app/validators.h"
#include "evolve/reproduction.h"
#include "evolve/run_files.h"
#include "evolve/scaffold.h"
#include "evolve/time_left.h"
#include "files/errors.h"

namespace walkers::app {
namespace {

namespace fs = std::filesystem;

struct ReproduceOptions {
  std::vector<std::string> learners = {DefaultLearner().name};
  std::string preset = "original";
  IntegrationChoice integration;
  int generations = 4000;
  int replicates = 3;
  EvaluatorOptions evaluator;
  int runs_at_once = 0;  // 0: as many as the evaluator makes evaluations at once
  std::uint64_t seed = 1;
  int ensemble = ReproductionConfig{}.ensemble;
  std::string authors_checkout;  // "": none given
  std::string out;
  StartFlags start;
};

int RunReproduce(const ReproduceOptions& opt) {
  ReproductionConfig config;
  config.learners = opt.learners;
  config.preset = PresetByName(opt.preset);
  config.evaluation = opt.integration.Settings();
  config.generations = opt.generations;
  config.replicates = opt.replicates;
  config.seed = opt.seed;
  config.ensemble = opt.ensemble;
  config.Validate();
  // the statistics' options; a checkout they cannot read is refused before any run
  std::vector<std::string> authors;
  if (!opt.authors_checkout.empty()) {
    authors = {"--authors", opt.authors_checkout};
    if (RunStatistics({"authors", opt.authors_checkout}) != 0) {
      throw InputError("--authors-checkout " + opt.authors_checkout +
                       ": the statistics cannot read the authors' runs there (see above)");
    }
  }
  const std::unique_ptr<Evaluator> evaluator = MakeEvaluator(opt.evaluator);
  const int runs_at_once = opt.runs_at_once > 0 ? opt.runs_at_once : evaluator->slots();

  const auto start = std::chrono::steady_clock::now();
  const std::vector<PlannedRun> plan = PlanRuns(config);
  const int total = static_cast<int>(plan.size());
  int index = 0;  // runs started
  // Time left for each run and all runs (evolve/time_left.h): a run's
  // generations count as not done until it starts and says how many it has; a
  // run finished before this session lends its kind (learner and case) the
  // cost of each generation.
  const auto kind_of = [](const PlannedRun& run) {
    return run.config.learner + " " + ScaffoldCaseName(run.scaffold_case);
  };
  TimeLeft time_left(config.generations);
  for (const PlannedRun& run : plan) time_left.AddRun(run.name, kind_of(run), 0);
  // one progress line per run; with runs side by side they take turns
  std::map<std::string, std::unique_ptr<Progress>> progress;
  const auto finish_lines = [&] {
    for (auto& [name, p] : progress) p->Finish();
  };
  ReproductionObserver observer;  // called one call at a time
  observer.on_run_start = [&](const PlannedRun& run, int completed) {
    finish_lines();
    std::fprintf(stderr, "run %d/%d: %s (seed %llu)%s\n", ++index, total, run.name.c_str(),
                 static_cast<unsigned long long>(run.config.seed),
                 completed >= run.config.generations ? ", done already"
                 : completed > 0                      ? (", resuming after generation " + std::to_string(completed)).c_str()
                                                      : "");
    time_left.AddRun(run.name, kind_of(run), completed);
    if (completed >= run.config.generations) {
      time_left.AddFinished(kind_of(run), GenerationCosts(RunFiles((fs::path(opt.out) / run.name).string()).generations));
    }
    progress[run.name] = std::make_unique<Progress>(run.name);
  };
  observer.on_rescore = [&](int done, int needed) {
    finish_lines();
    std::fprintf(stderr, "re-scored %d of %d finals (ensembles of %d)\n", done, needed, config.ensemble);
  };
  observer.on_generation = [&](const PlannedRun& run, const GenerationSummary& s) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    time_left.Done(run.name, s.generation, elapsed);
    // every other run's line is ended before this one is drawn in place
    for (auto& [name, p] : progress) {
      if (name != run.name) p->Finish();
    }
    progress.at(run.name)->Report(s, time_left.Estimate(elapsed), time_left.RunLeft(run.name, elapsed));
  };
  // the directory stays locked until the figures are drawn
  Reproduction reproduction(config, opt.out, opt.start.mode());
  std::fprintf(stderr, "%d runs, %d at once, on %s\n", total, std::min(runs_at_once, total),
               DescribeEvaluator(opt.evaluator).c_str());
  reproduction.Run(*evaluator, observer, runs_at_once);
  finish_lines();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("%d runs and their finals; this session %s\n", total, FormatDuration(seconds).c_str());

  // the summary first: the figures may fail without taking the verdicts with them
  std::vector<std::string> summary = {"summary", opt.out}, figures = {"figures", opt.out};
  summary.insert(summary.end(), authors.begin(), authors.end());
  figures.insert(figures.end(), authors.begin(), authors.end());
  const int summarized = RunStatistics(summary);
  if (summarized != 0) {
    std::fprintf(stderr, "walkers: error: the statistics failed (exit status %d); %s/summary.md is not up to date\n",
                 summarized, opt.out.c_str());
  }
  const int drawn = RunStatistics(figures);
  if (drawn != 0) {
    std::fprintf(stderr, "walkers: error: the figures failed (exit status %d); the statistics are in %s/summary.md\n",
                 drawn, opt.out.c_str());
  }
  if (summarized != 0 || drawn != 0) return 1;
  std::printf("summary: %s/summary.md, figures: %s/figures/\n", opt.out.c_str(), opt.out.c_str());
  return 0;
}

}  // namespace

void AddReproduceCommand(CLI::App& app, Command* selected) {
  auto opt = std::make_shared<ReproduceOptions>();
  CLI::App* sub = app.add_subcommand(
      "reproduce", "Reproduce the paper: three scaffolds x replicates (x learners), statistics and figures");
  sub->add_option("--learners", opt->learners,
                  "Learners to compare, comma-separated; the first is the one the paper's figures show")
      ->delimiter(',')
      ->check(CLI::IsMember(BuiltInLearnerNames()))
      ->capture_default_str();
  AddPresetOption(sub, &opt->preset);
  AddIntegrationOptions(sub, &opt->integration);
  sub->add_option("--generations", opt->generations, "Generations per run")
      ->check(IntegerRange(1, kMaxGenerations))
      ->capture_default_str();
  sub->add_option("--replicates", opt->replicates, "Runs per case")
      ->check(IntegerRange(1, kMaxReplicates))
      ->capture_default_str();
  AddEvaluatorOptions(sub, &opt->evaluator);
  sub->add_option("--runs-at-once", opt->runs_at_once,
                  "Runs advanced side by side, sharing the threads (default: as many as threads, or MPI ranks)")
      ->check(IntegerRange(1, 1024));
  AddSeedOption(sub, &opt->seed, "Seed of replicate 1; replicate r uses seed + r - 1");
  sub->add_option("--ensemble", opt->ensemble,
                  "Evaluate each run's final best, best biped and best tripod again N times (relative tolerance "
                  "scaled by 1 + k 1e-4); the claims about final fitness use the medians")
      ->check(IntegerRange(1, kMaxEnsemble))
      ->capture_default_str();
  sub->add_option("--authors-checkout", opt->authors_checkout,
                  "A checkout of the authors' repository: their nine runs beside ours in Fig. 9 and the summary "
                  "(their CaseData/image/fitness-data; nothing of theirs is copied)")
      ->check(CLI::ExistingDirectory);
  sub->add_option("--out", opt->out, "Reproduction directory")->required();
  AddStartFlags(sub, &opt->start, "the reproduction");
  sub->callback([opt, selected] { *selected = [opt] { return RunReproduce(*opt); }; });
}

}  // namespace walkers::app
