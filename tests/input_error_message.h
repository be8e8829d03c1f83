// The message of the InputError (files/errors.h) a call throws, for tests of
// what bad input is told.
#pragma once

#include <string>

#include "files/errors.h"

namespace walkers::testing {

// The message of the InputError `f` throws, or "" if it throws none.
template <typename F>
std::string InputErrorMessage(const F& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace walkers::testing
