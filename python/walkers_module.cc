// The Python module `walkers` (docs/python.md): the genome's genes from the
// one gene table (control/genome.h), genomes to and from files, dicts and
// NumPy arrays, one evaluation as `walkers evaluate --json` reports it, and
// batches of evaluations on the project's own thread evaluator
// (evolve/evaluator.h) with the GIL released, and walkers.Run, an ask/tell
// run under a scaffold (run_binding.h). Bad input raises ValueError with the
// project's own messages (the gene, its value and its range).
#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "control/accuracy.h"
#include "control/evaluation.h"
#include "control/evaluation_json.h"
#include "control/genome.h"
#include "control/preset.h"
#include "control/walk_record.h"
#include "evolve/evaluator.h"
#include "evolve/finals.h"  // kMaxEnsemble
#include "evolve/learner.h"
#include "evolve/reproduction.h"  // the scaffolds and learners as JSON
#include "evolve/scaffold.h"
#include "evolve/source_commit.h"
#include "files/input_file.h"
#include "python/conversions.h"
#include "python/run_binding.h"

namespace walkers::python {
namespace {

// One column of the gene table as an array, in the table's order.
template <typename Field>
py::array_t<double> GeneColumn(Field field) {
  py::array_t<double> column(kNumGenes);
  for (int i = 0; i < kNumGenes; ++i) column.mutable_data()[i] = GeneTable()[i].*field;
  return column;
}

// ---- evaluations ----

// The settings of integrator=, accuracy= and cut_off= (None: the
// integrator's own; "none" or a number of right-hand sides), as --integrator,
// --accuracy and --cut-off make them; bad values as ValueError.
EvaluationSettings SettingsOf(const std::string& integrator, std::optional<double> accuracy,
                              const py::handle& cut_off) {
  std::optional<long> rhs;
  if (py::isinstance<py::str>(cut_off)) {
    if (cut_off.cast<std::string>() != "none") {
      throw InputError("cut_off = \"" + cut_off.cast<std::string>() + "\": none, \"none\" or right-hand sides");
    }
    rhs = 0;
  } else if (!cut_off.is_none()) {
    rhs = cut_off.cast<long>();
  }
  return SettingsOfIntegrator(integrator, accuracy, rhs);
}

py::dict Evaluate1(const py::handle& genome_object, const std::string& preset_name, std::optional<int> ensemble_size,
                   const std::string& integrator, std::optional<double> accuracy, const py::handle& cut_off) {
  const Genome genome = GenomeOf(genome_object, "genome");
  const Preset preset = PresetByName(preset_name);
  if (ensemble_size) RequireInRange("ensemble", *ensemble_size, 1, kMaxEnsemble);
  const EvaluationSettings settings = SettingsOf(integrator, accuracy, cut_off);
  nlohmann::json out;
  {
    py::gil_scoped_release no_gil;
    // as `walkers evaluate --json [--ensemble N]`: the ensemble's middle member is this evaluation
    const EvaluationResult result = Evaluate(genome, preset, settings);
    if (ensemble_size) {
      const FitnessEnsemble ensemble = EvaluateEnsemble(genome, preset, settings, *ensemble_size, &result);
      out = EvaluationToJson(result, &ensemble);
    } else {
      out = EvaluationToJson(result);
    }
  }
  return ToPython(out);
}

// A walk recorded at 30 Hz (control/walk_record.h), its frames as NumPy
// arrays, one row a frame: for plotting.
py::dict RecordWalk1(const py::handle& genome_object, const std::string& preset_name) {
  const Genome genome = GenomeOf(genome_object, "genome");
  const Preset preset = PresetByName(preset_name);
  nlohmann::json walk;
  {
    py::gil_scoped_release no_gil;
    walk = RecordWalk(genome, preset, "").json;
  }
  walk.erase("title");  // the replay page's, not the walk's
  py::dict out = ToPython(walk);
  const py::module_ numpy = py::module_::import("numpy");
  py::dict frames = out["frames"];
  for (const auto& [key, value] : frames) frames[key] = numpy.attr("asarray")(value);
  return out;
}

py::dict EvaluateBatch(const py::handle& genomes_object, const std::string& preset_name, std::optional<int> threads,
                       const std::string& integrator, std::optional<double> accuracy, const py::handle& cut_off) {
  const DoubleArray rows = GeneRows(genomes_object, "genomes");
  const Preset preset = PresetByName(preset_name);
  const EvaluationSettings settings = SettingsOf(integrator, accuracy, cut_off);
  const int slots = ThreadsOrEveryCore(threads);

  // every row validated before any is evaluated
  const py::ssize_t n = rows.shape(0);
  std::vector<Genome> genomes;
  genomes.reserve(n);
  for (py::ssize_t i = 0; i < n; ++i) {
    genomes.push_back(GenomeOfGenes(rows.data(i, 0), "genomes[" + std::to_string(i) + "]"));
  }

  std::vector<EvaluationResult> results(n);
  {
    py::gil_scoped_release no_gil;
    std::vector<EvaluationTask> tasks(n);
    for (py::ssize_t i = 0; i < n; ++i) tasks[i] = {&genomes[i], &preset, &settings, &results[i]};
    ThreadPool(slots)->EvaluateAll(tasks);
  }
  return ResultArrays(results);
}

}  // namespace
}  // namespace walkers::python

PYBIND11_MODULE(walkers, m) {
  using namespace walkers;
  using namespace walkers::python;
  m.doc() = "Scaffolded bipedal walkers: genomes and their evaluations (docs/python.md)";
  m.attr("__version__") = SourceCommit();

  // bad input, from a file or an argument (files/errors.h), as the CLI reports it
  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });

  // the gene table, in its order
  py::tuple names(static_cast<std::size_t>(kNumGenes));
  for (int i = 0; i < kNumGenes; ++i) names[i] = GeneTable()[i].name;
  m.attr("gene_names") = names;
  m.attr("gene_defaults") = GeneColumn(&GeneSpec::default_value);
  m.attr("gene_floors") = GeneColumn(&GeneSpec::floor);
  m.attr("gene_ceilings") = GeneColumn(&GeneSpec::ceiling);
  m.attr("gene_sigmas") = GeneColumn(&GeneSpec::sigma);
  m.attr("file_floor_half_body_x") = kMinFileHalfBodyX;

  m.def(
      "default_genome", [] { return DictOfGenome(DefaultGenome()); },
      "The initial individual as a dict of a genome file's keys");
  m.def(
      "load_genome", [](const py::handle& path) { return DictOfGenome(LoadGenome(PathOf(path))); }, py::arg("path"),
      "A genome file, checked as the CLI checks it, as a dict");
  m.def(
      "save_genome",
      [](const py::handle& genome, const py::handle& path) { SaveGenome(GenomeOf(genome, "genome"), PathOf(path)); },
      py::arg("genome"), py::arg("path"), "Writes a genome (dict, path or gene array) as a genome file");
  m.def(
      "genome_dict", [](const py::handle& genome) { return DictOfGenome(GenomeOf(genome, "genome")); },
      py::arg("genome"), "A genome (dict, path or gene array), checked, as a dict of a genome file's keys");
  m.def(
      "genome_array", [](const py::handle& genome) { return GenesArray(GenomeOf(genome, "genome")); },
      py::arg("genome"), "A genome's 18 genes in the order of gene_names (the fixed masses left out)");

  m.def("evaluate", &Evaluate1, py::arg("genome"), py::arg("preset") = "original", py::arg("ensemble") = py::none(),
        py::arg("integrator") = "cvode", py::arg("accuracy") = py::none(), py::arg("cut_off") = py::none(),
        "One 15 s evaluation: the fields of `walkers evaluate --json`, with an ensemble of N as --ensemble N; "
        "integrator, accuracy and cut_off as --integrator, --accuracy and --cut-off");
  m.def("evaluate_batch", &EvaluateBatch, py::arg("genomes"), py::arg("preset") = "original",
        py::arg("threads") = py::none(), py::arg("integrator") = "cvode", py::arg("accuracy") = py::none(),
        py::arg("cut_off") = py::none(),
        "Evaluates an (n, 18) array, one genome per row, on `threads` threads (default: every core); "
        "returns arrays of fitness, gait, fell, footsteps and cvode_steps");

  m.def("record_walk", &RecordWalk1, py::arg("genome"), py::arg("preset") = "original",
        "One evaluation recorded at 30 Hz: the result's fields, the body's sizes and the frames as arrays");

  m.def(
      "scaffold_cases", [] { return ScaffoldCaseNames(); }, "The scaffolds' names in the paper's order");
  m.def(
      "scaffolds", [] { return ToPython(ScaffoldsJson()); },
      "The one list of scaffolds, in the paper's order: name, label and colour, as the figures show them");
  m.def(
      "learners", [] { return ToPython(LearnersJson(LearnerNames())); },
      "The one list of learners: name, label and colour; 'external' is the one walkers.Run drives");
  m.def(
      "scaffold_ceiling",
      [](const std::string& case_name, int generation, double ave_best3, const std::string& preset) {
        RequireInRange("generation", generation, 0, std::numeric_limits<int>::max());
        const ScaffoldInputs in{generation, ave_best3, kAuthorsInitialFitness};
        return MakeScaffold(ScaffoldCaseByName(case_name), PresetByName(preset))->Ceiling(in);
      },
      py::arg("case"), py::arg("generation"), py::arg("ave_best3") = 0.0, py::arg("preset") = "original",
      "The scaffold's ceiling on halfBodyX [m] for a generation's children, given the mean fitness of the "
      "archive's best three so far");

  BindRun(m);
}
