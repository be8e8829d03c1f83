// walkers simulate: the walker with no controller, limp joints.
#include <chrono>
#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/trajectory_csv.h"
#include "app/validators.h"
#include "control/genome.h"
#include "control/start_pose.h"
#include "integration/integrator.h"
#include "dynamics/observation.h"

namespace walkers::app {
namespace {

struct SimulateOptions {
  std::string genome_path;
  double duration = 0;
  bool passive = false;
  std::string trajectory_path;
  bool force = false;
};

int RunSimulate(const SimulateOptions& opt) {
  if (!opt.trajectory_path.empty()) {
    CheckOutputFile("--trajectory", opt.trajectory_path, opt.force, {{"--genome", opt.genome_path}});
  }
  const Genome genome = LoadGenome(opt.genome_path);
  const Model model = BuildModel(BodyOf(genome));
  const State start = StartState(model);

  // planted: both feet welded at the start pose; passive: nothing holds them
  Inputs inputs;
  if (!opt.passive) {
    for (int leg = 0; leg < kNumLegs; ++leg) inputs.welds[leg] = PlantFoot(model, start, leg);
  }

  std::optional<TrajectoryCsv> csv;
  if (!opt.trajectory_path.empty()) csv.emplace(opt.trajectory_path, false);

  Integrator integrator(model);
  integrator.Reset(0.0, start, inputs);
  const auto wall_start = std::chrono::steady_clock::now();

  IntegrationStatus status;
  auto record = [&] {
    if (csv) csv->Write(integrator.time(), integrator.state(), Observe(model, integrator.state()));
  };
  record();
  // one row per 1/30 s, and the final time
  for (long frame = 1; status.ok() && integrator.time() < opt.duration; ++frame) {
    const double t = std::min(opt.duration, frame / kControlRate);
    status = integrator.AdvanceTo(t);
    record();
  }
  const double wall_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wall_start).count();
  if (csv) csv->Close();

  const IntegratorStats stats = integrator.stats();
  nlohmann::json summary = {{"sim_time", integrator.time()},
                            {"wall_ms", wall_ms},
                            {"cvode_steps", stats.steps},
                            {"rhs_evals", stats.rhs_evals},
                            {"failure", nullptr}};
  if (!status.ok()) summary["failure"] = status.reason;
  std::cout << summary.dump() << std::endl;
  return status.ok() ? 0 : 3;
}

}  // namespace

void AddSimulateCommand(CLI::App& app, Command* selected) {
  auto opt = std::make_shared<SimulateOptions>();
  CLI::App* sub = app.add_subcommand("simulate", "Simulate the walker with no controller (limp joints)");
  sub->add_option("--genome", opt->genome_path, "Genome file (JSON)")->required()->check(CLI::ExistingFile);
  sub->add_option("--duration", opt->duration, "Simulated time [s]")
      ->required()
      ->check(FiniteRange(1e-9, 3600.0));
  sub->add_flag("--passive", opt->passive,
                "Plant no foot: the walker drops and collapses (default: both feet planted at the start pose)");
  sub->add_option("--trajectory", opt->trajectory_path, "Write the trajectory as CSV, one row per 1/30 s");
  AddForceOption(sub, &opt->force, "the --trajectory file");
  sub->callback([opt, selected] { *selected = [opt] { return RunSimulate(*opt); }; });
}

}  // namespace walkers::app
