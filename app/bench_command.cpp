#include "app/bench_command.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include "app/exit_codes.h"

namespace sedem::app {

int bench(const BenchOptions& options) {
  namespace fs = std::filesystem;
  // The benchmarks are built next to the application: build/app/sedem, build/bench/...
  const fs::path self = fs::read_symlink("/proc/self/exe");
  const fs::path program =
      self.parent_path().parent_path() / "bench" / ("sedem_bench_" + options.which);
  if (!fs::exists(program)) {
    std::fprintf(stderr, "sedem: no benchmark program %s (build the project first)\n",
                 program.c_str());
    return exit_code::usage;
  }
  std::vector<std::string> args{program.string()};
  args.insert(args.end(), options.args.begin(), options.args.end());
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  std::fflush(stdout);
  ::execv(program.c_str(), argv.data());
  std::fprintf(stderr, "sedem: cannot start %s: %s\n", program.c_str(), std::strerror(errno));
  return exit_code::usage;
}

}  // namespace sedem::app
