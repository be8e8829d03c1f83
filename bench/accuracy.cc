// The accuracy criterion of docs/performance.md ("Accuracy") for a set of
// genomes: each is evaluated as an ensemble of N members at the production
// settings and at the reference, 100x tighter ones, both perturbed alike
// (control/accuracy.h, kAccuracyPerturbation: the start pose's trunk raised in
// steps), and judged by JudgeAccuracy. Prints one line per genome; --json
// writes both ensembles of every genome, which scripts/accuracy.py reads to
// judge the rest of the criterion: the two-sample Kolmogorov-Smirnov test of
// the irregular genomes, Holm-corrected over the set (SciPy), and the drift
// over the set. Not a Google Benchmark: a measurement.
//
//   accuracy [--ensemble N] [--threads T] [--json FILE] [--variant NAME] [--tolerances R,Q,V]
//            [--perturbation start|tolerance] [--step S] [--reference FILE]... GENOME|DIR...
//
// --variant takes one of bench/variants.h; --tolerances after it changes that
// variant's tolerances. --perturbation tolerance perturbs the relative
// tolerance instead, as the re-scores of a run's finals do; --step sets the
// step between neighbouring members (m for start, relative for tolerance).
// --reference takes the reference ensembles from files that an earlier run
// wrote with --json (their "tight" ensembles, matched by genome name, of the
// same perturbation) instead of evaluating them: candidate settings are then
// judged against one reference, 100x tighter than the settings that run had,
// and each costs only its own ensembles.
//
// GENOME|DIR: genome files, or folders whose *.json are taken in name order.
// The default ensemble is 25, the criterion's. Exit status: 0 when every
// genome passes the rules of its own that this program judges (a regular
// genome's medians, gait, fall, lost and numerical walkers), 1 when one does
// not, 2 on bad input.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/variants.h"
#include "control/accuracy.h"
#include "evolve/evaluator.h"
#include "files/durable_file.h"
#include "files/input_file.h"

using namespace walkers;

namespace {

struct Options {
  int ensemble = 25;
  int threads = 1;
  std::string json;
  EvaluationSettings production;
  std::string settings_name = "production";
  Perturbation perturbation = kAccuracyPerturbation;
  bool step_given = false;
  std::vector<std::string> references;  // earlier --json files whose reference ensembles are reused
  std::vector<std::string> genomes;
};

nlohmann::json ToJson(const FitnessEnsemble& e) {
  return {{"fitness", e.fitness},
          {"bipeds", e.bipeds},
          {"tripods", e.tripods},
          {"falls", e.falls},
          {"steps_median", Median(e.cvode_steps)},
          {"wall_ms_median", Median(e.wall_ms)}};
}

int Usage(const char* program) {
  std::fprintf(stderr,
               "usage: %s [--ensemble N] [--threads T] [--json FILE] [--variant NAME] [--tolerances R,Q,V] "
               "[--perturbation start|tolerance] [--step S] [--reference FILE]... GENOME|DIR...\n",
               program);
  return 2;
}

double ParsePositive(const std::string& name, const std::string& text) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !(value > 0.0) || !std::isfinite(value)) {
    throw std::invalid_argument(name + " must be a positive number, got '" + text + "'");
  }
  return value;
}

int ParseCount(const std::string& name, const std::string& text, long max) {
  char* end = nullptr;
  errno = 0;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno == ERANGE || value < 1 || value > max) {
    throw std::invalid_argument(name + " must be a whole number in 1.." + std::to_string(max) + ", got '" + text +
                                "'");
  }
  return static_cast<int>(value);
}

Options Parse(const std::vector<std::string>& args) {
  Options opt;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    const auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw std::invalid_argument(a + " needs a value");
      return args[++i];
    };
    if (a == "--ensemble") {
      opt.ensemble = ParseCount(a, value(), 1000);
    } else if (a == "--threads") {
      opt.threads = ParseCount(a, value(), 256);
    } else if (a == "--json") {
      opt.json = value();
    } else if (a == "--variant") {
      const std::string name = value();
      bool found = false;
      for (const bench::Variant& v : bench::Variants()) {
        if (v.name == name) opt.production = v.settings, found = true;
      }
      if (!found) throw std::invalid_argument("unknown variant " + name + " (bench/variants.h)");
      opt.settings_name = name;
    } else if (a == "--tolerances") {
      const std::string text = value();
      std::stringstream in(text);
      std::string r, q, v;
      if (!std::getline(in, r, ',') || !std::getline(in, q, ',') || !std::getline(in, v)) {
        throw std::invalid_argument("--tolerances takes rtol,atol_position,atol_velocity, got '" + text + "'");
      }
      opt.production.integrator.relative_tolerance = ParsePositive("rtol", r);
      opt.production.integrator.absolute_tolerance_position = ParsePositive("atol_position", q);
      opt.production.integrator.absolute_tolerance_velocity = ParsePositive("atol_velocity", v);
      opt.settings_name = (opt.settings_name == "production" ? "" : opt.settings_name + ", ") + "tolerances " + text;
    } else if (a == "--perturbation") {
      const std::string kind = value();
      if (kind == "start") {
        opt.perturbation.kind = PerturbationKind::kStartPose;
      } else if (kind == "tolerance") {
        opt.perturbation.kind = PerturbationKind::kRelativeTolerance;
      } else {
        throw std::invalid_argument("--perturbation must be start or tolerance, got '" + kind + "'");
      }
    } else if (a == "--step") {
      opt.perturbation.step = ParsePositive(a, value());
      opt.step_given = true;
    } else if (a == "--reference") {
      opt.references.push_back(value());
    } else if (a.rfind("--", 0) == 0) {
      throw std::invalid_argument("unknown option " + a);
    } else if (std::filesystem::is_directory(a)) {
      std::vector<std::string> files;
      for (const auto& entry : std::filesystem::directory_iterator(a)) {
        if (entry.path().extension() == ".json") files.push_back(entry.path().string());
      }
      std::sort(files.begin(), files.end());
      opt.genomes.insert(opt.genomes.end(), files.begin(), files.end());
    } else {
      opt.genomes.push_back(a);
    }
  }
  if (opt.genomes.empty()) throw std::invalid_argument("no genome files given");
  if (!opt.step_given) {
    opt.perturbation.step = opt.perturbation.kind == kAccuracyPerturbation.kind ? kAccuracyPerturbation.step
                                                                                : kRescorePerturbation.step;
  }
  return opt;
}

// A reference saved by an earlier run: the settings it was 100x tighter than
// and its ensemble of every genome, by name.
struct SavedReference {
  nlohmann::json settings;  // relative_tolerance, absolute_tolerance_position, absolute_tolerance_velocity
  std::vector<std::pair<std::string, FitnessEnsemble>> ensembles;
};

SavedReference LoadReferences(const Options& opt) {
  SavedReference saved;
  const char* kind = opt.perturbation.kind == PerturbationKind::kStartPose ? "start" : "tolerance";
  for (const std::string& file : opt.references) {
    const nlohmann::json j = LoadJsonFile(file);
    // members perturbed alike; a smaller odd ensemble's members are some of
    // the reference's (a screening, not a verdict: the criterion's are 25)
    if (j.at("perturbation").at("kind") != kind || j.at("perturbation").at("step") != opt.perturbation.step) {
      throw std::invalid_argument(file + ": its ensembles are perturbed by " + j.at("perturbation").dump() +
                                  ", not as this run's");
    }
    const nlohmann::json settings = {{"relative_tolerance", j.at("relative_tolerance")},
                                     {"absolute_tolerance_position", j.at("absolute_tolerance_position")},
                                     {"absolute_tolerance_velocity", j.at("absolute_tolerance_velocity")}};
    if (!saved.settings.is_null() && settings != saved.settings) {
      throw std::invalid_argument(file + ": its reference is 100x tighter than " + settings.dump() +
                                  ", another file's than " + saved.settings.dump());
    }
    saved.settings = settings;
    for (const nlohmann::json& g : j.at("genomes")) {
      const nlohmann::json& t = g.at("tight");
      FitnessEnsemble e;
      e.fitness = t.at("fitness").get<std::vector<double>>();
      e.bipeds = t.at("bipeds").get<int>();
      e.tripods = t.at("tripods").get<int>();
      e.falls = t.at("falls").get<int>();
      e.cvode_steps = {t.at("steps_median").get<double>()};
      e.wall_ms = {t.at("wall_ms_median").get<double>()};
      saved.ensembles.emplace_back(g.at("genome").get<std::string>(), e);
    }
  }
  return saved;
}

int Run(const Options& opt) {
  const EvaluationSettings tight = HundredTimesTighter(opt.production);
  const SavedReference saved = LoadReferences(opt);
  const bool evaluate_reference = opt.references.empty();
  std::vector<Genome> genomes;
  for (const std::string& file : opt.genomes) genomes.push_back(LoadGenome(file));

  // every member of every ensemble is one task for the evaluator's threads;
  // each result has its slot, so the output does not depend on the number of
  // threads
  const Preset preset = OriginalPreset();
  std::vector<EvaluationSettings> settings = {opt.production};
  if (evaluate_reference) settings.push_back(tight);
  std::vector<EvaluationSettings> members;  // [settings][member]
  for (const EvaluationSettings& s : settings) {
    for (int k = 0; k < opt.ensemble; ++k) {
      members.push_back(EnsembleMemberSettings(s, opt.ensemble, k, opt.perturbation));
    }
  }
  std::vector<EvaluationResult> flat(genomes.size() * members.size());  // [genome][settings][member]
  std::vector<EvaluationTask> tasks;
  for (size_t i = 0; i < genomes.size(); ++i) {
    for (size_t m = 0; m < members.size(); ++m) {
      // the tighter ensembles cost more: handed out first
      tasks.push_back({&genomes[i], &preset, &members[m], &flat[i * members.size() + m],
                       m < static_cast<size_t>(opt.ensemble) ? 1.0 : 2.0});
    }
  }
  MakeThreadEvaluator(opt.threads)->EvaluateAll(tasks);
  std::vector<FitnessEnsemble> production, tighter;
  for (size_t i = 0; i < genomes.size(); ++i) {
    const auto first = flat.begin() + static_cast<long>(i * members.size());
    production.push_back(EnsembleOf({first, first + opt.ensemble}));
    if (evaluate_reference) {
      tighter.push_back(EnsembleOf({first + opt.ensemble, first + 2 * opt.ensemble}));
      continue;
    }
    const std::string name = std::filesystem::path(opt.genomes[i]).stem().string();
    const auto found = std::find_if(saved.ensembles.begin(), saved.ensembles.end(),
                                    [&name](const auto& entry) { return entry.first == name; });
    if (found == saved.ensembles.end()) throw std::invalid_argument("no reference ensemble of " + name);
    tighter.push_back(found->second);
  }

  const auto& s = opt.production.integrator;
  const char* kind = opt.perturbation.kind == PerturbationKind::kStartPose ? "start" : "tolerance";
  const std::string reference =
      evaluate_reference ? "100x tighter" : "saved, 100x tighter than " + saved.settings.dump();
  std::printf("settings: %s (rtol %g, atol_q %g, atol_v %g), reference: %s; ensembles of %d, "
              "perturbation %s in steps of %g\n",
              opt.settings_name.c_str(), s.relative_tolerance, s.absolute_tolerance_position,
              s.absolute_tolerance_velocity, reference.c_str(), opt.ensemble, kind, opt.perturbation.step);
  std::printf("%-32s %26s %26s %8s %8s %5s %5s %9s %5s %9s %9s\n", "genome", "median [IQR]",
              "reference: median [IQR]", "rel.diff", "regular", "gait", "fall", "walker", "pass", "steps", "ms");
  nlohmann::json out = {{"settings", opt.settings_name},
                        {"relative_tolerance", s.relative_tolerance},
                        {"absolute_tolerance_position", s.absolute_tolerance_position},
                        {"absolute_tolerance_velocity", s.absolute_tolerance_velocity},
                        {"ensemble", opt.ensemble},
                        {"perturbation", {{"kind", kind}, {"step", opt.perturbation.step}}},
                        {"genomes", nlohmann::json::array()}};
  if (!evaluate_reference) out["reference"] = {{"files", opt.references}, {"tighter_than", saved.settings}};
  int failed = 0;
  std::vector<double> steps, ms;
  for (size_t i = 0; i < genomes.size(); ++i) {
    const FitnessEnsemble& a = production[i];
    const FitnessEnsemble& b = tighter[i];
    const AccuracyVerdict v = JudgeAccuracy(a, b);
    failed += v.passes() ? 0 : 1;
    // an irregular genome that passes its own rules waits for its KS test over the set
    const char* pass = !v.passes() ? "NO" : v.regular ? "yes" : "KS";
    const std::string name = std::filesystem::path(opt.genomes[i]).stem().string();
    steps.push_back(Median(production[i].cvode_steps));
    ms.push_back(Median(production[i].wall_ms));
    std::printf("%-32s %8.3f [%7.3f, %7.3f] %8.3f [%7.3f, %7.3f] %7.2f%% %8s %5s %5s %9s %5s %9.0f %9.1f\n",
                name.c_str(), a.Median(), a.LowerQuartile(), a.UpperQuartile(), b.Median(), b.LowerQuartile(),
                b.UpperQuartile(), 100.0 * v.median_difference, v.regular ? "yes" : "no", v.gait_agrees ? "yes" : "NO",
                v.fall_agrees ? "yes" : "NO", v.lost_walker ? "LOST" : v.numerical_walker ? "NUMERICAL" : "kept",
                pass, steps.back(), ms.back());
    out["genomes"].push_back({{"genome", name},
                              {"file", opt.genomes[i]},
                              {"production", ToJson(production[i])},
                              {"tight", ToJson(tighter[i])},
                              {"regular", v.regular},
                              {"median_difference", v.median_difference},
                              {"lost_walker", v.lost_walker},
                              {"numerical_walker", v.numerical_walker},
                              {"passes_own_rules", v.passes()}});
  }
  std::printf("%zu genomes: %d fail their own rules (scripts/accuracy.py judges the rest: the KS tests with Holm's "
              "correction, the drift); median over the set %.0f steps, %.1f ms per evaluation\n",
              genomes.size(), failed, Median(steps), Median(ms));
  if (!opt.json.empty()) WriteFileAtomically(opt.json, out.dump(1) + "\n");
  return failed == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return Run(Parse(std::vector<std::string>(argv + 1, argv + argc)));
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "accuracy: %s\n", e.what());
    return Usage(argv[0]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "accuracy: %s\n", e.what());
    return 2;
  }
}
