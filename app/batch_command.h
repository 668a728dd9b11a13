#pragma once

#include <string>
#include <vector>

namespace sedem::app {

struct BatchOptions {
  std::vector<std::string> scenes;
  std::string sweep;  // key=v1,v2,...: one run per value (of every scene)
  std::string out_dir = "out/batch";
  std::vector<std::string> overrides;
  bool quiet = false;
};

// One run per scene (and per sweep value), each in its own sub-folder of out_dir named after
// the scene file and the swept value. Returns the worst exit status.
int batch(const BatchOptions& options);

// "key=v1,v2,v3" -> {"key=v1", "key=v2", "key=v3"}; throws std::invalid_argument if malformed.
std::vector<std::string> expand_sweep(const std::string& sweep);

}  // namespace sedem::app
