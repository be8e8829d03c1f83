#include "app/statistics.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace walkers::app {

std::string PythonInterpreter() {
  if (const char* python = std::getenv("WALKERS_PYTHON")) return python;
  if (::access("/usr/bin/python3", X_OK) == 0) return "/usr/bin/python3";
  return "python3";
}

int RunStatistics(const std::vector<std::string>& arguments) {
  const std::string package = std::getenv("WALKERS_STATS") ? std::getenv("WALKERS_STATS")
                                                            : std::string(WALKERS_SOURCE_DIR "/scripts/walkers_stats");
  const std::string python = PythonInterpreter();
  // no shell: a folder's name is passed as it is
  std::vector<char*> argv = {const_cast<char*>(python.c_str()), const_cast<char*>(package.c_str())};
  for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  // what this process printed goes first
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    ::execvp(python.c_str(), argv.data());
    ::_exit(127);
  }
  int status = 0;
  if (::waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace walkers::app
