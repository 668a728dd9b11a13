#include "app/test_outputs.h"

#include <fstream>
#include <stdexcept>

#include "app/figure_inputs.h"
#include "core/instruments/readings_csv.h"
#include "render/hydrometer_writer.h"

namespace sedem::app {
namespace fs = std::filesystem;

namespace {

// Writes through a temporary file renamed into place: a reader never sees half a file.
template <class Write>
void write_atomically(const fs::path& file, Write&& write) {
  auto tmp = file;
  tmp += ".tmp";
  {
    std::ofstream out(tmp);
    write(out);
    out.flush();
    if (!out) throw std::runtime_error("cannot write " + tmp.string());
  }
  fs::rename(tmp, file);
}

}  // namespace

nlohmann::json results_json(const TestResults& results) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& t : results.granulometry.tests)
    j[t.test] = {{"error_pp", t.error}, {"bias_pp", t.bias}, {"readings", t.dem.rows.size()}};
  return j;
}

LabelledResults labelled_results(const Scene& scene, const RunObservers& observers) {
  LabelledResults run;
  run.label = scene.name;
  run.column_height = scene.cylinder.height;
  run.column_width = scene.cylinder.diameter;
  run.particle_density = scene.sample.particle_density;
  run.simulated_count = double(scene.sample.simulated_count);
  run.vector_figures = scene.output.vector_figures;
  if (observers.instruments) {
    run.results = observers.instruments->results();
    const Suspension& s = observers.instruments->suspension();
    run.homogeneous_density =
        s.fluid.density + s.initial_concentration * (1 - s.fluid.density / s.particle_density);
  }
  if (observers.columns) run.columns = observers.columns->states();
  return run;
}

nlohmann::json write_test_outputs(const Scene& scene, const RunObservers& observers,
                                  const fs::path& out_dir) {
  const LabelledResults run = labelled_results(scene, observers);
  const TestResults& results = run.results;
  for (const auto& t : results.granulometry.tests)
    write_atomically(out_dir / ("readings_" + t.test + ".csv"),
                     [&](std::ostream& out) { write_readings_csv(out, t.dem); });
  if (observers.instruments) {
    write_atomically(out_dir / "granulometry.csv",
                     [&](std::ostream& out) { write_granulometry_csv(out, results.granulometry); });
  }
  if (!results.hydrometer.empty()) {
    const auto& h = observers.instruments->hydrometer();
    render::HydrometerSeriesWriter bulb(out_dir, {h.heights, h.radii}, scene.cylinder.height);
    for (const auto& r : results.hydrometer) bulb.write(r.time, r.tip_depth);
  }
  write_figures({run}, out_dir / "figures");
  return results_json(results);
}

}  // namespace sedem::app
