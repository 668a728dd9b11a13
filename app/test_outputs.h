#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "core/instruments/hydrometer.h"
#include "core/observe/instrument_observer.h"
#include "core/scene/scene.h"

namespace sedem::app {

// What a run's laboratory tests leave in its folder: readings_<test>.csv, granulometry.csv,
// hydrometer.pvd (the bulb at each reading) and the figures (Figs. 12-18, PNG + CSV) in
// figures/. Returns each test's error and bias for run.json.
nlohmann::json write_test_outputs(const Scene& scene, const TestResults& results,
                                  const HydrometerGeometry& hydrometer,
                                  const std::filesystem::path& out_dir);

// Error and bias of each test, in percentage points, for run.json.
nlohmann::json results_json(const TestResults& results);

}  // namespace sedem::app
