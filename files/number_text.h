// Numbers as text: in files that must read back exactly, and in messages,
// where 0.1 should read "0.1" and not "0.10000000000000001".
#pragma once

#include <charconv>
#include <string>

namespace walkers {

// The shortest decimal text that reads back as exactly x.
inline std::string FormatExact(double x) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), x);
  return std::string(buffer, result.ptr);
}

}  // namespace walkers
