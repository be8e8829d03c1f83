// walkers evolve: one scaffolded evolution run.
#include <cstdio>
#include <iostream>
#include <memory>

#include "app/commands.h"
#include "app/evaluators.h"
#include "app/validators.h"
#include "app/progress.h"
#include "evolve/run.h"

namespace walkers::app {
namespace {

struct EvolveOptions {
  std::string scaffold_case;
  std::string learner = DefaultLearner().name;
  std::string preset = "original";
  IntegrationChoice integration;
  int generations = 4000;
  std::uint64_t seed = 1;
  EvaluatorOptions evaluator;
  std::string out;
  StartFlags start;
  GeneticAlgorithmConfig ga;
};

int RunEvolve(const EvolveOptions& opt) {
  RunConfig config;
  config.scaffold_case = ScaffoldCaseByName(opt.scaffold_case);
  config.learner = opt.learner;
  config.preset = PresetByName(opt.preset);
  config.evaluation = opt.integration.Settings();
  config.generations = opt.generations;
  config.seed = opt.seed;
  config.ga = opt.ga;
  config.Validate();

  const std::unique_ptr<Evaluator> evaluator = MakeEvaluator(opt.evaluator);
  EvolutionRun run(config, opt.out, opt.start.mode(), *evaluator);
  if (run.completed_generations() > 0) {
    std::fprintf(stderr, "resuming %s after generation %d\n", opt.out.c_str(), run.completed_generations());
  }

  const std::string learner = config.learner == DefaultLearner().name ? "" : config.learner + "/";
  Progress progress(learner + ScaffoldCaseName(config.scaffold_case) + "/" + config.preset.name);
  run.Run([&](const GenerationSummary& s) { progress.Report(s); });
  progress.Finish();

  const Individual& best = run.archive().best();
  std::printf("best fitness %.4f (%s, generation %d) after %d generations; InitF %.4f; results in %s\n",
              best.fitness(), GaitName(best.result.gait), best.generation, run.completed_generations(),
              run.initial_fitness(), opt.out.c_str());
  return 0;
}

}  // namespace

void AddEvolveCommand(CLI::App& app, Command* selected) {
  auto opt = std::make_shared<EvolveOptions>();
  CLI::App* sub = app.add_subcommand("evolve", "Evolve walkers under a scaffold (paper Algorithm 1)");
  sub->add_option("--case", opt->scaffold_case, "Scaffold on the trunk's length (paper §2.5)")
      ->required()
      ->check(CLI::IsMember(ScaffoldCaseNames()));
  sub->add_option("--learner", opt->learner, "Learner: the paper's GA or one of pagmo2's (docs/learners.md)")
      ->check(CLI::IsMember(BuiltInLearnerNames()))
      ->capture_default_str();
  AddPresetOption(sub, &opt->preset);
  AddIntegrationOptions(sub, &opt->integration);
  sub->add_option("--generations", opt->generations, "Generations to run")
      ->check(IntegerRange(1, kMaxGenerations))
      ->capture_default_str();
  AddSeedOption(sub, &opt->seed, "Random seed of the run");
  AddEvaluatorOptions(sub, &opt->evaluator);
  sub->add_option("--out", opt->out, "Run directory")->required();
  AddStartFlags(sub, &opt->start, "the run");
  sub->add_option("--population", opt->ga.population, "Children per generation")
      ->check(IntegerRange(kMinPopulation, kMaxPopulation))
      ->capture_default_str();
  sub->add_option("--archive", opt->ga.archive_size, "All-time fittest kept")
      ->check(IntegerRange(kMinArchive, kMaxArchive))
      ->capture_default_str();
  sub->add_option("--mutation-children", opt->ga.mutation_children,
                  "Mutation children per generation (at most --population); the rest are crossover children")
      ->check(IntegerRange(0, kMaxPopulation))
      ->capture_default_str();
  sub->callback([opt, selected] { *selected = [opt] { return RunEvolve(*opt); }; });
}

}  // namespace walkers::app
