#include "python/conversions.h"

#include <algorithm>
#include <cstdint>
#include <mutex>
#include <thread>

#include "files/input_file.h"

namespace walkers::python {

py::object ToPython(const nlohmann::json& value) { return py::module_::import("json").attr("loads")(value.dump()); }

nlohmann::json JsonOf(const py::handle& value, const std::string& what) {
  const py::module_ json = py::module_::import("json");
  std::string text;
  try {
    text = json.attr("dumps")(value, py::arg("allow_nan") = false).cast<std::string>();
  } catch (const py::error_already_set& e) {
    throw py::value_error(what + " must be a JSON value (dicts, lists, strings, numbers, bools, None): " +
                          std::string(py::str(e.value())));
  }
  nlohmann::json parsed = nlohmann::json::parse(text);
  // an integer too large for 64 bits is parsed as a double: not the value given
  // (compared as text, keys sorted: an object's keys come back in order)
  const py::object dumps = json.attr("dumps"), loads = json.attr("loads");
  const auto canonical = [&](const std::string& t) { return dumps(loads(t), py::arg("sort_keys") = true); };
  if (!canonical(parsed.dump()).equal(canonical(text))) {
    throw py::value_error(what + " does not come back from JSON as it was given (an integer beyond 64 bits? "
                                 "keep it as a string)");
  }
  return parsed;
}

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

Genome GenomeOfGenes(const double* genes, const std::string& source) {
  Genome genome = DefaultGenome();
  std::copy(genes, genes + kNumGenes, genome.genes.begin());
  return GenomeFromJson(GenomeToJson(genome), source);
}

std::string ShapeText(const py::array& array) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < array.ndim(); ++d) {
    text += (d > 0 ? ", " : "") + std::to_string(array.shape(d));
  }
  return text + (array.ndim() == 1 ? ",)" : ")");
}

std::string PathOf(const py::handle& path) {
  return py::module_::import("os").attr("fspath")(path).cast<std::string>();
}

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

int ThreadsOrEveryCore(std::optional<int> threads) {
  if (!threads) return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  RequireInRange("threads", *threads, 1, kMaxThreads);
  return *threads;
}

DoubleArray GeneRows(const py::handle& object, const std::string& what, py::ssize_t rows) {
  const DoubleArray array = DoubleArray::ensure(object);
  if (!array) throw py::value_error(what + " must be an array of numbers, one genome per row");
  const std::string n = rows < 0 ? "n" : std::to_string(rows);
  if (array.ndim() != 2 || array.shape(1) != kNumGenes || (rows >= 0 && array.shape(0) != rows)) {
    throw py::value_error(what + " must have shape (" + n + ", " + std::to_string(kNumGenes) +
                          "), one genome per row; got shape " + ShapeText(array));
  }
  return array;
}

py::dict ResultArrays(const std::vector<EvaluationResult>& results) {
  const auto n = static_cast<py::ssize_t>(results.size());
  py::array_t<double> fitness(n);
  py::array_t<bool> fell(n);
  py::array_t<std::int64_t> footsteps(n), cvode_steps(n);
  py::list gait;
  for (py::ssize_t i = 0; i < n; ++i) {
    fitness.mutable_data()[i] = results[i].fitness;
    fell.mutable_data()[i] = results[i].outcome == Outcome::kFell;
    footsteps.mutable_data()[i] = results[i].footsteps;
    cvode_steps.mutable_data()[i] = results[i].integrator_stats.steps;
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

}  // namespace walkers::python
