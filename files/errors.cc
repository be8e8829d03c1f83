#include "files/errors.h"

namespace walkers {

void FailCheck(const char* file, int line, const char* function, const char* condition, const std::string& message) {
  throw std::logic_error(std::string(file) + ":" + std::to_string(line) + " (" + function + "): invariant `" +
                         condition + "` broken: " + message);
}

}  // namespace walkers
