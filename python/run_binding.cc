#include "python/run_binding.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "control/preset.h"
#include "evolve/external_learner.h"
#include "evolve/run.h"
#include "evolve/scaffold.h"
#include "python/conversions.h"

namespace walkers::python {
namespace {

// One run, driven by Python's calls: bounds() begins a generation,
// evaluate() evaluates its children with the GIL released, checkpoint()
// finishes it. A generation begun or evaluated is kept here between the
// calls; one call at a time (a second Python thread's call is refused).
class PythonRun {
 public:
  PythonRun(const RunConfig& config, const std::string& dir, StartMode mode, int threads)
      : evaluator_(ThreadPool(threads)),
        run_(std::make_unique<EvolutionRun>(config, dir, mode, *evaluator_)),
        population_(config.ga.population),
        generations_(config.generations),
        restored_(external().restored_state()) {}
  PythonRun(const PythonRun&) = delete;
  PythonRun& operator=(const PythonRun&) = delete;

  py::tuple Bounds() {
    const Busy busy(this);
    const BreedingInputs& in = Begun("bounds()");
    py::array_t<double> lo(kNumGenes), hi(kNumGenes);
    for (int k = 0; k < kNumGenes; ++k) {
      const GeneBounds b = ChildGeneBounds(k, in.body_ceiling);
      lo.mutable_data()[k] = b.lo;
      hi.mutable_data()[k] = b.hi;
    }
    return py::make_tuple(lo, hi);
  }

  py::tuple Evaluate(const py::handle& proposals) {
    const Busy busy(this);
    const BreedingInputs in = Begun("evaluate()");
    const DoubleArray rows = GeneRows(proposals, "genomes", population_);
    std::vector<Genome> genomes;
    for (py::ssize_t i = 0; i < rows.shape(0); ++i) {
      Genome genome = DefaultGenome();
      for (int k = 0; k < kNumGenes; ++k) {
        const double x = rows.at(i, k);
        if (!std::isfinite(x)) {
          throw py::value_error("genomes[" + std::to_string(i) + "]: gene '" + GeneTable()[k].name + "' is " +
                                std::to_string(x) +
                                ": a proposed gene must be a finite number (one outside its bounds is clamped "
                                "into them)");
        }
        genome.genes[k] = x;
      }
      genomes.push_back(genome);
    }
    const std::vector<Individual> children = external().Children(in, genomes);
    EvaluatedChildren evaluated;
    Failing([&] {
      py::gil_scoped_release no_gil;
      evaluated = run_->EvaluateChildren(in, children);
    });
    py::array_t<double> genes(
        {static_cast<py::ssize_t>(evaluated.children.size()), static_cast<py::ssize_t>(kNumGenes)});
    std::vector<EvaluationResult> results;
    py::list lineages;
    for (std::size_t c = 0; c < evaluated.children.size(); ++c) {
      const Individual& child = evaluated.children[c];
      std::copy(child.genome.genes.begin(), child.genome.genes.end(), genes.mutable_data(c, 0));
      results.push_back(child.result);
      lineages.append(child.lineage.Text());
    }
    py::dict arrays = ResultArrays(results);
    arrays["parents"] = lineages;
    evaluated_ = std::move(evaluated);
    return py::make_tuple(genes, arrays);
  }

  void Checkpoint(const py::handle& state) {
    const Busy busy(this);
    const nlohmann::json learner_state = ExternalLearner::StateOf(JsonOf(state, "state"));
    const BreedingInputs in = Begun("checkpoint()");
    if (!evaluated_) {
      throw std::runtime_error("checkpoint(): generation " + std::to_string(in.generation) +
                               " is not evaluated yet; call evaluate(genomes) first");
    }
    Failing([&] {
      py::gil_scoped_release no_gil;
      last_ = run_->FinishGeneration(in, *evaluated_, learner_state);
    });
    begun_.reset();
    evaluated_.reset();
  }

  // Whether every generation is done; a done run's files are final, and its
  // folder is released.
  bool Done() {
    const Busy busy(this);
    if (run_ && run_->done()) Close();
    return finished_;
  }

  int completed() const { return run_ ? run_->completed_generations() : completed_; }
  int generations() const { return generations_; }
  int population() const { return population_; }
  py::object restored_state() const { return ToPython(restored_); }

  // The last generation's summary, as a dict; None before the first.
  py::object Progress() const {
    if (!last_) return py::none();
    py::dict out;
    out["generation"] = last_->generation;
    out["best_fitness"] = last_->best_fitness;
    out["ave_best3"] = last_->ave_best3;
    out["ceiling"] = last_->ceiling;
    out["falls"] = last_->falls;
    out["evals_per_s"] = last_->evals_per_s;
    return out;
  }

  // Releases the folder: what the last checkpoint holds is what a resume
  // continues (a generation begun or evaluated since is dropped).
  void Close() {
    if (!run_) return;
    finished_ = run_->done();
    completed_ = run_->completed_generations();
    begun_.reset();
    evaluated_.reset();
    run_.reset();
  }

 private:
  // Marks a Python call under way; a second one at the same time is an error.
  class Busy {
   public:
    explicit Busy(PythonRun* run) : run_(run) {
      if (run_->busy_) {
        throw std::runtime_error("another call on this Run is under way: a run answers one Python thread at a time");
      }
      run_->busy_ = true;
    }
    ~Busy() { run_->busy_ = false; }
    Busy(const Busy&) = delete;
    Busy& operator=(const Busy&) = delete;

   private:
    PythonRun* run_;
  };

  // The generation under way, begun if none is: an error naming `call` when
  // the run is closed or done, or when its generation is evaluated and
  // `call` is not checkpoint().
  const BreedingInputs& Begun(const std::string& call) {
    if (run_ ? run_->done() : finished_) {
      throw std::runtime_error(call + ": the run is done (" + std::to_string(generations_) + " generations)");
    }
    if (!run_) throw std::runtime_error(call + ": the run is closed");
    if (evaluated_ && call != "checkpoint()") {
      throw std::runtime_error(call + ": generation " + std::to_string(begun_->generation) +
                               " is evaluated; call checkpoint(state) first");
    }
    if (!begun_) begun_ = run_->BeginGeneration();
    return *begun_;
  }

  const ExternalLearner& external() const { return dynamic_cast<const ExternalLearner&>(run_->learner()); }

  // Runs `step` of the run; a failure closes the run at its last checkpoint
  // before it reaches Python.
  template <typename Step>
  void Failing(const Step& step) {
    try {
      step();
    } catch (...) {
      Close();
      throw;
    }
  }

  std::shared_ptr<Evaluator> evaluator_;
  std::unique_ptr<EvolutionRun> run_;  // null once closed
  const int population_;
  const int generations_;
  const nlohmann::json restored_;
  bool busy_ = false;     // a Python call is under way (read and written with the GIL)
  bool finished_ = false;  // closed with every generation done
  int completed_ = 0;      // the generations completed when closed
  std::optional<BreedingInputs> begun_;
  std::optional<EvaluatedChildren> evaluated_;
  std::optional<GenerationSummary> last_;
};

std::unique_ptr<PythonRun> MakeRun(const py::handle& out, const std::string& case_name, int generations,
                                   int population, std::uint64_t seed, const std::string& preset,
                                   std::optional<int> archive, std::optional<int> threads, bool resume, bool force) {
  if (resume && force) throw py::value_error("resume and force exclude each other");
  RunConfig config;
  config.learner = "external";
  config.scaffold_case = ScaffoldCaseByName(case_name);
  config.preset = PresetByName(preset);
  config.generations = generations;
  config.seed = seed;
  config.ga.population = population;
  // the GA's mutants are not the external learner's: only its sizes count
  config.ga.mutation_children = std::clamp(config.ga.mutation_children, 0, population);
  if (archive) config.ga.archive_size = *archive;
  const StartMode mode = resume ? StartMode::kResume : force ? StartMode::kForce : StartMode::kNew;
  return std::make_unique<PythonRun>(config, PathOf(out), mode, ThreadsOrEveryCore(threads));
}

}  // namespace
void BindRun(py::module_& m) {
  py::class_<PythonRun>(m, "Run",
                        "An evolution run under a scaffold whose children a Python optimiser proposes (ask/tell). "
                        "It writes the run folder `walkers evolve --learner` writes, its learner named 'external'; "
                        "each generation: bounds(), evaluate(genomes), checkpoint(state) (docs/python.md)")
      .def(py::init(&MakeRun), py::arg("out"), py::arg("case") = "performance", py::arg("generations") = 300,
           py::arg("population") = 16, py::arg("seed") = 1, py::arg("preset") = "original",
           py::arg("archive") = py::none(), py::arg("threads") = py::none(), py::arg("resume") = false,
           py::arg("force") = false)
      .def("bounds", &PythonRun::Bounds,
           "The next generation's gene bounds (lo, hi): Table 1's, with the scaffold's ceiling on halfBodyX")
      .def("evaluate", &PythonRun::Evaluate, py::arg("genomes"),
           "Evaluates the next generation's (population, 18) proposals under the GA's rules (clamped into the "
           "bounds, a genome seen before drawn again); returns the genomes evaluated and evaluate_batch's arrays, "
           "with each child's parents")
      .def("checkpoint", &PythonRun::Checkpoint, py::arg("state"),
           "Hands the optimiser's state (any JSON value) for the generation's checkpoint; returns once it is on disk")
      .def_property_readonly("done", &PythonRun::Done, "Whether every generation is done")
      .def_property_readonly("completed_generations", &PythonRun::completed)
      .def_property_readonly("generations", &PythonRun::generations)
      .def_property_readonly("population", &PythonRun::population)
      .def_property_readonly("state", &PythonRun::restored_state,
                             "The state the resumed run was checkpointed with; None for a fresh run")
      .def_property_readonly("progress", &PythonRun::Progress,
                             "The last generation's summary (best_fitness, ave_best3, ceiling, ...); None before one")
      .def("close", &PythonRun::Close, "Stops the run where its last checkpoint left it and releases the folder")
      .def("__enter__", [](PythonRun& run) -> PythonRun& { return run; }, py::return_value_policy::reference)
      .def("__exit__", [](PythonRun& run, const py::args&) { run.Close(); });
}

}  // namespace walkers::python
