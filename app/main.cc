// walkers: evolve, evaluate and simulate scaffolded bipedal walkers.
#include <exception>
#include <iostream>

#include "app/commands.h"

int main(int argc, char** argv) {
  CLI::App app{"Scaffolded bipedal walkers: a planar biped evolved with robotics scaffolded learning."};
  app.require_subcommand(1);

  walkers::app::Command selected;
  walkers::app::AddSimulateCommand(app, &selected);
  walkers::app::AddEvaluateCommand(app, &selected);
  walkers::app::AddEvolveCommand(app, &selected);
  walkers::app::AddReplayCommand(app, &selected);
  walkers::app::AddReproduceCommand(app, &selected);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    return selected();
  } catch (const std::exception& e) {
    std::cerr << "walkers: error: " << e.what() << "\n";
    return 1;
  }
}
