#include "python/run_binding.h"

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
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

// Where the run's thread stands, as the Python side sees it.
enum class Phase {
  kWorking,    // evaluating, writing files: Python waits
  kProposing,  // waits in Propose for the generation's genomes
  kTold,       // told the evaluated children; waits in State for the checkpoint's state
  kFinished,   // every generation done, archive.json and best.json written
  kFailed,     // stopped by an error, or by close()
};

// Thrown on the run's thread when Python closes the run while it waits.
struct Closed {};

// One run and its thread. Python's calls hand the run what it waits for and
// wait, without the GIL, until it waits again; the run's thread never touches
// Python. One call at a time: a second Python thread's call is refused.
class PythonRun : public ProposalSource {
 public:
  PythonRun(const RunConfig& config, const std::string& dir, StartMode mode, int threads)
      : evaluator_(ThreadPool(threads)), population_(config.ga.population), generations_(config.generations) {
    auto learner = std::make_unique<ExternalLearner>(LearnerByName(config.learner), config.ga.population, this);
    const ExternalLearner* external = learner.get();
    run_ = std::make_unique<EvolutionRun>(config, dir, mode, *evaluator_, std::move(learner));
    restored_ = external->restored_state();
    completed_ = run_->completed_generations();
    thread_ = std::thread([this] { Loop(); });
  }
  ~PythonRun() override { Close(); }
  PythonRun(const PythonRun&) = delete;
  PythonRun& operator=(const PythonRun&) = delete;

  // ---- the run's thread: the external learner's questions ----

  std::vector<Genome> Propose(const BreedingInputs& in, int) override {
    std::unique_lock<std::mutex> lock(mutex_);
    in_ = in;
    phase_ = Phase::kProposing;
    changed_.notify_all();
    changed_.wait(lock, [&] { return proposals_.has_value() || closing_; });
    if (closing_) throw Closed{};
    std::vector<Genome> genomes = std::move(*proposals_);
    proposals_.reset();
    return genomes;
  }

  void Tell(const BreedingInputs&, const std::vector<Individual>& evaluated) override {
    std::lock_guard<std::mutex> lock(mutex_);
    evaluated_ = evaluated;
    phase_ = Phase::kTold;
    changed_.notify_all();
  }

  nlohmann::json State() override {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return state_.has_value() || closing_; });
    if (closing_) throw Closed{};
    nlohmann::json state = std::move(*state_);
    state_.reset();
    return state;
  }

  // ---- Python's calls ----

  py::tuple Bounds() {
    const Busy busy(this);
    BreedingInputs in;
    {
      py::gil_scoped_release no_gil;
      std::unique_lock<std::mutex> lock(mutex_);
      Require(Phase::kProposing, "bounds()", lock);
      in = in_;
    }
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
    std::vector<Individual> evaluated;
    {
      py::gil_scoped_release no_gil;
      std::unique_lock<std::mutex> lock(mutex_);
      Answer(Phase::kProposing, "evaluate()", [&] { proposals_ = std::move(genomes); }, lock);
      Require(Phase::kTold, "evaluate()", lock);
      evaluated = evaluated_;
    }
    py::array_t<double> genes({static_cast<py::ssize_t>(evaluated.size()), static_cast<py::ssize_t>(kNumGenes)});
    std::vector<EvaluationResult> results;
    for (std::size_t c = 0; c < evaluated.size(); ++c) {
      std::copy(evaluated[c].genome.genes.begin(), evaluated[c].genome.genes.end(), genes.mutable_data(c, 0));
      results.push_back(evaluated[c].result);
    }
    py::dict arrays = ResultArrays(results);
    py::list parents;
    for (const Individual& c : evaluated) parents.append(c.parents);
    arrays["parents"] = parents;
    return py::make_tuple(genes, arrays);
  }

  void Checkpoint(const py::handle& state) {
    const Busy busy(this);
    nlohmann::json json = JsonOf(state, "state");
    py::gil_scoped_release no_gil;
    std::unique_lock<std::mutex> lock(mutex_);
    Answer(Phase::kTold, "checkpoint()", [&] { state_ = std::move(json); }, lock);
    if (phase_ == Phase::kFailed) throw std::runtime_error(error_);
  }

  // Whether every generation is done; a done run's files are final, and its
  // folder is released.
  bool Done() {
    const Busy busy(this);
    bool finished = false;
    {
      py::gil_scoped_release no_gil;
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [&] { return phase_ != Phase::kWorking; });
      if (phase_ == Phase::kFailed) throw std::runtime_error(error_);
      finished = phase_ == Phase::kFinished;
    }
    if (finished) Close();
    return finished;
  }

  int completed() {
    std::lock_guard<std::mutex> lock(mutex_);
    return completed_;
  }
  int generations() const { return generations_; }
  int population() const { return population_; }
  py::object restored_state() const { return ToPython(restored_); }

  // The last generation's summary, as a dict; None before the first.
  py::object Progress() {
    std::optional<GenerationSummary> s;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      s = last_;
    }
    if (!s) return py::none();
    py::dict out;
    out["generation"] = s->generation;
    out["best_fitness"] = s->best_fitness;
    out["ave_best3"] = s->ave_best3;
    out["ceiling"] = s->ceiling;
    out["falls"] = s->falls;
    out["evals_per_s"] = s->evals_per_s;
    return out;
  }

  // Stops the run's thread (a run waiting for Python ends there; one
  // evaluating finishes the generation's evaluations first) and releases the
  // folder: what the last checkpoint holds is what a resume continues.
  void Close() {
    if (thread_.joinable()) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        closing_ = true;
      }
      changed_.notify_all();
      thread_.join();  // the run's thread never needs the GIL
    }
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

  void Loop() {
    std::string error;
    Phase end = Phase::kFinished;
    try {
      run_->Run([this](const GenerationSummary& s) {
        std::lock_guard<std::mutex> lock(mutex_);
        completed_ = s.generation + 1;
        last_ = s;
      });
    } catch (const Closed&) {
      end = Phase::kFailed;
      error = "the run is closed";
    } catch (const std::exception& e) {
      end = Phase::kFailed;
      error = e.what();
    }
    std::lock_guard<std::mutex> lock(mutex_);
    phase_ = end;
    error_ = error;
    changed_.notify_all();
  }

  // Requires the run to wait at `at` (as Require), gives it what it waits for
  // (`give`, under the lock), and waits until it waits again or has stopped.
  template <typename Give>
  void Answer(Phase at, const std::string& call, Give give, std::unique_lock<std::mutex>& lock) {
    Require(at, call, lock);
    give();
    phase_ = Phase::kWorking;
    changed_.notify_all();
    changed_.wait(lock, [&] { return phase_ != Phase::kWorking; });
  }

  // Waits until the run waits for Python or has stopped, then requires it to
  // wait at `wanted`: an error naming `call` otherwise.
  void Require(Phase wanted, const std::string& call, std::unique_lock<std::mutex>& lock) {
    changed_.wait(lock, [&] { return phase_ != Phase::kWorking; });
    if (phase_ == wanted) return;
    switch (phase_) {
      case Phase::kFailed:
        throw std::runtime_error(error_);
      case Phase::kFinished:
        throw std::runtime_error(call + ": the run is done (" + std::to_string(generations_) + " generations)");
      case Phase::kTold:
        throw std::runtime_error(call + ": generation " + std::to_string(in_.generation) +
                                 " is evaluated; call checkpoint(state) first");
      default:
        throw std::runtime_error(call + ": generation " + std::to_string(in_.generation) +
                                 " is not evaluated yet; call evaluate(genomes) first");
    }
  }

  std::shared_ptr<Evaluator> evaluator_;
  std::unique_ptr<EvolutionRun> run_;
  const int population_;
  const int generations_;
  nlohmann::json restored_;
  std::thread thread_;
  bool busy_ = false;  // a Python call is under way (read and written with the GIL)

  std::mutex mutex_;
  std::condition_variable changed_;
  // guarded by mutex_
  Phase phase_ = Phase::kWorking;
  std::string error_;
  bool closing_ = false;
  BreedingInputs in_;
  std::optional<std::vector<Genome>> proposals_;
  std::vector<Individual> evaluated_;
  std::optional<nlohmann::json> state_;
  int completed_ = 0;
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
