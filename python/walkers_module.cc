// The Python module `walkers` (docs/python.md): the genome's genes from the
// one gene table (control/genome.h), genomes to and from files, dicts and
// NumPy arrays, one evaluation as `walkers evaluate --json` reports it, and
// batches of evaluations on the project's own thread evaluator
// (evolve/evaluator.h) with the GIL released. Bad input raises ValueError
// with the project's own messages (the gene, its value and its range).
#include <algorithm>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "control/accuracy.h"
#include "control/evaluation.h"
#include "control/evaluation_json.h"
#include "control/genome.h"
#include "control/input_file.h"
#include "control/preset.h"
#include "control/walk_record.h"
#include "evolve/evaluator.h"
#include "evolve/finals.h"  // kMaxEnsemble
#include "evolve/scaffold.h"
#include "evolve/source_commit.h"

namespace py = pybind11;

namespace walkers::python {
namespace {

// A batch's threads may number at most this, as --threads allows.
constexpr int kMaxThreads = 1024;

// ---- JSON and Python objects ----

// A JSON value as the Python object json.loads makes of it: a double is
// printed in its shortest round-trip form and parsed back to the same bits.
py::object ToPython(const nlohmann::json& value) { return py::module_::import("json").attr("loads")(value.dump()); }

// A genome dict as the JSON object a genome file holds. Numbers (int, float,
// NumPy scalars) become doubles; anything else is kept in a form the genome's
// validation refuses with the gene's name (a bool, or the value's text).
nlohmann::json JsonOfDict(const py::dict& dict) {
  nlohmann::json object = nlohmann::json::object();
  for (const auto& [key, value] : dict) {
    if (!py::isinstance<py::str>(key)) {
      throw py::value_error("a genome dict's keys are gene names, got " + py::repr(key).cast<std::string>());
    }
    const std::string name = key.cast<std::string>();
    if (py::isinstance<py::bool_>(value)) {
      object[name] = value.cast<bool>();
      continue;
    }
    try {
      object[name] = value.cast<double>();  // what float() takes
    } catch (const py::cast_error&) {
      // not a number (an array, text, an int too large for a double): its text, shortened
      constexpr std::size_t kShown = 40;
      std::string text = py::str(value).cast<std::string>();
      if (text.size() > kShown) text = text.substr(0, kShown) + "...";
      object[name] = text;
    }
  }
  return object;
}

// ---- genomes ----

// The genes of one row, with the fixed masses at their defaults, validated as
// a genome file is (the gene, its value and its allowed range named after
// `source`).
Genome GenomeOfGenes(const double* genes, const std::string& source) {
  Genome genome = DefaultGenome();
  std::copy(genes, genes + kNumGenes, genome.genes.begin());
  return GenomeFromJson(GenomeToJson(genome), source);
}

// "(3, 17)": an array's shape as NumPy prints it
std::string ShapeText(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < array.ndim(); ++d) {
    text += (d > 0 ? ", " : "") + std::to_string(array.shape(d));
  }
  return text + (array.ndim() == 1 ? ",)" : ")");
}

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// A path as str or os.PathLike; TypeError for anything else, as os.fspath.
std::string PathOf(const py::handle& path) {
  return py::module_::import("os").attr("fspath")(path).cast<std::string>();
}

// A genome from what Python code holds: a dict of a genome file's keys, a
// genome file's path (str or os.PathLike), or a sequence of the 18 genes in
// the gene table's order. `what` names it in messages.
Genome GenomeOf(const py::handle& genome, const std::string& what) {
  if (py::isinstance<py::dict>(genome)) return GenomeFromJson(JsonOfDict(genome.cast<py::dict>()), what);
  if (py::isinstance<py::str>(genome) || py::hasattr(genome, "__fspath__")) {
    return LoadGenome(PathOf(genome));
  }
  const DoubleArray genes = DoubleArray::ensure(genome);
  if (!genes) {
    throw py::value_error(what + " must be a dict of genes, a genome file's path or an array of the " +
                          std::to_string(kNumGenes) + " genes");
  }
  if (genes.ndim() != 1 || genes.shape(0) != kNumGenes) {
    throw py::value_error(what + " must have shape (" + std::to_string(kNumGenes) +
                          ",), one value per gene; got shape " + ShapeText(genes));
  }
  return GenomeOfGenes(genes.data(), what);
}

// A genome as a dict of a genome file's keys: the genes in the gene table's
// order, then the fixed masses.
py::dict DictOfGenome(const Genome& genome) {
  const nlohmann::json json = GenomeToJson(genome);
  py::dict dict;
  for (const GeneSpec& spec : GeneTable()) dict[spec.name] = json.at(spec.name).get<double>();
  for (const auto& [key, value] : json.items()) {
    if (!dict.contains(key)) dict[py::str(key)] = value.get<double>();
  }
  return dict;
}

py::array_t<double> GenesArray(const Genome& genome) {
  py::array_t<double> genes(kNumGenes);
  std::copy(genome.genes.begin(), genome.genes.end(), genes.mutable_data());
  return genes;
}

// One column of the gene table as an array, in the table's order.
template <typename Field>
py::array_t<double> GeneColumn(Field field) {
  py::array_t<double> column(kNumGenes);
  for (int i = 0; i < kNumGenes; ++i) column.mutable_data()[i] = GeneTable()[i].*field;
  return column;
}

// ---- evaluations ----

py::dict Evaluate1(const py::handle& genome_object, const std::string& preset_name, std::optional<int> ensemble_size) {
  const Genome genome = GenomeOf(genome_object, "genome");
  const Preset preset = PresetByName(preset_name);
  if (ensemble_size) RequireInRange("ensemble", *ensemble_size, 1, kMaxEnsemble);
  nlohmann::json out;
  {
    py::gil_scoped_release no_gil;
    // as `walkers evaluate --json [--ensemble N]`: the ensemble's middle member is this evaluation
    const EvaluationResult result = Evaluate(genome, preset);
    if (ensemble_size) {
      const FitnessEnsemble ensemble = EvaluateEnsemble(genome, preset, {}, *ensemble_size, &result);
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

// The thread evaluator of the last batch, kept with its threads started for
// the next batch on as many threads. A batch holds its own reference, so a
// batch on other threads at the same time may replace it safely.
std::shared_ptr<Evaluator> ThreadPool(int threads) {
  static std::mutex mutex;
  static std::shared_ptr<Evaluator> pool;
  std::lock_guard<std::mutex> lock(mutex);
  if (!pool || pool->slots() != threads) pool = MakeThreadEvaluator(threads);
  return pool;
}

py::dict EvaluateBatch(const py::handle& genomes_object, const std::string& preset_name, std::optional<int> threads) {
  const DoubleArray rows = DoubleArray::ensure(genomes_object);
  if (!rows) throw py::value_error("genomes must be an array of numbers, one genome per row");
  if (rows.ndim() != 2 || rows.shape(1) != kNumGenes) {
    throw py::value_error("genomes must have shape (n, " + std::to_string(kNumGenes) +
                          "), one genome per row; got shape " + ShapeText(rows));
  }
  const Preset preset = PresetByName(preset_name);
  if (threads) RequireInRange("threads", *threads, 1, kMaxThreads);
  const int slots = threads ? *threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));

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
    const EvaluationSettings settings;
    std::vector<EvaluationTask> tasks(n);
    for (py::ssize_t i = 0; i < n; ++i) tasks[i] = {&genomes[i], &preset, &settings, &results[i]};
    ThreadPool(slots)->EvaluateAll(tasks);
  }

  py::array_t<double> fitness(n);
  py::array_t<bool> fell(n);
  py::array_t<std::int64_t> footsteps(n), cvode_steps(n);
  py::list gait;
  for (py::ssize_t i = 0; i < n; ++i) {
    fitness.mutable_data()[i] = results[i].fitness;
    fell.mutable_data()[i] = results[i].fell;
    footsteps.mutable_data()[i] = results[i].footsteps;
    cvode_steps.mutable_data()[i] = results[i].cvode_steps;
    gait.append(GaitName(results[i].gait));
  }
  py::dict out;
  out["fitness"] = fitness;
  out["gait"] = py::module_::import("numpy").attr("array")(gait, py::arg("dtype") = "U6");
  out["fell"] = fell;
  out["footsteps"] = footsteps;
  out["cvode_steps"] = cvode_steps;
  return out;
}

}  // namespace
}  // namespace walkers::python

PYBIND11_MODULE(walkers, m) {
  using namespace walkers;
  using namespace walkers::python;
  m.doc() = "Scaffolded bipedal walkers: genomes and their evaluations (docs/python.md)";
  m.attr("__version__") = SourceCommit();

  // the genome files' and the genes' errors are bad input, as the CLI reports them
  py::register_exception_translator([](std::exception_ptr error) {
    try {
      if (error) std::rethrow_exception(error);
    } catch (const GenomeError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
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
        "One 15 s evaluation: the fields of `walkers evaluate --json`, with an ensemble of N as --ensemble N");
  m.def("evaluate_batch", &EvaluateBatch, py::arg("genomes"), py::arg("preset") = "original",
        py::arg("threads") = py::none(),
        "Evaluates an (n, 18) array, one genome per row, on `threads` threads (default: every core); "
        "returns arrays of fitness, gait, fell, footsteps and cvode_steps");

  m.def("record_walk", &RecordWalk1, py::arg("genome"), py::arg("preset") = "original",
        "One evaluation recorded at 30 Hz: the result's fields, the body's sizes and the frames as arrays");

  m.def(
      "scaffold_cases", [] { return ScaffoldCaseNames(); }, "The scaffolds' names in the paper's order");
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
}
