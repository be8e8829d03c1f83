// walkers: evolve, evaluate and simulate scaffolded bipedal walkers.
#include <algorithm>
#include <exception>
#include <iostream>
#include <memory>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

#include "app/commands.h"
#include "evolve/source_commit.h"
#ifdef WALKERS_HAVE_MPI
#include "evolve/mpi_evaluator.h"
#endif

namespace {

// The edit distance between two words (insertions, deletions, substitutions).
std::size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), 0);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// "; did you mean X?" for the nearest of `names` to a mistyped word, if one is near
std::string Suggestion(const std::string& typed, const std::vector<std::string>& names) {
  std::string nearest;
  std::size_t best = std::max<std::size_t>(2, typed.size() / 3) + 1;  // a typo, not another word
  for (const std::string& name : names) {
    const std::size_t d = EditDistance(typed, name);
    if (d < best) best = d, nearest = name;
  }
  return nearest.empty() ? "" : "; did you mean " + nearest + "?";
}

// CLI11 checks required options before it reports arguments it does not
// know, so "evaluate --genom F" said "--genome is required". The unknown
// argument is the actual problem: report it, with the nearest valid name.
// Returns the error to report, or nothing if every argument was known.
std::unique_ptr<CLI::ExtrasError> UnknownArguments(CLI::App& app, const std::vector<std::string>& args) {
  CLI::App* where = &app;
  for (CLI::App* sub : app.get_subcommands()) where = sub;  // the command given, if any
  std::vector<std::string> extra = where->remaining();
  if (extra.empty()) return nullptr;
  // in the order they were given
  const auto position = [&](const std::string& a) { return std::find(args.begin(), args.end(), a) - args.begin(); };
  std::stable_sort(extra.begin(), extra.end(),
                   [&](const std::string& a, const std::string& b) { return position(a) < position(b); });
  // ExtrasError lists its arguments last first (CLI11's internal order)
  std::string message = CLI::ExtrasError(std::vector<std::string>(extra.rbegin(), extra.rend())).what();
  if (where == &app) {
    std::vector<std::string> commands;
    for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) commands.push_back(sub->get_name());
    std::string list;
    for (const std::string& c : commands) list += (list.empty() ? "" : ", ") + c;
    const std::string hint = Suggestion(extra.front(), commands);
    message += hint.empty() ? "; the commands are " + list : hint;
  } else {
    std::vector<std::string> options;
    for (const CLI::Option* opt : where->get_options()) {
      for (const std::string& name : opt->get_lnames()) options.push_back("--" + name);
    }
    for (const std::string& arg : extra) {
      if (arg.rfind("--", 0) != 0) continue;
      const std::string hint = Suggestion(arg.substr(0, arg.find('=')), options);
      if (!hint.empty()) {
        message += hint;
        break;
      }
    }
  }
  return std::make_unique<CLI::ExtrasError>(message, CLI::ExitCodes::ExtrasError);
}

int RunCommandLine(int argc, char** argv) {
  CLI::App app{"Scaffolded bipedal walkers: a planar biped evolved with robotics scaffolded learning."};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("walkers, commit ") + walkers::SourceCommit());

  walkers::app::Command selected;
  walkers::app::AddSimulateCommand(app, &selected);
  walkers::app::AddEvaluateCommand(app, &selected);
  walkers::app::AddEvolveCommand(app, &selected);
  walkers::app::AddReplayCommand(app, &selected);
  walkers::app::AddReproduceCommand(app, &selected);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() != 0) {
      if (const auto unknown = UnknownArguments(app, std::vector<std::string>(argv + 1, argv + argc))) {
        return app.exit(*unknown);
      }
    }
    return app.exit(e);
  }
  try {
    return selected();
  } catch (const std::exception& e) {
    std::cerr << "walkers: error: " << e.what() << "\n";
    return 1;
  }
}

}  // namespace

int main(int argc, char** argv) {
#ifdef WALKERS_HAVE_MPI
  // in an MPI job rank 0 runs the command; the other ranks evaluate for it
  std::optional<walkers::mpi::Session> mpi;
  if (walkers::mpi::LaunchedByLauncher()) {
    mpi.emplace(&argc, &argv);
    if (mpi->rank() != 0) {
      walkers::mpi::ServeEvaluations();
      return 0;
    }
    return mpi->Finish(RunCommandLine(argc, argv));
  }
#endif
  return RunCommandLine(argc, argv);
}
