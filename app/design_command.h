#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace sedem::app {

struct DesignCommandOptions {
  std::string scene;
  std::string test;
  long readings = -1;  // -1: the standard's count
  std::string out;     // default out/design/<scene name>_<test>
  std::vector<std::string> overrides;
  // Particles of the DEM run that confirms the design: -1 the scene's own count, 0 none.
  std::int64_t dem_count = -1;
  std::int64_t sizes = 1000;  // sizes of the sample the reference and the DEM run cut
  bool quiet = false;
};

// `sedem design SCENE --test T`: the reading schedule with the least worst error against the
// scene's true curve (docs/design.md), beside the standard's and the floor's, from the
// reference solution and confirmed by a DEM run: design.json, design.csv, design.png (+ CSV).
// Returns 0, or 2 (one line) for an invalid scene, test, count or a test the scene disables.
int design(const DesignCommandOptions& options);

}  // namespace sedem::app
