// Running the analysis scripts on a reproduction directory: the claims
// (scripts/claims.py) and the figures (scripts/figures.py).
#pragma once

#include <string>

namespace walkers::app {

// The interpreter: $WALKERS_PYTHON, else /usr/bin/python3 (Debian's, which has
// matplotlib), else python3 on the PATH.
std::string PythonInterpreter();

// Runs the figure script ($WALKERS_FIGURES_SCRIPT, else scripts/figures.py) on
// DIR; returns its exit status (0 on success).
int DrawFigures(const std::string& dir);

// Runs the claims script ($WALKERS_CLAIMS_SCRIPT, else scripts/claims.py) on
// DIR: the paper's claims tested, into summary.json and summary.md; returns its
// exit status (0 on success).
int WriteClaims(const std::string& dir);

}  // namespace walkers::app
