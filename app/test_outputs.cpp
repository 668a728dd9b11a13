#include "app/test_outputs.h"

#include <cmath>
#include <fstream>
#include <stdexcept>

#include "app/figure_inputs.h"
#include "core/instruments/readings_csv.h"
#include "render/atomic_write.h"
#include "render/hydrometer_writer.h"

namespace sedem::app {
namespace fs = std::filesystem;

namespace {

// A figure that cannot be computed (a reading that is no number) is null, with a note: never
// NaN counted as perfect, never "inf" in run.json.
nlohmann::json figure(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

}  // namespace

nlohmann::json results_json(const TestResults& results) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& t : results.granulometry.tests) {
    nlohmann::json r = {{"error_pp", figure(t.error)},
                        {"bias_pp", figure(t.bias)},
                        {"readings", t.dem.rows.size()}};
    if (t.dem.rows.empty())
      r["note"] = "no readings: the run ended before the test's first reading time";
    else if (!std::isfinite(t.error) || !std::isfinite(t.bias))
      r["note"] = "cannot be computed: a reading of the test or of its reference is not a number";
    if (t.test == "hydrometer") {
      std::size_t off = 0;
      for (const auto& h : results.hydrometer) off += h.on_scale ? 0 : 1;
      r["off_scale_readings"] = off;
    }
    j[t.test] = r;
  }
  return j;
}

LabelledResults labelled_results(const Scene& scene, const RunObservers& observers) {
  LabelledResults run;
  run.label = scene.name;
  run.column_height = scene.cylinder.height;
  run.column_width = scene.cylinder.diameter;
  run.particle_density = scene.sample.particle_density;
  run.simulated_count = double(scene.sample.simulated_count);
  run.figures = figure_output(scene.output);
  if (observers.instruments) {
    // Fig. 12's profiles only: a long instruments.profile_times_min holds thousands.
    run.results = observers.instruments->results(render::kFig12MaxPanels);
    const Suspension& s = observers.instruments->suspension();
    run.homogeneous_density =
        s.fluid.density + s.initial_concentration * (1 - s.fluid.density / s.particle_density);
  }
  if (observers.columns) run.columns = observers.columns->states();
  return run;
}

nlohmann::json write_test_outputs(const Scene& scene, const RunObservers& observers,
                                  const fs::path& out_dir, const std::string& partial_note) {
  // Held in the vector the figures take, not copied into it: a run's profiles can be hundreds
  // of MB.
  std::vector<LabelledResults> runs;
  runs.push_back(labelled_results(scene, observers));
  LabelledResults& run = runs.front();
  run.figures.partial_note = partial_note;
  const TestResults& results = run.results;
  const auto note = [&](std::ostream& out) {
    if (!partial_note.empty()) out << "# " << partial_note << '\n';
  };
  for (const auto& t : results.granulometry.tests)
    write_atomically(out_dir / ("readings_" + t.test + ".csv"), [&](std::ostream& out) {
      note(out);
      write_readings_csv(out, t.dem);
    });
  if (observers.instruments) {
    write_atomically(out_dir / "granulometry.csv", [&](std::ostream& out) {
      note(out);
      write_granulometry_csv(out, results.granulometry);
    });
  }
  if (!results.hydrometer.empty()) {
    const auto& h = observers.instruments->hydrometer();
    render::HydrometerSeriesWriter bulb(out_dir, {h.heights, h.radii}, scene.cylinder.height);
    for (const auto& r : results.hydrometer) bulb.write(r.time, r.tip_depth);
  }
  write_figures(runs, out_dir / "figures");
  return results_json(results);
}

}  // namespace sedem::app
