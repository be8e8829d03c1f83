// How accurately an evaluation's settings compute fitness (docs/performance.md,
// "Accuracy"). The walk is chaotic: a perturbation far below the integration
// error (the relative tolerance scaled by 1 + 1e-4) can move a touchdown by a
// controller tick and a walker's fitness by tens of per cent, at any
// tolerance. One evaluation per setting therefore says little; an ensemble of
// such perturbations shows the spread and gives a median to compare.
#pragma once

#include <vector>

#include "control/evaluation.h"

namespace walkers {

// The same settings with the relative and both absolute tolerances divided by 100.
EvaluationSettings HundredTimesTighter(const EvaluationSettings& settings);

// |fitness - reference| relative to the reference; fitnesses near zero
// (|reference| < 1) compare absolutely.
double RelativeFitnessDifference(double fitness, double reference);

// The median of some values; 0 if there are none.
double Median(std::vector<double> values);
// The p-quantile (0 <= p <= 1) by linear interpolation between order
// statistics (numpy's default); 0 if there are no values.
double Quantile(std::vector<double> values, double p);

struct FitnessEnsemble {
  std::vector<double> fitness;  // one per member, in order of the perturbation
  std::vector<double> cvode_steps, wall_ms;  // what each member cost, in the same order
  int bipeds = 0;
  int tripods = 0;
  int falls = 0;  // a fall has no gait class

  // of the fitnesses; 0 for an empty ensemble
  double Median() const { return walkers::Median(fitness); }
  double Min() const;
  double Max() const;
  // the largest RelativeFitnessDifference of a member from `reference`; 0 for
  // an empty ensemble
  double WorstDifferenceFrom(double reference) const;
  // whether the ensemble makes fitness one number: every member within
  // `tolerance` (relative) of the median
  bool Pinned(double tolerance) const { return WorstDifferenceFrom(Median()) <= tolerance; }
  // the interquartile range of the fitnesses
  double LowerQuartile() const { return Quantile(fitness, 0.25); }
  double UpperQuartile() const { return Quantile(fitness, 0.75); }
};

// The accuracy criterion of docs/performance.md ("Accuracy") for one genome,
// given its ensembles at the production settings and at 100x tighter ones:
// a genome is regular when the tight ensemble's interquartile range is under
// 2 % of its median; a regular genome's two medians must agree within 1 %, an
// irregular one's production median must lie inside the tight ensemble's
// interquartile range (the criterion also accepts a two-sample
// Kolmogorov-Smirnov p > 0.05 instead, which scripts/accuracy.py computes);
// and the majority's gait class and fall verdict must agree. Two more rules
// catch a walk that the integration error makes or breaks: no lost walker (a
// genome whose tight median is a walker's, >= kWalkerFitness, must not have
// a production majority, more than half its members, <= kNonWalkerFitness)
// and no numerical walker (the reverse: a production majority >=
// kWalkerFitness while the tight median is <= kNonWalkerFitness).
constexpr double kWalkerFitness = 5.0;     // [leg lengths] a walker's fitness, at least
constexpr double kNonWalkerFitness = 1.0;  // [leg lengths] a walker that went nowhere, at most
struct AccuracyVerdict {
  bool regular = false;
  double median_difference = 0;  // RelativeFitnessDifference of the medians
  bool fitness_agrees = false;   // regular: medians within 1 %; irregular: median inside the tight IQR
  bool gait_agrees = false;
  bool fall_agrees = false;
  bool lost_walker = false;       // the tight ensemble walks, production's majority does not
  bool numerical_walker = false;  // production's majority walks, the tight ensemble does not
  bool passes() const { return fitness_agrees && gait_agrees && fall_agrees && !lost_walker && !numerical_walker; }
};
AccuracyVerdict JudgeAccuracy(const FitnessEnsemble& production, const FitnessEnsemble& tight);

// `size` evaluations of the genome, member k with the relative tolerance
// scaled by 1 + 1e-4 (k - (size - 1) / 2), symmetric about the settings: for
// an odd size the middle member is the settings themselves. `unperturbed`, if
// given, is an evaluation of the genome at the settings that the caller has
// already made; an odd-size ensemble takes its middle member from it instead
// of evaluating again (the two would be bit-identical).
FitnessEnsemble EvaluateEnsemble(const Genome& genome, const Preset& preset, const EvaluationSettings& settings,
                                 int size, const EvaluationResult* unperturbed = nullptr);

// The settings of member k (0 <= k < size) of such an ensemble, and the
// ensemble of the members' results, for a caller that makes the evaluations
// itself (on an Evaluator's workers, say).
EvaluationSettings EnsembleMemberSettings(const EvaluationSettings& settings, int size, int k);
FitnessEnsemble EnsembleOf(const std::vector<EvaluationResult>& members);

}  // namespace walkers
