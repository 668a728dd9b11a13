#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "app/figure_inputs.h"
#include "app/output_observers.h"
#include "core/scene/scene.h"

namespace sedem::app {

// What a run's observers leave in its folder when it ends: readings_<test>.csv,
// granulometry.csv, hydrometer.pvd (the bulb at each reading) and the figures (Figs. 11-18,
// PNG + CSV) in figures/. Returns each test's error and bias for run.json. A non-empty
// `partial_note` (outputs of a run that did not complete, redrawn by `sedem render --partial`)
// starts every CSV as a comment ("# partial: ...") and ends every figure's title in
// " (partial)".
nlohmann::json write_test_outputs(const Scene& scene, const RunObservers& observers,
                                  const std::filesystem::path& out_dir,
                                  const std::string& partial_note = "");

// The figure data of a run's observers, labelled with the scene's name.
LabelledResults labelled_results(const Scene& scene, const RunObservers& observers);

// Error and bias of each test, in percentage points, for run.json.
nlohmann::json results_json(const TestResults& results);

}  // namespace sedem::app
