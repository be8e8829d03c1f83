#include "evolve/analysis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "evolve/files.h"
#include "evolve/learner.h"
#include "evolve/run.h"

namespace walkers {
namespace {

using nlohmann::json;

// the paper's findings (§3) and the authors' runs (MODEL.md §7)
constexpr double kPaperCase3OverCase1 = 0.83;
constexpr double kPaperCase2OverCase1 = 0.66;
constexpr double kPaperBipedOverTripod = 1.375;

json Optional(const std::optional<double>& x) { return x ? json(*x) : json(nullptr); }

// a share as "12.3 %", or "—" for none
std::string Percent(const std::optional<double>& x) {
  if (!x) return "—";
  char buf[32];
  std::snprintf(buf, sizeof(buf), "%.1f %%", 100.0 * *x);
  return buf;
}

json IndividualJson(const std::optional<EvaluatedSummary>& e) {
  if (!e) return nullptr;
  return {{"run", e->run}, {"id", e->id}, {"fitness", e->fitness}};
}

void KeepBest(const EvaluatedSummary& candidate, std::optional<EvaluatedSummary>* best) {
  if (!*best || candidate.fitness > (*best)->fitness) *best = candidate;
}

}  // namespace

RunData LoadRunData(const std::string& dir, ScaffoldCase scaffold_case, int replicate, const std::string& name) {
  RunData run;
  run.scaffold_case = scaffold_case;
  run.replicate = replicate;
  run.name = name;
  const RunFiles files(dir);

  CsvReader generations(ReadFile(files.generations), files.generations);
  const int best = generations.Column("best_fitness");
  const int gait = generations.Column("best_gait");
  const int rate = generations.Column("evals_per_s");
  std::vector<double> evals_per_s;
  while (generations.Next()) {
    run.best_fitness.push_back(generations.Number(best));
    run.best_is_tripod.push_back(generations.fields()[gait] == "tripod");
    evals_per_s.push_back(generations.Number(rate));
  }

  CsvReader evaluations(ReadFile(files.evaluations), files.evaluations);
  const int gen = evaluations.Column("generation");
  const int child = evaluations.Column("child");
  const int fitness = evaluations.Column("fitness");
  const int fell = evaluations.Column("fell");
  const int kind = evaluations.Column("gait");
  const int first_gene = evaluations.Column(GeneTable()[0].name);
  std::vector<long> per_generation(evals_per_s.size(), 0);
  while (evaluations.Next()) {
    const std::vector<std::string>& row = evaluations.fields();
    const std::int64_t g = evaluations.Integer(gen, 0, std::numeric_limits<int>::max());
    EvaluatedSummary e{name, row[gen] + "/" + row[child], evaluations.Number(fitness), row[fell] == "1",
                       row[kind] == "tripod", Genome{}};
    ++run.evaluations;
    run.falls += e.fell ? 1 : 0;
    if (static_cast<std::size_t>(g) < per_generation.size()) ++per_generation[g];
    if (e.fell) continue;
    std::optional<EvaluatedSummary>* kept = e.tripod ? &run.best_tripod : &run.best_biped;
    if (*kept && (*kept)->fitness >= e.fitness) continue;
    e.genome = DefaultGenome();
    for (int k = 0; k < kNumGenes; ++k) e.genome.genes[k] = evaluations.Number(first_gene + k);
    *kept = e;
  }
  // the time the evaluations took, from each generation's rate
  for (std::size_t g = 0; g < evals_per_s.size(); ++g) {
    if (evals_per_s[g] > 0) run.evaluation_seconds += per_generation[g] / evals_per_s[g];
  }
  return run;
}

MeanSd MeanAndSd(const std::vector<double>& values) {
  MeanSd out;
  out.n = static_cast<int>(values.size());
  if (out.n == 0) return out;
  for (double v : values) out.mean += v;
  out.mean /= out.n;
  if (out.n > 1) {
    double ss = 0.0;
    for (double v : values) ss += (v - out.mean) * (v - out.mean);
    out.sd = std::sqrt(ss / (out.n - 1));
  }
  return out;
}

std::vector<int> ReportedGenerations(int generations) {
  std::vector<int> out;
  for (int g : {500, 1000, 2000}) {
    if (g < generations) out.push_back(g);
  }
  out.push_back(generations);
  return out;
}

ReproductionSummary Summarize(const std::vector<RunData>& runs) {
  ReproductionSummary s;
  for (const ScaffoldSpec& scaffold : Scaffolds()) {
    const ScaffoldCase c = scaffold.id;
    std::vector<const RunData*> of_case;
    for (const RunData& r : runs) {
      if (r.scaffold_case == c) of_case.push_back(&r);
    }
    if (of_case.empty()) continue;
    CaseSummary cs;
    cs.scaffold_case = c;
    cs.runs = static_cast<int>(of_case.size());
    // generations every replicate reached
    std::size_t generations = SIZE_MAX;
    for (const RunData* r : of_case) generations = std::min(generations, r->best_fitness.size());
    if (generations == 0 || generations == SIZE_MAX) {
      throw std::runtime_error("case " + std::string(scaffold.name) + " has a run with no generation");
    }
    for (std::size_t g = 0; g < generations; ++g) {
      std::vector<double> values;
      for (const RunData* r : of_case) values.push_back(r->best_fitness[g]);
      const MeanSd m = MeanAndSd(values);
      cs.mean_best.push_back(m.mean);
      cs.sd_best.push_back(m.sd);
    }
    for (int completed : ReportedGenerations(static_cast<int>(generations))) {
      std::vector<double> values;
      for (const RunData* r : of_case) values.push_back(r->best_fitness[completed - 1]);
      cs.best_after.push_back({completed, MeanAndSd(values)});
    }
    for (const RunData* r : of_case) cs.tripod_finals += r->best_is_tripod.back() ? 1 : 0;
    s.cases.push_back(cs);
  }

  auto find = [&](ScaffoldCase c) -> const CaseSummary* {
    for (const CaseSummary& cs : s.cases) {
      if (cs.scaffold_case == c) return &cs;
    }
    return nullptr;
  };
  const CaseSummary *free = find(ScaffoldCase::kFree), *time = find(ScaffoldCase::kTime),
                    *performance = find(ScaffoldCase::kPerformance);
  if (free && performance) {
    const std::size_t n = std::min(free->mean_best.size(), performance->mean_best.size());
    int above = 0;
    for (std::size_t g = 0; g < n; ++g) above += performance->mean_best[g] > free->mean_best[g] ? 1 : 0;
    s.case3_over_case1 = static_cast<double>(above) / n;
  }
  if (free && time && free->mean_best.back() != 0.0) {
    s.case2_over_case1 = time->mean_best.back() / free->mean_best.back();
  }
  for (const RunData& r : runs) {
    if (r.best_biped) KeepBest(*r.best_biped, &s.best_biped);
    if (r.best_tripod) KeepBest(*r.best_tripod, &s.best_tripod);
    s.evaluations += r.evaluations;
    s.falls += r.falls;
    s.evaluation_seconds += r.evaluation_seconds;
  }
  if (s.best_biped && s.best_tripod && s.best_tripod->fitness > 0.0) {
    s.biped_over_tripod = s.best_biped->fitness / s.best_tripod->fitness;
  }
  return s;
}

json SummaryToJson(const ReproductionSummary& s) {
  json cases = json::object();
  for (const CaseSummary& c : s.cases) {
    json best = json::array();
    for (const auto& [g, m] : c.best_after) {
      best.push_back({{"generations", g}, {"mean", m.mean}, {"sd", m.sd}, {"replicates", m.n}});
    }
    const ScaffoldSpec& scaffold = ScaffoldSpecOf(c.scaffold_case);
    cases[scaffold.name] = {{"runs", c.runs},
                            {"best_fitness_after", best},
                            {"tripod_finals", c.tripod_finals},
                            {"paper_tripod_finals_of_3", scaffold.paper_tripod_finals}};
  }
  return {{"cases", cases},
          {"case3_over_case1_share", {{"value", Optional(s.case3_over_case1)}, {"paper", kPaperCase3OverCase1}}},
          {"case2_over_case1_final", {{"value", Optional(s.case2_over_case1)}, {"paper", kPaperCase2OverCase1}}},
          {"best_biped", IndividualJson(s.best_biped)},
          {"best_tripod", IndividualJson(s.best_tripod)},
          {"biped_over_tripod", {{"value", Optional(s.biped_over_tripod)}, {"paper", kPaperBipedOverTripod}}},
          {"evaluations", s.evaluations},
          {"fell_share", s.evaluations ? json(static_cast<double>(s.falls) / s.evaluations) : json(nullptr)},
          {"evaluation_seconds", s.evaluation_seconds},
          {"evals_per_s", s.evaluation_seconds > 0 ? json(s.evaluations / s.evaluation_seconds) : json(nullptr)}};
}

std::string SummaryToMarkdown(const ReproductionSummary& s, const std::string& title) {
  std::ostringstream md;
  char buf[256];
  md << "# " << title << "\n\n";
  // one replicate has no spread to show
  bool replicated = false;
  for (const CaseSummary& c : s.cases) replicated = replicated || c.runs > 1;
  md << (replicated ? "## Best fitness (mean ± sd over replicates)" : "## Best fitness (one replicate)")
     << "\n\n| case | runs |";
  std::vector<int> columns;
  for (const CaseSummary& c : s.cases) {
    for (const auto& [g, m] : c.best_after) {
      if (std::find(columns.begin(), columns.end(), g) == columns.end()) columns.push_back(g);
    }
  }
  std::sort(columns.begin(), columns.end());
  for (int g : columns) md << " after " << g << " |";
  md << " final best is a tripod | paper |\n|---|---|";
  for (std::size_t i = 0; i < columns.size(); ++i) md << "---|";
  md << "---|---|\n";
  for (const CaseSummary& c : s.cases) {
    const ScaffoldSpec& scaffold = ScaffoldSpecOf(c.scaffold_case);
    md << "| " << scaffold.number() << ", " << scaffold.label << " | " << c.runs << " |";
    for (int g : columns) {
      const auto it = std::find_if(c.best_after.begin(), c.best_after.end(), [&](const auto& p) { return p.first == g; });
      if (it == c.best_after.end()) {
        md << " — |";
      } else {
        if (it->second.n > 1) {
          std::snprintf(buf, sizeof(buf), " %.2f ± %.2f |", it->second.mean, it->second.sd);
        } else {
          std::snprintf(buf, sizeof(buf), " %.2f |", it->second.mean);
        }
        md << buf;
      }
    }
    md << ' ' << c.tripod_finals << " of " << c.runs << " | " << scaffold.paper_tripod_finals << " of 3 |\n";
  }
  md << "\n## Findings beside the paper's\n\n| finding | ours | paper |\n|---|---|---|\n";
  md << "| generations in which case 3's mean best fitness exceeds case 1's | " << Percent(s.case3_over_case1)
     << " | 83 % |\n";
  md << "| case 2's final mean best fitness as a share of case 1's | " << Percent(s.case2_over_case1) << " | 66 % |\n";
  auto who = [&](const std::optional<EvaluatedSummary>& e) {
    if (!e) return std::string("none");
    std::snprintf(buf, sizeof(buf), "%.2f (%s, %s)", e->fitness, e->run.c_str(), e->id.c_str());
    return std::string(buf);
  };
  md << "| best biped | " << who(s.best_biped) << " | from case 3 |\n";
  md << "| best tripod | " << who(s.best_tripod) << " | from case 2 |\n";
  std::string ratio = "—";
  if (s.biped_over_tripod) {
    std::snprintf(buf, sizeof(buf), "%+.1f %%", 100.0 * (*s.biped_over_tripod - 1.0));
    ratio = buf;
  }
  md << "| best biped's fitness over the best tripod's | " << ratio << " | +37.5 % |\n";
  md << "| evaluations that fell | " << Percent(s.evaluations ? std::optional<double>(double(s.falls) / s.evaluations) : std::nullopt)
     << " | 37–49 % (the authors' runs) |\n";
  std::snprintf(buf, sizeof(buf), "\n%ld evaluations in %.0f s of evaluation time (%.1f per second).\n", s.evaluations,
                s.evaluation_seconds, s.evaluation_seconds > 0 ? s.evaluations / s.evaluation_seconds : 0.0);
  md << buf;
  return md.str();
}

json LearnersToJson(const std::vector<LearnerSummary>& learners) {
  json out = json::object();
  for (const LearnerSummary& l : learners) {
    json cases = json::object();
    for (const CaseSummary& c : l.summary.cases) {
      const MeanSd& final_best = c.best_after.back().second;
      cases[ScaffoldSpecOf(c.scaffold_case).name] = {{"runs", c.runs},
                                                      {"generations", c.best_after.back().first},
                                                      {"final_best_mean", final_best.mean},
                                                      {"final_best_sd", final_best.sd},
                                                      {"tripod_finals", c.tripod_finals}};
    }
    out[l.learner] = {{"cases", cases},
                      {"case3_over_case1_share", Optional(l.summary.case3_over_case1)},
                      {"case2_over_case1_final", Optional(l.summary.case2_over_case1)}};
  }
  return out;
}

std::string LearnersToMarkdown(const std::vector<LearnerSummary>& learners) {
  std::ostringstream md;
  char buf[256];
  md << "## Learners under the scaffolds\n\n"
     << "Final best fitness (mean ± sd over replicates; one replicate: its value) and the runs whose final best is a "
        "tripod.\n\n| learner |";
  for (const ScaffoldSpec& scaffold : Scaffolds()) md << " case " << scaffold.number() << ", " << scaffold.label << " |";
  md << " generations in which case 3's mean best exceeds case 1's | case 2's final mean best over case 1's |\n|---|";
  for (std::size_t i = 0; i < Scaffolds().size(); ++i) md << "---|";
  md << "---|---|\n";
  for (const LearnerSummary& l : learners) {
    md << "| " << LearnerByName(l.learner).label << " (" << l.learner << ") |";
    for (const ScaffoldSpec& scaffold : Scaffolds()) {
      const auto it = std::find_if(l.summary.cases.begin(), l.summary.cases.end(),
                                   [&](const CaseSummary& c) { return c.scaffold_case == scaffold.id; });
      if (it == l.summary.cases.end()) {
        md << " — |";
        continue;
      }
      const MeanSd& m = it->best_after.back().second;
      if (m.n > 1) {
        std::snprintf(buf, sizeof(buf), " %.2f ± %.2f, %d of %d tripods |", m.mean, m.sd, it->tripod_finals, it->runs);
      } else {
        std::snprintf(buf, sizeof(buf), " %.2f, %d of %d tripods |", m.mean, it->tripod_finals, it->runs);
      }
      md << buf;
    }
    md << ' ' << Percent(l.summary.case3_over_case1) << " | " << Percent(l.summary.case2_over_case1) << " |\n";
  }
  return md.str();
}

}  // namespace walkers
