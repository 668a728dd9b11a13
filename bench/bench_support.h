#pragma once

// What the benchmark programs share: the scene keys that turn files and pictures off, the
// sample scenes of the source tree, and a test's error out of a run's results.

#include <string>
#include <vector>

#include "core/observe/instrument_observer.h"

namespace sedem::bench {

// output.frames, output.particles and output.fields off: a benchmark measures the simulation
// and the tests, not the writing of files.
std::vector<std::string> no_output_keys();

// scenes/sample<k>.toml of the source tree, for each k.
std::vector<std::string> sample_scenes(const std::vector<int>& samples = {1, 2, 3, 4, 5});

// A test's error against the reference solution, percentage points; NaN when the test is off
// or took no reading before the run's end.
double test_error(const TestResults& results, const std::string& test);

}  // namespace sedem::bench
