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

FitnessEnsemble EvaluateEnsemble(const Genome& genome, const Preset& preset, const EvaluationSettings& settings,
                                 int size, const EvaluationResult* unperturbed) {
  FitnessEnsemble ensemble;
  for (int k = 0; k < size; ++k) {
    const double offset = k - 0.5 * (size - 1);  // half-integers for an even size
    EvaluationResult r;
    if (offset == 0.0 && unperturbed) {
      r = *unperturbed;
    } else {
      EvaluationSettings member = settings;
      member.integrator.relative_tolerance *= 1.0 + 1e-4 * offset;
      r = Evaluate(genome, preset, member);
    }
    ensemble.fitness.push_back(r.fitness);
    ensemble.bipeds += r.gait == Gait::kBiped ? 1 : 0;
    ensemble.falls += r.fell ? 1 : 0;
  }
  return ensemble;
}

}  // namespace walkers
