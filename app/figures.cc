#include "app/figures.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace walkers::app {

std::string PythonInterpreter() {
  if (const char* python = std::getenv("WALKERS_PYTHON")) return python;
  if (::access("/usr/bin/python3", X_OK) == 0) return "/usr/bin/python3";
  return "python3";
}

namespace {

// Runs $ENV_NAME, else the repository's scripts/NAME, on DIR; its exit status.
int RunScript(const char* env_name, const char* name, const std::string& dir) {
  const std::string script = std::getenv(env_name) ? std::getenv(env_name)
                                                   : std::string(WALKERS_SOURCE_DIR "/scripts/") + name;
  // what this process printed goes first; no shell: the directory's name is passed as it is
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    const std::string python = PythonInterpreter();
    ::execlp(python.c_str(), python.c_str(), script.c_str(), dir.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  if (::waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

int DrawFigures(const std::string& dir) { return RunScript("WALKERS_FIGURES_SCRIPT", "figures.py", dir); }

int WriteClaims(const std::string& dir) { return RunScript("WALKERS_CLAIMS_SCRIPT", "claims.py", dir); }

}  // namespace walkers::app
