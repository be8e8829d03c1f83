// How accurately an evaluation's settings compute fitness (docs/performance.md,
// "Accuracy"). The walk is chaotic: a perturbation far below the integration
// error can move a touchdown by a controller tick and a walker's fitness by
// tens of per cent, at any tolerance. One evaluation per setting therefore
// says little; an ensemble of perturbed evaluations shows the spread and gives
// a median to compare.
#pragma once

#include <vector>

#include "control/evaluation.h"

namespace walkers {

// The same settings with the relative and both absolute tolerances divided by
// 100: the accuracy criterion's reference.
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
// given its ensembles at the production settings and at the reference, 100x
// tighter ones, both perturbed by kAccuracyPerturbation. A genome is regular
// when the reference's interquartile range is under 2 % of its median (of 1
// when the median is smaller); a regular genome's fitness agrees when the two
// medians are within 1 % or production's median lies inside the reference's
// interquartile range. An irregular genome's fitness is judged by a two-sample
// Kolmogorov-Smirnov test whose p-values are Holm-corrected over the whole set
// (scripts/accuracy.py), not here. For every genome the majority's gait class
// and fall verdict must agree, and two rules catch a walk that the
// integration error makes or breaks: no lost walker (a genome whose reference
// median is a walker's, >= kWalkerFitness, must not have a production
// majority, more than half its members, <= kNonWalkerFitness) and no
// numerical walker (the reverse: a production majority >= kWalkerFitness
// while the reference median is <= kNonWalkerFitness). Over the set the
// criterion also asks for no drift (scripts/accuracy.py).
constexpr double kRegularIqr = 0.02;       // of the reference median: a regular genome's spread, below
constexpr double kRegularMedians = 0.01;   // a regular genome's medians, relative difference below
constexpr double kWalkerFitness = 5.0;     // [leg lengths] a walker's fitness, at least
constexpr double kNonWalkerFitness = 1.0;  // [leg lengths] a walker that went nowhere, at most
struct AccuracyVerdict {
  bool regular = false;
  double median_difference = 0;  // RelativeFitnessDifference of the medians
  // regular: medians within 1 % or production's median inside the reference
  // IQR; false for an irregular genome, whose KS test is judged over the set
  bool fitness_agrees = false;
  bool gait_agrees = false;
  bool fall_agrees = false;
  bool lost_walker = false;       // the reference walks, production's majority does not
  bool numerical_walker = false;  // production's majority walks, the reference does not
  // every rule of the genome's own; an irregular genome also needs its KS
  // test to pass over the set
  bool passes() const {
    return (!regular || fitness_agrees) && gait_agrees && fall_agrees && !lost_walker && !numerical_walker;
  }
};
AccuracyVerdict JudgeAccuracy(const FitnessEnsemble& production, const FitnessEnsemble& reference);

// How the members of an ensemble of `size` differ: member k (0 <= k < size)
// is moved by k - (size - 1) / 2 steps, symmetric about the settings, so that
// for an odd size the middle member is the settings themselves.
enum class PerturbationKind {
  // the relative tolerance scaled by 1 + offset * step: the re-scores of a
  // run's finals (evolve/finals.h) and `walkers evaluate --ensemble`
  kRelativeTolerance,
  // the start pose's trunk raised by offset * step [m]
  // (EvaluationSettings::start_trunk_raise): the same for any tolerance
  kStartPose,
};
struct Perturbation {
  PerturbationKind kind = PerturbationKind::kRelativeTolerance;
  double step = 1e-4;  // relative, or [m]
};
// the re-scores' ensembles
constexpr Perturbation kRescorePerturbation{PerturbationKind::kRelativeTolerance, 1e-4};
// The accuracy criterion's ensembles, production's and the reference's alike:
// members 1 um apart (of which the projection onto the welds keeps under a
// tenth, and the 2 s lock damps that about a thousandfold before the first
// step).
// At this step the 100x tighter reference spreads the walkers that its own
// dynamics makes chaotic about as much as production does; steps from 1e-8 to
// 1e-3 m were measured (docs/performance.md, "Accuracy").
constexpr Perturbation kAccuracyPerturbation{PerturbationKind::kStartPose, 1e-6};

// `size` evaluations of the genome, perturbed as `perturbation` says.
// `unperturbed`, if given, is an evaluation of the genome at the settings
// that the caller has already made; an odd-size ensemble takes its middle
// member from it instead of evaluating again (the two would be bit-identical).
FitnessEnsemble EvaluateEnsemble(const Genome& genome, const Preset& preset, const EvaluationSettings& settings,
                                 int size, const EvaluationResult* unperturbed = nullptr,
                                 const Perturbation& perturbation = kRescorePerturbation);

// The settings of member k (0 <= k < size) of such an ensemble, and the
// ensemble of the members' results, for a caller that makes the evaluations
// itself (on an Evaluator's workers, say).
EvaluationSettings EnsembleMemberSettings(const EvaluationSettings& settings, int size, int k,
                                          const Perturbation& perturbation = kRescorePerturbation);
FitnessEnsemble EnsembleOf(const std::vector<EvaluationResult>& members);

}  // namespace walkers
