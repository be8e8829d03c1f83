// The subcommands of the `walkers` program. Each Add*Command registers its
// options on the application; when the user picks it, it stores in *selected
// the function that runs it. Running returns the process's exit code; bad
// input is reported by throwing, and main turns that into a message and exit 1.
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

namespace walkers::app {

using Command = std::function<int()>;

void AddSimulateCommand(CLI::App& app, Command* selected);
void AddEvaluateCommand(CLI::App& app, Command* selected);
void AddEvolveCommand(CLI::App& app, Command* selected);
void AddReplayCommand(CLI::App& app, Command* selected);
void AddReproduceCommand(CLI::App& app, Command* selected);

}  // namespace walkers::app
