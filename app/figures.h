// Running the figure script (scripts/figures.py) on a reproduction directory.
#pragma once

#include <string>

namespace walkers::app {

// The interpreter: $WALKERS_PYTHON, else /usr/bin/python3 (Debian's, which has
// matplotlib), else python3 on the PATH.
std::string PythonInterpreter();

// Runs the script on DIR; returns its exit status (0 on success).
int DrawFigures(const std::string& dir);

}  // namespace walkers::app
