#include "evolve/run_config.h"

#include <limits>

#include "files/input_file.h"

namespace walkers {
using nlohmann::json;

namespace {

int IntField(const JsonFields& f, const std::string& key) {
  return static_cast<int>(f.Integer(key, std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
}

// The evaluation settings config.json records, with their allowed ranges.
struct EvaluationField {
  const char* key;
  NumberRange range;
  double* (*of)(EvaluationSettings*);
};
const EvaluationField kEvaluationFields[] = {
    {"duration", {0, 3600, true}, [](EvaluationSettings* e) { return &e->duration; }},
    {"relative_tolerance", {0, 1, true}, [](EvaluationSettings* e) { return &e->integrator.relative_tolerance; }},
    {"absolute_tolerance_position", {0, 1, true},
     [](EvaluationSettings* e) { return &e->integrator.absolute_tolerance_position; }},
    {"absolute_tolerance_velocity", {0, 1, true},
     [](EvaluationSettings* e) { return &e->integrator.absolute_tolerance_velocity; }},
    {"contact_stiffness", {0, 1e15, true}, [](EvaluationSettings* e) { return &e->contact.surface.stiffness; }},
    {"contact_dissipation", {0, 1e6}, [](EvaluationSettings* e) { return &e->contact.surface.dissipation; }},
    {"friction_transition_velocity", {0, 1e3, true},
     [](EvaluationSettings* e) { return &e->contact.transition_velocity; }},
    {"weld_depth", {0, 0.1}, [](EvaluationSettings* e) { return &e->weld.depth; }},
    {"weld_stabilization", {0, 1e6, true}, [](EvaluationSettings* e) { return &e->weld.stabilization; }},
};
constexpr int kMaxBdfOrder = 5;  // CVODE's BDF
// the integrator's keys, present in runs that are not CVODE's without a cut-off
constexpr const char* kIntegratorKeys[] = {"integrator", "accuracy", "constraint_tolerance", "cut_off_rhs"};
constexpr long kMaxCutOffRhs = 1000000000;

double Of(const EvaluationField& field, const EvaluationSettings& settings) {
  return *field.of(const_cast<EvaluationSettings*>(&settings));
}

}  // namespace

bool NamesLearner(const RunConfig& c) { return c.learner != DefaultLearner().name; }

void RunConfig::Validate(const std::string& source) const {
  const LearnerSpec& spec = LearnerByName(learner);
  RequireInRange(FieldOf(source, "generations"), generations, 1, kMaxGenerations);
  if (seed > kMaxSeed) {
    throw InputError(FieldOf(source, "seed") + " = " + std::to_string(seed) + " is outside its allowed range [0, " +
                     std::to_string(kMaxSeed) + "]");
  }
  ga.Validate(source);
  RequireInRange(FieldOf(source, "population"), ga.population, spec.min_population, kMaxPopulation,
                 std::string(" for the learner ") + spec.name);
  for (const EvaluationField& field : kEvaluationFields) {
    RequireInRange(FieldOf(source, std::string("evaluation.") + field.key), Of(field, evaluation), field.range);
  }
  RequireInRange(FieldOf(source, "evaluation.max_order"), evaluation.integrator.max_order, 1, kMaxBdfOrder);
}

json EvaluationSettingsToJson(const EvaluationSettings& settings) {
  json evaluation = {{"max_order", settings.integrator.max_order},
                     {"restart_at_ticks", settings.integrator.restart_at_ticks}};
  for (const EvaluationField& field : kEvaluationFields) evaluation[field.key] = Of(field, settings);
  // the integrator and the cut-off, written when they are not CVODE's and
  // none (files without them are CVODE's runs)
  const IntegratorSettings& integrator = settings.integrator;
  if (integrator.method != IntegrationMethod::kCvode || settings.cut_off_rhs != 0) {
    evaluation["integrator"] = IntegrationMethodName(integrator.method);
    evaluation["accuracy"] = integrator.accuracy;
    evaluation["constraint_tolerance"] = integrator.constraint_tolerance;
    evaluation["cut_off_rhs"] = settings.cut_off_rhs;
  }
  return evaluation;
}

json RunConfigToJson(const RunConfig& c) {
  const json evaluation = EvaluationSettingsToJson(c.evaluation);
  json out = {{"case", ScaffoldCaseName(c.scaffold_case)},
              {"preset", c.preset.name},
              {"generations", c.generations},
              {"seed", c.seed},
              {"population", c.ga.population},
              {"archive_size", c.ga.archive_size},
              {"mutation_children", c.ga.mutation_children},
              {"mutation_probability", c.ga.mutation_probability},
              {"evaluation", evaluation}};
  if (NamesLearner(c)) out["learner"] = c.learner;
  return out;
}

void RequireResumableAs(const RunConfig& stored, const RunConfig& requested, const std::string& source) {
  // the learner compared too, the GA's included, which config.json leaves unnamed
  const auto compared = [](const RunConfig& c) {
    json j = RunConfigToJson(c);
    j["learner"] = c.learner;
    return j;
  };
  const json have = compared(stored), want = compared(requested);
  for (const auto& item : want.items()) {
    if (item.key() == "generations") continue;  // a resumed run may be extended
    if (!have.contains(item.key()) || have.at(item.key()) != item.value()) {
      throw InputError(source + ": this run has " + item.key() + " = " +
                       (have.contains(item.key()) ? have.at(item.key()).dump() : std::string("(none)")) + " but " +
                       item.value().dump() + " was asked for; resume with the run's own settings");
    }
  }
}

RunConfig RunConfigFromJson(const json& j, const std::string& source) {
  const json keys = RunConfigToJson(RunConfig{});
  const JsonFields f(j, source);
  std::vector<std::string> known = KeysOf(keys);
  known.push_back("learner");  // absent: the paper's GA
  f.RequireOnly(known);
  RunConfig c;
  c.scaffold_case = ScaffoldCaseByName(f.OneOf("case", ScaffoldCaseNames()));
  if (j.contains("learner")) c.learner = f.OneOf("learner", LearnerNames());
  c.preset = PresetByName(f.OneOf("preset", PresetNames()));
  c.generations = IntField(f, "generations");
  c.seed = f.Unsigned("seed", kMaxSeed);
  c.ga.population = IntField(f, "population");
  c.ga.archive_size = IntField(f, "archive_size");
  c.ga.mutation_children = IntField(f, "mutation_children");
  c.ga.mutation_probability = f.Number("mutation_probability");
  const JsonFields e = f.Object("evaluation");
  std::vector<std::string> evaluation_keys = KeysOf(keys.at("evaluation"));
  for (const char* key : kIntegratorKeys) evaluation_keys.push_back(key);
  e.RequireOnly(evaluation_keys);
  for (const EvaluationField& field : kEvaluationFields) *field.of(&c.evaluation) = e.Number(field.key, field.range);
  c.evaluation.integrator.max_order = static_cast<int>(e.Integer("max_order", 1, kMaxBdfOrder));
  c.evaluation.integrator.restart_at_ticks = e.Bool("restart_at_ticks");
  if (j.at("evaluation").contains("integrator")) {
    IntegratorSettings& integrator = c.evaluation.integrator;
    const std::string method = e.OneOf("integrator", {"cvode", "rk-merson"});
    ParseIntegrationMethod(method, &integrator.method);
    integrator.accuracy = e.Number("accuracy", {0, 1, true});
    integrator.constraint_tolerance = e.Number("constraint_tolerance", {0, 1, true});
    c.evaluation.cut_off_rhs = e.Integer("cut_off_rhs", 0, kMaxCutOffRhs);
  }
  c.Validate(source);
  return c;
}

RunConfig ParseRunConfig(const std::string& text, const std::string& source) {
  return RunConfigFromJson(ParseJson(text, source), source);
}

}  // namespace walkers
