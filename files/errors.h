// The project's one error policy:
// - InputError: a value a user or a file supplied is not allowed (a command
//   line option, a Python argument, a genome, a run's configuration, a
//   checkpoint, a CSV row). Its message names the file or the option, the
//   field and what is allowed ("run/config.json: field 'population' = 1 is
//   outside its allowed range [2, 100000]").
// - std::runtime_error: the world failed the program (a file could not be
//   written, a folder is another process's, an evaluation's MPI rank stopped
//   answering); its message names the file or the folder.
// - WALKERS_CHECK: an invariant of the program itself broke, a bug; it
//   throws std::logic_error naming the file, line and function where.
// An error is thrown once, where it is found, and never caught to be thrown
// again as another type.
#pragma once

#include <stdexcept>
#include <string>

namespace walkers {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws std::logic_error "FILE:LINE (FUNCTION): invariant `CONDITION` broken: MESSAGE".
[[noreturn]] void FailCheck(const char* file, int line, const char* function, const char* condition,
                            const std::string& message);

}  // namespace walkers

// Checks an invariant of the program; `message` (a std::string expression,
// evaluated only on failure) says what broke.
#define WALKERS_CHECK(condition, message)                                     \
  do {                                                                        \
    if (!(condition)) {                                                       \
      ::walkers::FailCheck(__FILE__, __LINE__, __func__, #condition, message); \
    }                                                                         \
  } while (false)
