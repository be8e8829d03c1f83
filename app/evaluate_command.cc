// walkers evaluate: one 15 s evaluation of a genome under the walking controller.
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/validators.h"
#include "app/trajectory_csv.h"
#include "control/accuracy.h"
#include "control/evaluation.h"
#include "control/evaluation_json.h"
#include "control/genome.h"
#include "control/step_profile.h"
#include "dynamics/observation.h"
#include "evolve/finals.h"  // kMaxEnsemble
#include "files/durable_file.h"
#include "files/errors.h"

namespace walkers::app {
namespace {

struct EvaluateOptions {
  std::string genome_path;
  std::string preset = "original";
  std::string trajectory_path;
  std::string profile_path;          // per-tick step profile, CSV
  std::string profile_summary_path;  // its totals per walking state, JSON
  bool json = false;
  int ensemble = 0;  // 0: no ensemble
  bool force = false;
  IntegrationChoice integration;
};

int RunEvaluate(const EvaluateOptions& opt) {
  const std::vector<std::pair<std::string, std::string>> outputs = {{"--trajectory", opt.trajectory_path},
                                                                      {"--profile", opt.profile_path},
                                                                      {"--profile-summary", opt.profile_summary_path}};
  for (size_t i = 0; i < outputs.size(); ++i) {
    if (outputs[i].second.empty()) continue;
    CheckOutputFile(outputs[i].first, outputs[i].second, opt.force, {{"--genome", opt.genome_path}});
    for (size_t j = 0; j < i; ++j) {
      const auto same = std::filesystem::path(outputs[i].second).lexically_normal() ==
                        std::filesystem::path(outputs[j].second).lexically_normal();
      if (same) throw InputError(outputs[j].first + " and " + outputs[i].first + " name the same file");
    }
  }
  const Genome genome = LoadGenome(opt.genome_path);
  const Preset preset = PresetByName(opt.preset);
  const Model model = BuildModel(BodyOf(genome));

  std::optional<TrajectoryCsv> csv;
  if (!opt.trajectory_path.empty()) csv.emplace(opt.trajectory_path, true);
  std::optional<StepProfile> profile;
  if (!opt.profile_path.empty() || !opt.profile_summary_path.empty()) profile.emplace(model);
  TickObserver observer;
  StepObserver step_observer;
  if (csv || profile) {
    observer = [&csv, &profile, &model](double t, const State& state, const WalkingController& controller) {
      if (csv) {
        csv->Write(t, state, Observe(model, state), WalkingStateName(controller.state()), controller.x_target());
      }
      if (profile) profile->OnTick(t, state, controller);
    };
  }
  if (profile) step_observer = [&profile](const StepInfo& step) { profile->OnStep(step); };
  const EvaluationSettings settings = opt.integration.Settings();
  const EvaluationResult r = Evaluate(genome, preset, settings, observer, step_observer);
  if (csv) csv->Close();
  if (!opt.profile_path.empty()) {
    AtomicFileWriter file(opt.profile_path, "the profile file");
    profile->WriteCsv(file.stream());
    file.Commit();
  }
  if (!opt.profile_summary_path.empty()) {
    AtomicFileWriter file(opt.profile_summary_path, "the profile summary");
    file.stream() << profile->Summary().dump(2) << "\n";
    file.Commit();
  }
  const FitnessEnsemble ensemble = EvaluateEnsemble(genome, preset, settings, opt.ensemble, &r);

  if (opt.json) {
    const nlohmann::json out = EvaluationToJson(r, opt.ensemble > 0 ? &ensemble : nullptr);
    std::cout << out.dump() << std::endl;
  } else {
    std::printf("fitness %.4f  (distance %.3f m over leg length %.3f m)\n", r.fitness, r.distance, r.leg_length);
    std::printf("%s, %d footsteps, trunk on the ground or its feet %.0f %% of the time after the lock%s\n",
                GaitName(r.gait), r.footsteps, 100.0 * r.trunk_contact_fraction,
                r.outcome == Outcome::kFell ? ", FELL" : "");
    if (r.outcome == Outcome::kFailed) std::printf("integration failed: %s\n", r.reason.c_str());
    std::printf("simulated %.2f s in %.1f ms: %ld CVODE steps, %ld right-hand sides (preset %s)\n", r.sim_time,
                r.wall_ms, r.integrator_stats.steps, r.integrator_stats.rhs_evals, r.preset.c_str());
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
  AddIntegrationOptions(sub, &opt->integration);
  sub->add_option("--trajectory", opt->trajectory_path, "Write the trajectory as CSV, one row per 1/30 s");
  sub->add_option("--profile", opt->profile_path,
                  "Write CVODE's steps as CSV, one row per 1/30 s tick: steps, failures, sizes, the limiting "
                  "state components, contact and joint-stop switches (docs/step_profile.md)");
  sub->add_option("--profile-summary", opt->profile_summary_path,
                  "Write the step profile's totals per walking state as JSON (docs/step_profile.md)");
  AddForceOption(sub, &opt->force, "the --trajectory and profile files");
  sub->add_flag("--json", opt->json, "Print one JSON object instead of a summary");
  sub->add_option("--ensemble", opt->ensemble,
                  "Also evaluate N times with the relative tolerance scaled by 1 + k 1e-4 and report the "
                  "fitness's spread (the walk can be chaotic; docs/performance.md, Accuracy)")
      ->check(IntegerRange(1, kMaxEnsemble));
  sub->callback([opt, selected] { *selected = [opt] { return RunEvaluate(*opt); }; });
}

}  // namespace walkers::app
