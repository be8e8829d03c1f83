// walkers evaluate: one 15 s evaluation of a genome under the walking controller.
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/validators.h"
#include "app/trajectory_csv.h"
#include "control/accuracy.h"
#include "control/evaluation.h"
#include "control/genome.h"
#include "dynamics/observation.h"

namespace walkers::app {
namespace {

struct EvaluateOptions {
  std::string genome_path;
  std::string preset = "original";
  std::string trajectory_path;
  bool json = false;
  int ensemble = 0;  // 0: no ensemble
  bool force = false;
};

int RunEvaluate(const EvaluateOptions& opt) {
  if (!opt.trajectory_path.empty()) {
    CheckOutputFile("--trajectory", opt.trajectory_path, opt.force, {{"--genome", opt.genome_path}});
  }
  const Genome genome = LoadGenome(opt.genome_path);
  const Preset preset = PresetByName(opt.preset);

  std::optional<TrajectoryCsv> csv;
  TickObserver observer;
  if (!opt.trajectory_path.empty()) {
    csv.emplace(opt.trajectory_path, true);
    const Model model = BuildModel(BodyOf(genome));
    observer = [&csv, model](double t, const State& state, const WalkingController& controller) {
      csv->Write(t, state, Observe(model, state), WalkingStateName(controller.state()),
                 controller.x_target());
    };
  }
  const EvaluationResult r = Evaluate(genome, preset, {}, observer);
  if (csv) csv->Close();
  const FitnessEnsemble ensemble = EvaluateEnsemble(genome, preset, {}, opt.ensemble, &r);

  if (opt.json) {
    nlohmann::json out = {{"fitness", r.fitness},
                          {"distance", r.distance},
                          {"leg_length", r.leg_length},
                          {"fell", r.fell},
                          {"failure", nullptr},
                          {"footsteps", r.footsteps},
                          {"trunk_contact_fraction", r.trunk_contact_fraction},
                          {"gait", GaitName(r.gait)},
                          {"sim_time", r.sim_time},
                          {"wall_ms", r.wall_ms},
                          {"cvode_steps", r.cvode_steps},
                          {"rhs_evals", r.rhs_evals},
                          {"preset", r.preset}};
    if (!r.failure.empty()) out["failure"] = r.failure;
    if (opt.ensemble > 0) {
      out["ensemble"] = {{"size", opt.ensemble},           {"fitness", ensemble.fitness},
                         {"fitness_median", ensemble.Median()}, {"fitness_min", ensemble.Min()},
                         {"fitness_max", ensemble.Max()},   {"bipeds", ensemble.bipeds},
                         {"tripods", ensemble.tripods},
                         {"falls", ensemble.falls}};
    }
    std::cout << out.dump() << std::endl;
  } else {
    std::printf("fitness %.4f  (distance %.3f m over leg length %.3f m)\n", r.fitness, r.distance, r.leg_length);
    std::printf("%s, %d footsteps, trunk on the ground or its feet %.0f %% of the time after the lock%s\n",
                GaitName(r.gait), r.footsteps, 100.0 * r.trunk_contact_fraction, r.fell ? ", FELL" : "");
    if (!r.failure.empty()) std::printf("integration failed: %s\n", r.failure.c_str());
    std::printf("simulated %.2f s in %.1f ms: %ld CVODE steps, %ld right-hand sides (preset %s)\n", r.sim_time,
                r.wall_ms, r.cvode_steps, r.rhs_evals, r.preset.c_str());
    if (opt.ensemble > 0) {
      std::printf("ensemble of %d (relative tolerance x 1 + k 1e-4): fitness median %.4f, min %.4f, max %.4f; "
                  "%d bipeds, %d tripods, %d falls\n",
                  opt.ensemble, ensemble.Median(), ensemble.Min(), ensemble.Max(), ensemble.bipeds, ensemble.tripods,
                  ensemble.falls);
    }
  }
  return 0;
}

}  // namespace

void AddEvaluateCommand(CLI::App& app, Command* selected) {
  auto opt = std::make_shared<EvaluateOptions>();
  CLI::App* sub = app.add_subcommand("evaluate", "Evaluate a genome: 15 s of walking, scored by paper eq. 6");
  sub->add_option("--genome", opt->genome_path, "Genome file (JSON)")->required()->check(CLI::ExistingFile);
  AddPresetOption(sub, &opt->preset);
  sub->add_option("--trajectory", opt->trajectory_path, "Write the trajectory as CSV, one row per 1/30 s");
  AddForceOption(sub, &opt->force, "the --trajectory file");
  sub->add_flag("--json", opt->json, "Print one JSON object instead of a summary");
  sub->add_option("--ensemble", opt->ensemble,
                  "Also evaluate N times with the relative tolerance scaled by 1 + k 1e-4 and report the "
                  "fitness's spread (the walk can be chaotic; docs/performance.md, Accuracy)")
      ->check(IntegerRange(1, 1000));
  sub->callback([opt, selected] { *selected = [opt] { return RunEvaluate(*opt); }; });
}

}  // namespace walkers::app
