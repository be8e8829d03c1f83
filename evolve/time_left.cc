#include "evolve/time_left.h"

#include <algorithm>

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

void TimeLeft::Done(const std::string& name, int generation, double now_s) {
  const auto it = runs_.find(name);
  if (it == runs_.end()) return;
  Run& run = it->second;
  run.next = std::clamp(generation + 1, run.next, generations_);
  if (run.paced_from < 0) {
    run.paced_from = run.next;
    run.paced_since = now_s;
  }
  if (first_run_.empty()) {
    first_run_ = name;
    first_done_s_ = now_s;
  }
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

std::optional<double> TimeLeft::Estimate(double now_s) const {
  if (first_run_.empty()) return std::nullopt;
  double done = 0.0, paced = 0.0, left = 0.0;
  for (const auto& [name, run] : runs_) {
    const std::vector<double>& prefix = Prefix(run.kind);
    done += prefix[run.next] - prefix[run.first];
    // the session's first generation marks the start of its pace
    const int from = name == first_run_ && run.paced_from >= 0 ? run.paced_from : run.first;
    paced += prefix[run.next] - prefix[from];
    left += prefix[generations_] - prefix[run.next];
  }
  if (paced > 0.0) return (now_s - first_done_s_) / paced * left;
  // the first generation alone: its time with the starting up
  if (done > 0.0) return now_s / done * left;
  return std::nullopt;
}

std::optional<double> TimeLeft::RunLeft(const std::string& name, double now_s) const {
  const auto it = runs_.find(name);
  if (it == runs_.end() || it->second.paced_from < 0) return std::nullopt;
  const Run& run = it->second;
  const std::vector<double>& prefix = Prefix(run.kind);
  const double done = prefix[run.next] - prefix[run.paced_from];
  if (!(done > 0.0)) return std::nullopt;
  return (now_s - run.paced_since) / done * (prefix[generations_] - prefix[run.next]);
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
