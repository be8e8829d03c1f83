#include "files/csv.h"

#include <charconv>
#include <cmath>

#include "files/errors.h"

namespace walkers {

std::vector<std::string> SplitCsvLine(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      field += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      out.push_back(field);
      field.clear();
    } else {
      field += c;
    }
  }
  out.push_back(field);
  return out;
}

std::string CsvQuoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

CsvReader::CsvReader(std::string text, std::string path) : text_(std::move(text)), path_(std::move(path)) {
  const std::size_t end = text_.find('\n');
  if (text_.empty() || end == 0) throw InputError(path_ + ": no header line");
  header_ = SplitCsvLine(text_.substr(0, end));
  at_ = end == std::string::npos ? text_.size() : end + 1;
}

int CsvReader::Column(const std::string& name) const {
  for (std::size_t i = 0; i < header_.size(); ++i) {
    if (header_[i] == name) return static_cast<int>(i);
  }
  throw InputError(path_ + ": no column '" + name + "'");
}

bool CsvReader::Next() {
  while (at_ < text_.size()) {
    std::size_t end = text_.find('\n', at_);
    if (end == std::string::npos) end = text_.size();
    const std::string line = text_.substr(at_, end - at_);
    at_ = end + 1;
    ++row_;
    if (line.empty()) continue;
    fields_ = SplitCsvLine(line);
    if (fields_.size() != header_.size()) {
      throw InputError(path_ + ": row " + std::to_string(row_) + " has " + std::to_string(fields_.size()) +
                       " fields, the header " + std::to_string(header_.size()));
    }
    return true;
  }
  return false;
}

void CsvReader::Fail(int column, const std::string& problem) const {
  throw InputError(path_ + ": row " + std::to_string(row_) + ", column '" + header_[column] + "': '" +
                   fields_[column] + "' " + problem);
}

double CsvReader::Number(int column) const {
  const std::string& text = fields_[column];
  double x = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (text.empty() || error != std::errc() || end != text.data() + text.size() || !std::isfinite(x)) {
    Fail(column, "is not a finite number");
  }
  return x;
}

std::int64_t CsvReader::Integer(int column, std::int64_t lo, std::int64_t hi) const {
  const std::string& text = fields_[column];
  std::int64_t x = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (text.empty() || error != std::errc() || end != text.data() + text.size()) Fail(column, "is not an integer");
  if (x < lo || x > hi) {
    Fail(column, "is outside its allowed range [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
  return x;
}

}  // namespace walkers
