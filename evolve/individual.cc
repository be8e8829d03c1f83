#include "evolve/individual.h"

#include <algorithm>
#include <charconv>

namespace walkers {
namespace {

constexpr const char* kClamped = " clamped";
constexpr const char* kRedrawn = " redrawn";

// "g/c" as a parent; nothing for other text
std::optional<Lineage::Parent> ParentOf(const std::string& id) {
  Lineage::Parent p;
  const char* end = id.data() + id.size();
  const auto [slash, e1] = std::from_chars(id.data(), end, p.generation);
  if (e1 != std::errc() || slash == end || *slash != '/') return std::nullopt;
  const auto [last, e2] = std::from_chars(slash + 1, end, p.child);
  if (e2 != std::errc() || last != end) return std::nullopt;
  return p;
}

}  // namespace

std::string Lineage::Text() const {
  std::string text = learner;
  for (std::size_t i = 0; i < parents.size(); ++i) {
    text += (i > 0 ? "+" : "") + std::to_string(parents[i].generation) + "/" + std::to_string(parents[i].child);
  }
  for (Admission a : admissions) text += a == Admission::kClamped ? kClamped : kRedrawn;
  return text;
}

std::optional<Lineage> Lineage::FromText(const std::string& text) {
  Lineage lineage;
  // the origin up to the first space, then what admitting it did
  const std::size_t space = std::min(text.find(' '), text.size());
  const std::string origin = text.substr(0, space);
  for (std::size_t at = space; at < text.size();) {
    if (text.compare(at, 8, kClamped) == 0) {
      lineage.admissions.push_back(Admission::kClamped);
    } else if (text.compare(at, 8, kRedrawn) == 0) {
      lineage.admissions.push_back(Admission::kRedrawn);
    } else {
      return std::nullopt;
    }
    at += 8;
  }
  // parents "g/c" joined by '+', or a learner's name
  if (!origin.empty() && origin.find_first_not_of("0123456789/+") == std::string::npos) {
    for (std::size_t begin = 0; begin <= origin.size();) {
      const std::size_t end = std::min(origin.find('+', begin), origin.size());
      const std::optional<Parent> parent = ParentOf(origin.substr(begin, end - begin));
      if (!parent) return std::nullopt;
      lineage.parents.push_back(*parent);
      begin = end + 1;
    }
  } else {
    lineage.learner = origin;
  }
  // what reads back as other text ("01/2") is not a lineage's
  if (lineage.Text() != text) return std::nullopt;
  return lineage;
}

bool Fitter(const Individual& a, const Individual& b) {
  if (a.fitness() != b.fitness()) return a.fitness() > b.fitness();
  if (a.generation != b.generation) return a.generation < b.generation;
  return a.child < b.child;
}

void Archive::Merge(const std::vector<Individual>& children) {
  members_.insert(members_.end(), children.begin(), children.end());
  std::stable_sort(members_.begin(), members_.end(), Fitter);
  if (static_cast<int>(members_.size()) > capacity_) members_.resize(capacity_);
}

double Archive::AverageOfBest(int n) const {
  const int count = std::min<int>(n, members_.size());
  if (count == 0) return 0.0;
  double sum = 0.0;
  for (int i = 0; i < count; ++i) sum += members_[i].fitness();
  return sum / count;
}

double Archive::Mean() const { return AverageOfBest(static_cast<int>(members_.size())); }

}  // namespace walkers
