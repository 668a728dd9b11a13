#pragma once

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

namespace sedem::test {

struct CommandResult {
  int status = -1;
  std::string output;  // stdout and stderr together
};

// Runs a shell command line and returns its exit status and output (stdout and stderr).
inline CommandResult run_command(const std::string& command) {
  CommandResult result;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer;
  std::size_t n;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    result.output.append(buffer.data(), n);
  const int raw = ::pclose(pipe);
  result.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  return result;
}

// Runs the sedem executable with `args` (a shell-quoted string) and returns its exit status
// and output.
inline CommandResult run_sedem(const std::string& args) {
  return run_command(std::string(SEDEM_EXE) + " " + args);
}

// Shell commands that wait (at most 10 s) until process $pid catches SIGTERM, i.e. until a
// run's set-up has begun: a signal counted from the spawn instead came, on a loaded machine,
// before the program had even started, and its default action killed it (exit 143).
inline std::string until_sigterm_caught() {
  return "for i in $(seq 1000); do m=$(awk '/^SigCgt/ {print $2}' /proc/$pid/status "
         "2>/dev/null); [ -n \"$m\" ] && [ $((0x$m & 0x4000)) -ne 0 ] && break; sleep 0.01; "
         "done; ";
}

}  // namespace sedem::test
