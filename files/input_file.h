// Reading the project's input files strictly (genomes, run configurations,
// checkpoints): a key given twice is refused where nlohmann's parser would
// keep the last one silently, nesting is bounded, and every message names the
// file, the field and, for a number, its allowed range in the shortest form
// that reads back exactly. Every such problem is an InputError
// (files/errors.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "files/errors.h"

namespace walkers {

// The whole file. Throws InputError "PATH: cannot open (reason)".
std::string ReadFile(const std::string& path);

// Objects and arrays nest at most this deep (the project's files need four).
constexpr int kMaxJsonDepth = 16;

// Parses `text`; `source` names it in messages. Throws InputError for text
// that is not JSON, a key repeated within one object, a number too large for
// a double and nesting deeper than kMaxJsonDepth.
nlohmann::json ParseJson(const std::string& text, const std::string& source);
nlohmann::json LoadJsonFile(const std::string& path);

// Throws InputError "unknown WHAT 'NAME': allowed values are A, B, C".
[[noreturn]] void FailUnknownName(const std::string& what, const std::string& name,
                                  const std::vector<std::string>& allowed);

// The keys of a JSON object, in its order: what JsonFields::RequireOnly allows
// when a file's fields are those its writer writes.
std::vector<std::string> KeysOf(const nlohmann::json& object);

// A field's name in messages: "SOURCE: FIELD", or FIELD when there is no
// source (a value given in code, on the command line or from Python).
inline std::string FieldOf(const std::string& source, const std::string& field) {
  return source.empty() ? field : source + ": " + field;
}

// A closed interval [lo, hi], or (lo, hi] when open_below.
struct NumberRange {
  double lo = 0, hi = 0;
  bool open_below = false;

  bool Contains(double x) const { return (open_below ? x > lo : x >= lo) && x <= hi; }
  std::string ToString() const;  // "[0, 800]", "(0, 1000]"
};

// Throws InputError "NAME = VALUE is outside its allowed range [LO, HI]"
// unless the value is within it; NAME says where the value came from
// (FieldOf("run/config.json", "population"), "ensemble").
// `why`, when given, follows the range (" for the learner sade").
void RequireInRange(const std::string& name, std::int64_t value, std::int64_t lo, std::int64_t hi,
                    const std::string& why = "");
void RequireInRange(const std::string& name, double value, const NumberRange& range);

// The fields of one JSON object, each read with its presence, type and range
// checked. Messages read "SOURCE: NOUN 'WHEREkey' ...", e.g.
// "run/checkpoint.json: field 'archive[2].fitness' must be a number, got "x"".
class JsonFields {
 public:
  // Throws InputError if `object` is not a JSON object. `where` prefixes the
  // keys in messages; `noun` says what a field is ("field", "gene").
  JsonFields(const nlohmann::json& object, std::string source, std::string where = "", std::string noun = "field");

  // Refuses a key that is not one of `known`.
  void RequireOnly(const std::vector<std::string>& known) const;

  const nlohmann::json& Get(const std::string& key) const;  // present
  double Number(const std::string& key, const NumberRange& range) const;  // finite, in range
  double Number(const std::string& key) const;                            // finite
  std::int64_t Integer(const std::string& key, std::int64_t lo, std::int64_t hi) const;
  std::uint64_t Unsigned(const std::string& key, std::uint64_t hi) const;  // a non-negative integer
  bool Bool(const std::string& key) const;
  std::string String(const std::string& key) const;
  // one of `allowed`
  std::string OneOf(const std::string& key, const std::vector<std::string>& allowed) const;
  JsonFields Object(const std::string& key) const;
  const nlohmann::json& Array(const std::string& key) const;

  const std::string& source() const { return source_; }
  // "WHEREkey", the field's name in messages
  std::string Name(const std::string& key) const { return where_ + key; }
  // Throws InputError "SOURCE: NOUN 'WHEREkey' PROBLEM".
  [[noreturn]] void Fail(const std::string& key, const std::string& problem) const;

 private:
  const nlohmann::json& object_;
  std::string source_, where_, noun_;
};

}  // namespace walkers
