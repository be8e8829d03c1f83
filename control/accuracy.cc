#include "control/accuracy.h"

#include <algorithm>
#include <cmath>

namespace walkers {

EvaluationSettings HundredTimesTighter(const EvaluationSettings& settings) {
  EvaluationSettings tight = settings;
  tight.integrator.relative_tolerance /= 100.0;
  tight.integrator.absolute_tolerance_position /= 100.0;
  tight.integrator.absolute_tolerance_velocity /= 100.0;
  return tight;
}

double RelativeFitnessDifference(double fitness, double reference) {
  return std::abs(fitness - reference) / std::max(1.0, std::abs(reference));
}

double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  if (n == 0) return 0.0;
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

double Quantile(std::vector<double> values, double p) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const double position = p * static_cast<double>(values.size() - 1);
  const size_t below = static_cast<size_t>(std::floor(position));
  const size_t above = std::min(below + 1, values.size() - 1);
  return values[below] + (position - static_cast<double>(below)) * (values[above] - values[below]);
}

AccuracyVerdict JudgeAccuracy(const FitnessEnsemble& production, const FitnessEnsemble& reference) {
  AccuracyVerdict v;
  const double reference_median = reference.Median();
  const double iqr = reference.UpperQuartile() - reference.LowerQuartile();
  v.regular = iqr < kRegularIqr * std::max(1.0, std::abs(reference_median));
  v.median_difference = RelativeFitnessDifference(production.Median(), reference_median);
  const bool inside =
      production.Median() >= reference.LowerQuartile() && production.Median() <= reference.UpperQuartile();
  v.fitness_agrees = v.regular && (v.median_difference < kRegularMedians || inside);
  const auto majority = [](int count, const FitnessEnsemble& e) {
    return 2 * count > static_cast<int>(e.fitness.size());
  };
  v.gait_agrees = majority(production.bipeds, production) == majority(reference.bipeds, reference) &&
                  majority(production.tripods, production) == majority(reference.tripods, reference);
  v.fall_agrees = majority(production.falls, production) == majority(reference.falls, reference);
  // a walk made or broken by the integration error
  const auto members = [](const FitnessEnsemble& e, auto&& in) {
    return static_cast<int>(std::count_if(e.fitness.begin(), e.fitness.end(), in));
  };
  const int production_stalled = members(production, [](double f) { return f <= kNonWalkerFitness; });
  const int production_walking = members(production, [](double f) { return f >= kWalkerFitness; });
  v.lost_walker = reference_median >= kWalkerFitness && majority(production_stalled, production);
  v.numerical_walker = reference_median <= kNonWalkerFitness && majority(production_walking, production);
  return v;
}

double FitnessEnsemble::Min() const {
  return fitness.empty() ? 0.0 : *std::min_element(fitness.begin(), fitness.end());
}

double FitnessEnsemble::Max() const {
  return fitness.empty() ? 0.0 : *std::max_element(fitness.begin(), fitness.end());
}

double FitnessEnsemble::WorstDifferenceFrom(double reference) const {
  double worst = 0.0;
  for (double f : fitness) worst = std::max(worst, RelativeFitnessDifference(f, reference));
  return worst;
}

EvaluationSettings EnsembleMemberSettings(const EvaluationSettings& settings, int size, int k,
                                          const Perturbation& perturbation) {
  const double offset = k - 0.5 * (size - 1);  // half-integers for an even size
  EvaluationSettings member = settings;
  if (offset == 0.0) return member;
  switch (perturbation.kind) {
    case PerturbationKind::kRelativeTolerance:
      // the integration's own tolerance: CVODE's relative tolerance, or
      // RK-Merson's accuracy
      if (member.integrator.method == IntegrationMethod::kRkMerson) {
        member.integrator.accuracy *= 1.0 + perturbation.step * offset;
      } else {
        member.integrator.relative_tolerance *= 1.0 + perturbation.step * offset;
      }
      break;
    case PerturbationKind::kStartPose:
      member.start_trunk_raise += perturbation.step * offset;
      break;
  }
  return member;
}

FitnessEnsemble EnsembleOf(const std::vector<EvaluationResult>& members) {
  FitnessEnsemble ensemble;
  for (const EvaluationResult& r : members) {
    ensemble.fitness.push_back(r.fitness);
    ensemble.bipeds += r.gait == Gait::kBiped ? 1 : 0;
    ensemble.tripods += r.gait == Gait::kTripod ? 1 : 0;
    ensemble.falls += r.outcome == Outcome::kFell ? 1 : 0;
    ensemble.cvode_steps.push_back(static_cast<double>(r.integrator_stats.steps));
    ensemble.wall_ms.push_back(r.wall_ms);
  }
  return ensemble;
}

FitnessEnsemble EvaluateEnsemble(const Genome& genome, const Preset& preset, const EvaluationSettings& settings,
                                 int size, const EvaluationResult* unperturbed, const Perturbation& perturbation) {
  std::vector<EvaluationResult> members;
  for (int k = 0; k < size; ++k) {
    const bool middle = 2 * k == size - 1;
    members.push_back(middle && unperturbed
                          ? *unperturbed
                          : Evaluate(genome, preset, EnsembleMemberSettings(settings, size, k, perturbation)));
  }
  return EnsembleOf(members);
}

}  // namespace walkers
