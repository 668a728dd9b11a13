#include "app/batch_command.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "app/exit_codes.h"
#include "app/run_command.h"
#include "app/stop_signals.h"

namespace sedem::app {

std::vector<std::string> expand_sweep(const std::string& sweep) {
  const auto eq = sweep.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == sweep.size())
    throw std::invalid_argument("--sweep " + sweep + ": expected key=v1,v2,...");
  const std::string key = sweep.substr(0, eq);
  std::vector<std::string> sets;
  std::size_t start = eq + 1;
  while (start <= sweep.size()) {
    auto comma = sweep.find(',', start);
    if (comma == std::string::npos) comma = sweep.size();
    const std::string value = sweep.substr(start, comma - start);
    if (value.empty()) throw std::invalid_argument("--sweep " + sweep + ": an empty value");
    sets.push_back(key + "=" + value);
    start = comma + 1;
  }
  return sets;
}

int batch(const BatchOptions& options) {
  std::vector<std::string> variants{""};
  if (!options.sweep.empty()) {
    try {
      variants = expand_sweep(options.sweep);
    } catch (const std::invalid_argument& e) {
      std::fprintf(stderr, "sedem: %s\n", e.what());
      return exit_code::usage;
    }
  }
  int worst = exit_code::ok;
  for (const auto& scene : options.scenes) {
    for (const auto& variant : variants) {
      RunOptions run_options;
      run_options.scene = scene;
      run_options.quiet = options.quiet;
      run_options.overrides = options.overrides;
      std::string folder = std::filesystem::path(scene).stem().string();
      if (!variant.empty()) {
        run_options.overrides.push_back(variant);
        folder += "__" + variant;
      }
      run_options.out_dir = (std::filesystem::path(options.out_dir) / folder).string();
      const int status = run(run_options);
      if (status != exit_code::ok) worst = status;
      if (stop_requested()) return exit_code::interrupted;
    }
  }
  return worst;
}

}  // namespace sedem::app
