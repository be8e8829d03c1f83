// Options and validators shared by the commands, and the rules for their
// output files: an existing output is replaced only with --force, and an
// output that is one of the command's inputs never.
#pragma once

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "control/evaluation.h"
#include "files/errors.h"
#include "files/number_text.h"
#include "integration/integrator.h"
#include "evolve/run.h"

namespace walkers::app {

// A finite number in [lo, hi]; unlike CLI::Range it rejects nan.
inline CLI::Validator FiniteRange(double lo, double hi) {
  const std::string range = "[" + FormatExact(lo) + ", " + FormatExact(hi) + "]";
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        double x = 0;
        if (!CLI::detail::lexical_cast(text, x) || !std::isfinite(x) || x < lo || x > hi) {
          return "value " + text + " is not a finite number in " + range;
        }
        return "";
      },
      "FLOAT in " + range);
}

// An integer in [lo, hi]; unlike CLI::Range it says when the value is no
// integer at all ("1.5", "-1" for an unsigned option).
inline CLI::Validator IntegerRange(long long lo, long long hi) {
  const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        long long x = 0;
        const char* end = text.data() + text.size();
        const auto [last, error] = std::from_chars(text.data(), end, x);
        if (text.empty() || last != end) return "value " + text + " is not an integer in " + range;
        if (error == std::errc::result_out_of_range || x < lo || x > hi) {
          return "value " + text + " is outside the allowed range " + range;
        }
        return "";
      },
      "INT in " + range);
}

// --preset: where the paper and the authors' program differ (control/preset.h)
inline CLI::Option* AddPresetOption(CLI::App* sub, std::string* preset) {
  return sub->add_option("--preset", *preset, "Where the paper and the authors' program differ")
      ->check(CLI::IsMember(PresetNames()))
      ->capture_default_str();
}

// --threads: worker threads; left at 0, ThreadsOrAllCores gives every core
inline CLI::Option* AddThreadsOption(CLI::App* sub, int* threads) {
  return sub->add_option("--threads", *threads, "Worker threads (default: all cores)")->check(IntegerRange(1, 1024));
}

inline int ThreadsOrAllCores(int requested) {
  return requested > 0 ? requested : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

// --seed: a non-negative integer in the seeds' range
inline CLI::Option* AddSeedOption(CLI::App* sub, std::uint64_t* seed, const std::string& help) {
  return sub->add_option("--seed", *seed, help)
      ->check(IntegerRange(0, static_cast<long long>(kMaxSeed)))
      ->capture_default_str();
}

// --integrator, --accuracy and --cut-off: how the evaluations integrate
// (docs/model.md, "Integration" and "RK-Merson"; docs/fidelity.md, "The cut-off")
struct IntegrationChoice {
  std::string integrator = "cvode";
  double accuracy = 0;  // 0: unset, RK-Merson's own (the authors' 0.05)
  std::string cut_off;  // empty: the integrator's own (RK-Merson: the authors'); "none"; or right-hand sides

  // The evaluation settings of the choice. Throws InputError naming the
  // option when the options do not go together.
  EvaluationSettings Settings() const {
    return SettingsOfIntegrator(integrator, accuracy > 0 ? std::optional<double>(accuracy) : std::nullopt,
                                cut_off.empty()     ? std::nullopt
                                : cut_off == "none" ? std::optional<long>(0)
                                                    : std::optional<long>(std::stol(cut_off)),
                                {"--integrator", "--accuracy", "--cut-off"});
  }
};
inline void AddIntegrationOptions(CLI::App* sub, IntegrationChoice* choice) {
  sub->add_option("--integrator", choice->integrator,
                  "cvode (accurate; the default) or rk-merson (Simbody's Runge-Kutta-Merson at the authors' "
                  "settings, with their cut-off: their numerics, on purpose)")
      ->check(CLI::IsMember({"cvode", "rk-merson"}))
      ->capture_default_str();
  sub->add_option("--accuracy", choice->accuracy, "rk-merson's accuracy (default 0.05, the authors')")
      ->check(FiniteRange(1e-12, 1));
  sub->add_option("--cut-off", choice->cut_off,
                  "An evaluation past this many right-hand sides scores -124, as the authors' evolver scored "
                  "one past 25 s; 'none' turns it off (default: rk-merson's calibrated " +
                      std::to_string(kAuthorsCutOffRhs) + ", none under cvode)")
      ->check(CLI::IsMember({"none"}) | IntegerRange(1, 1000000000));
}

// --force: replace what the output already holds
inline CLI::Option* AddForceOption(CLI::App* sub, bool* force, const std::string& what) {
  return sub->add_flag("--force", *force, "Replace " + what + " if it exists");
}

// --resume and --force of a command that writes a run or a reproduction
struct StartFlags {
  bool resume = false;
  bool force = false;
  StartMode mode() const { return resume ? StartMode::kResume : force ? StartMode::kForce : StartMode::kNew; }
};
inline void AddStartFlags(CLI::App* sub, StartFlags* flags, const std::string& what) {
  auto* resume = sub->add_flag("--resume", flags->resume, "Continue " + what + " in --out from its last checkpoint");
  auto* force = sub->add_flag("--force", flags->force,
                              "Replace " + what + " in --out; the old one is kept in --out/replaced/ until the new "
                              "one's first generation is written");
  resume->excludes(force);
}

// An output file (option `option`, path `path`): refused if it is one of the
// command's `inputs` (option, path) whatever --force says, or if it exists
// and `force` is not set. Throws InputError naming the option.
inline void CheckOutputFile(const std::string& option, const std::string& path, bool force,
                            const std::vector<std::pair<std::string, std::string>>& inputs) {
  namespace fs = std::filesystem;
  std::error_code ec;
  for (const auto& [input_option, input] : inputs) {
    if (fs::equivalent(path, input, ec)) {
      throw InputError(option + " " + path + " is the " + input_option + " file; an output never replaces an input");
    }
  }
  if (fs::is_directory(path)) throw InputError(option + " " + path + " is a directory");
  if (fs::exists(fs::symlink_status(path)) && !force) {
    throw InputError(option + " " + path + " exists; pass --force to replace it");
  }
}

}  // namespace walkers::app
