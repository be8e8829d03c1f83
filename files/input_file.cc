#include "files/input_file.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include "files/number_text.h"

namespace walkers {
namespace {

using nlohmann::json;

// nlohmann's message without its "[json.exception.parse_error.101] " tag
std::string LibraryDetail(const json::exception& e) {
  const std::string what = e.what();
  const std::size_t tag_end = what.find("] ");
  return tag_end == std::string::npos ? what : what.substr(tag_end + 2);
}

// a value as a message shows it: its JSON, cut short if long
std::string Shown(const json& value) {
  constexpr std::size_t kMax = 40;
  const std::string text = value.dump();
  return text.size() <= kMax ? text : text.substr(0, kMax) + "...";
}

}  // namespace

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open (" + std::strerror(errno) + ")");
  std::ostringstream out;
  out << in.rdbuf();
  if (in.bad()) throw InputError(path + ": reading failed");
  return out.str();
}

json ParseJson(const std::string& text, const std::string& source) {
  // the keys seen in each open object or array (an array's set stays empty)
  std::vector<std::set<std::string>> open;
  std::string last_key;
  const json::parser_callback_t check = [&](int depth, json::parse_event_t event, json& parsed) {
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        if (depth >= kMaxJsonDepth) {
          throw InputError(source + ": nested more than " + std::to_string(kMaxJsonDepth) + " levels deep");
        }
        open.emplace_back();
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        open.pop_back();
        break;
      case json::parse_event_t::key:
        last_key = parsed.get<std::string>();
        if (!open.back().insert(last_key).second) {
          throw InputError(source + ": key '" + last_key + "' appears twice in one object");
        }
        break;
      case json::parse_event_t::value:
        break;
    }
    return true;
  };
  try {
    return json::parse(text, check);
  } catch (const json::out_of_range& e) {  // a number beyond a double's range
    throw InputError(source + ": " + (last_key.empty() ? std::string("a value") : "'" + last_key + "'") +
                     " is not a finite number (" + LibraryDetail(e) + ")");
  } catch (const json::exception& e) {
    throw InputError(source + ": not valid JSON (" + LibraryDetail(e) + ")");
  }
}

json LoadJsonFile(const std::string& path) { return ParseJson(ReadFile(path), path); }

void FailUnknownName(const std::string& what, const std::string& name, const std::vector<std::string>& allowed) {
  std::string list;
  for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
  throw InputError("unknown " + what + " '" + name + "': allowed values are " + list);
}

std::vector<std::string> KeysOf(const json& object) {
  std::vector<std::string> keys;
  for (const auto& item : object.items()) keys.push_back(item.key());
  return keys;
}

std::string NumberRange::ToString() const {
  return (open_below ? "(" : "[") + FormatExact(lo) + ", " + FormatExact(hi) + "]";
}

void RequireInRange(const std::string& name, std::int64_t value, std::int64_t lo, std::int64_t hi,
                    const std::string& why) {
  if (value < lo || value > hi) {
    throw InputError(name + " = " + std::to_string(value) + " is outside its allowed range [" + std::to_string(lo) +
                     ", " + std::to_string(hi) + "]" + why);
  }
}

void RequireInRange(const std::string& name, double value, const NumberRange& range) {
  if (!range.Contains(value)) {
    throw InputError(name + " = " + FormatExact(value) + " is outside its allowed range " + range.ToString());
  }
}

JsonFields::JsonFields(const json& object, std::string source, std::string where, std::string noun)
    : object_(object), source_(std::move(source)), where_(std::move(where)), noun_(std::move(noun)) {
  if (!object_.is_object()) {
    const std::string what = where_.empty() ? "the file" : "'" + where_.substr(0, where_.size() - 1) + "'";
    throw InputError(source_ + ": " + what + " must be a JSON object, got " + Shown(object_));
  }
}

void JsonFields::Fail(const std::string& key, const std::string& problem) const {
  throw InputError(source_ + ": " + noun_ + " '" + Name(key) + "' " + problem);
}

void JsonFields::RequireOnly(const std::vector<std::string>& known) const {
  for (const auto& item : object_.items()) {
    bool found = false;
    for (const std::string& k : known) found = found || item.key() == k;
    if (!found) throw InputError(source_ + ": unknown " + noun_ + " '" + Name(item.key()) + "'");
  }
}

const json& JsonFields::Get(const std::string& key) const {
  const auto it = object_.find(key);
  if (it == object_.end()) throw InputError(source_ + ": missing " + noun_ + " '" + Name(key) + "'");
  return *it;
}

double JsonFields::Number(const std::string& key) const {
  const json& value = Get(key);
  if (!value.is_number()) Fail(key, "must be a number, got " + Shown(value));
  const double x = value.get<double>();
  if (!std::isfinite(x)) Fail(key, "is not finite");
  return x;
}

double JsonFields::Number(const std::string& key, const NumberRange& range) const {
  const double x = Number(key);
  if (!range.Contains(x)) Fail(key, "= " + FormatExact(x) + " is outside its allowed range " + range.ToString());
  return x;
}

std::int64_t JsonFields::Integer(const std::string& key, std::int64_t lo, std::int64_t hi) const {
  const json& value = Get(key);
  if (!value.is_number_integer()) Fail(key, "must be an integer, got " + Shown(value));
  const bool beyond_int64 = value.is_number_unsigned() &&
                            value.get<std::uint64_t>() > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max());
  const std::int64_t x = beyond_int64 ? 0 : value.get<std::int64_t>();
  if (beyond_int64 || x < lo || x > hi) {
    Fail(key, "= " + value.dump() + " is outside its allowed range [" + std::to_string(lo) + ", " +
                  std::to_string(hi) + "]");
  }
  return x;
}

std::uint64_t JsonFields::Unsigned(const std::string& key, std::uint64_t hi) const {
  const json& value = Get(key);
  if (!value.is_number_integer()) Fail(key, "must be a non-negative integer, got " + Shown(value));
  if (!value.is_number_unsigned() || value.get<std::uint64_t>() > hi) {
    Fail(key, "= " + value.dump() + " is outside its allowed range [0, " + std::to_string(hi) + "]");
  }
  return value.get<std::uint64_t>();
}

bool JsonFields::Bool(const std::string& key) const {
  const json& value = Get(key);
  if (!value.is_boolean()) Fail(key, "must be true or false, got " + Shown(value));
  return value.get<bool>();
}

std::string JsonFields::String(const std::string& key) const {
  const json& value = Get(key);
  if (!value.is_string()) Fail(key, "must be a string, got " + Shown(value));
  return value.get<std::string>();
}

std::string JsonFields::OneOf(const std::string& key, const std::vector<std::string>& allowed) const {
  const std::string s = String(key);
  std::string list;
  for (const std::string& a : allowed) {
    if (s == a) return s;
    list += (list.empty() ? "" : ", ") + a;
  }
  Fail(key, "= " + Shown(json(s)) + " is not one of " + list);
}

JsonFields JsonFields::Object(const std::string& key) const {
  return JsonFields(Get(key), source_, Name(key) + ".", noun_);
}

const json& JsonFields::Array(const std::string& key) const {
  const json& value = Get(key);
  if (!value.is_array()) Fail(key, "must be an array, got " + Shown(value));
  return value;
}

}  // namespace walkers
