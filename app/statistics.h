// Running the statistics package (scripts/walkers_stats/) on a reproduction:
// its summary with the claims' verdicts, its figures, and the check of a
// checkout of the authors' repository.
#pragma once

#include <string>
#include <vector>

namespace walkers::app {

// The interpreter: $WALKERS_PYTHON, else /usr/bin/python3 (Debian's, which has
// matplotlib and SciPy), else python3 on the PATH.
std::string PythonInterpreter();

// Runs the package ($WALKERS_STATS, else the repository's
// scripts/walkers_stats) with `arguments`, e.g. {"summary", DIR}; returns its
// exit status (0 on success).
int RunStatistics(const std::vector<std::string>& arguments);

}  // namespace walkers::app
