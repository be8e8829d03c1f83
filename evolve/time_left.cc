#include "evolve/time_left.h"

#include <algorithm>
#include <cmath>

#include "files/csv.h"
#include "files/errors.h"
#include "files/input_file.h"

namespace walkers {

TimeLeft::TimeLeft(int generations) : generations_(generations) {}

void TimeLeft::AddFinished(const std::string& kind, const std::vector<double>& costs) {
  if (static_cast<int>(costs.size()) != generations_) return;
  finished_[kind].push_back(costs);
  prefix_.clear();
}

void TimeLeft::AddRun(const std::string& name, const std::string& kind, int completed) {
  completed = std::clamp(completed, 0, generations_);
  runs_[name] = Run{kind, completed, completed};
}

void TimeLeft::Done(const std::string& name, int generation) {
  const auto it = runs_.find(name);
  if (it != runs_.end()) it->second.next = std::clamp(generation + 1, it->second.next, generations_);
}

const std::vector<double>& TimeLeft::Prefix(const std::string& kind) const {
  // a kind without finished runs takes every finished run's mean ("")
  const std::string key = finished_.count(kind) ? kind : "";
  if (const auto it = prefix_.find(key); it != prefix_.end()) return it->second;
  std::vector<const std::vector<double>*> runs;
  for (const auto& [k, lists] : finished_) {
    if (key.empty() || k == key) {
      for (const auto& costs : lists) runs.push_back(&costs);
    }
  }
  std::vector<double> prefix(generations_ + 1, 0.0);
  for (int g = 0; g < generations_; ++g) {
    double cost = 1.0;  // no finished run at all: every generation alike
    if (!runs.empty()) {
      cost = 0.0;
      for (const auto* costs : runs) cost += (*costs)[g];
      cost /= static_cast<double>(runs.size());
    }
    prefix[g + 1] = prefix[g] + cost;
  }
  return prefix_[key] = std::move(prefix);
}

std::optional<double> TimeLeft::Estimate(double elapsed_s) const {
  double done = 0.0, left = 0.0;
  for (const auto& [name, run] : runs_) {
    const std::vector<double>& prefix = Prefix(run.kind);
    done += prefix[run.next] - prefix[run.first];
    left += prefix[generations_] - prefix[run.next];
  }
  if (!(done > 0.0)) return std::nullopt;
  return elapsed_s / done * left;
}

std::vector<double> GenerationCosts(const std::string& generations_csv) {
  try {
    CsvReader csv(ReadFile(generations_csv), generations_csv);
    const int rate = csv.Column("evals_per_s");
    std::vector<double> costs;
    while (csv.Next()) {
      const double evals_per_s = csv.Number(rate);
      if (!(evals_per_s > 0.0)) return {};
      costs.push_back(1.0 / evals_per_s);
    }
    return costs;
  } catch (const InputError&) {
    return {};
  }
}

}  // namespace walkers
