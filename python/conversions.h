// Conversions between the project's types and Python's objects, shared by
// the module's functions (walkers_module.cc) and its ask/tell run
// (run_binding.cc): genomes from dicts, files and arrays, results as NumPy
// arrays, JSON as Python objects, and the module's thread evaluator.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "control/evaluation.h"
#include "control/genome.h"
#include "evolve/evaluator.h"

namespace walkers::python {
namespace py = pybind11;

// A batch's threads may number at most this, as --threads allows.
constexpr int kMaxThreads = 1024;

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// A JSON value as the Python object json.loads makes of it: a double is
// printed in its shortest round-trip form and parsed back to the same bits.
py::object ToPython(const nlohmann::json& value);

// A Python object as JSON, through json.dumps; a value JSON cannot hold
// (an integer beyond 64 bits, say) is a ValueError naming `what`.
nlohmann::json JsonOf(const py::handle& value, const std::string& what);

// A genome dict as the JSON object a genome file holds. Numbers (int, float,
// NumPy scalars) become doubles; anything else is kept in a form the genome's
// validation refuses with the gene's name (a bool, or the value's text).
nlohmann::json JsonOfDict(const py::dict& dict);

// The genes of one row, with the fixed masses at their defaults, validated as
// a genome file is (the gene, its value and its allowed range named after
// `source`).
Genome GenomeOfGenes(const double* genes, const std::string& source);

// "(3, 17)": an array's shape as NumPy prints it
std::string ShapeText(const py::array& array);

// An (n, 18) array of genes, one genome per row, as an array of doubles;
// ValueError naming `what` for anything else, or for `rows` rows when it is
// given (not -1).
DoubleArray GeneRows(const py::handle& object, const std::string& what, py::ssize_t rows = -1);

// A path as str or os.PathLike; TypeError for anything else, as os.fspath.
std::string PathOf(const py::handle& path);

// A genome from what Python code holds: a dict of a genome file's keys, a
// genome file's path (str or os.PathLike), or a sequence of the 18 genes in
// the gene table's order. `what` names it in messages.
Genome GenomeOf(const py::handle& genome, const std::string& what);

// A genome as a dict of a genome file's keys: the genes in the gene table's
// order, then the fixed masses.
py::dict DictOfGenome(const Genome& genome);

// A genome's genes, in the gene table's order.
py::array_t<double> GenesArray(const Genome& genome);

// Evaluations' results as evaluate_batch returns them: arrays of fitness,
// gait, fell, footsteps and cvode_steps, one entry per result.
py::dict ResultArrays(const std::vector<EvaluationResult>& results);

// The thread evaluator of `threads` threads (at least one; by default every core).
std::shared_ptr<Evaluator> ThreadPool(int threads);
int ThreadsOrEveryCore(std::optional<int> threads);

}  // namespace walkers::python
