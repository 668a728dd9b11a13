#pragma once

#include <string>
#include <vector>

namespace sedem::app {

struct BenchOptions {
  std::string which = "engine";   // engine | accuracy | speedup | scale
  std::vector<std::string> args;  // passed on to the benchmark
};

// `sedem bench`: runs one of the benchmark programs built beside sedem (bench/), with its
// arguments. Returns its exit status.
int bench(const BenchOptions& options);

}  // namespace sedem::app
