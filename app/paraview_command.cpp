#include "app/paraview_command.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/exit_codes.h"
// The macro, generated into the build tree from docs/sedem_paraview.py (app/CMakeLists.txt).
#include SEDEM_PARAVIEW_MACRO_HEADER

namespace sedem::app {
namespace fs = std::filesystem;

namespace {

// `name` as the shell would find it on PATH, or "".
std::string on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "";
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    const fs::path candidate = fs::path(dirs.substr(start, end - start)) / name;
    if (end > start && ::access(candidate.c_str(), X_OK) == 0) return candidate.string();
    start = end + 1;
  }
  return "";
}

std::string find_pvpython(const std::string& given) {
  if (!given.empty()) return given;
  if (const char* env = std::getenv("SEDEM_PVPYTHON"); env && *env) return env;
  return on_path("pvpython");
}

}  // namespace

int paraview_state(const ParaviewOptions& options) {
  const fs::path dir = options.run_dir;
  if (!fs::exists(dir / "particles.pvd") && !fs::exists(dir / "fields.pvd")) {
    std::fprintf(stderr,
                 "sedem: %s holds no particles.pvd or fields.pvd (is it a sedem run folder, "
                 "written with output.particles or output.fields?)\n",
                 dir.c_str());
    return exit_code::invalid_scene;
  }
  const std::string pvpython = find_pvpython(options.pvpython);
  if (pvpython.empty() || ::access(pvpython.c_str(), X_OK) != 0) {
    std::fprintf(stderr,
                 "sedem: %s: ParaView's pvpython is needed to write a ParaView state; install "
                 "ParaView (Debian: apt install paraview) or name it with --pvpython PATH or "
                 "SEDEM_PVPYTHON\n",
                 pvpython.empty() ? "no pvpython on PATH" : (pvpython + " cannot be run").c_str());
    return exit_code::usage;
  }
  // The macro goes to a file of its own beside the state while pvpython runs it.
  const fs::path macro = dir / "sedem_paraview.py.tmp";
  const fs::path state = dir / "sedem.pvsm";
  {
    std::ofstream out(macro, std::ios::binary);
    out << kParaviewMacro;
    if (!out.flush()) {
      std::fprintf(stderr, "sedem: cannot write into %s\n", dir.c_str());
      return exit_code::output_unwritable;
    }
  }
  std::vector<std::string> args{pvpython, macro.string(), fs::absolute(dir).string(), "--state",
                                fs::absolute(state).string()};
  if (!options.time.empty()) args.insert(args.end(), {"--time", options.time});
  if (!options.screenshot.empty())
    args.insert(args.end(), {"--screenshot", fs::absolute(options.screenshot).string()});
  std::error_code ec;
  fs::remove(state, ec);
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child == 0) {
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    ::execv(argv[0], argv.data());
    std::perror("sedem: running pvpython");
    ::_exit(127);
  }
  int status = -1;
  if (child > 0)
    while (::waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
  fs::remove(macro, ec);
  if (child < 0 || !WIFEXITED(status) || WEXITSTATUS(status) != 0 || !fs::exists(state)) {
    std::fprintf(stderr, "sedem: %s failed on %s: no state written\n", pvpython.c_str(),
                 dir.c_str());
    return exit_code::io_failure;
  }
  if (!options.quiet) std::printf("sedem: ParaView state %s (File > Load State)\n", state.c_str());
  return exit_code::ok;
}

}  // namespace sedem::app
