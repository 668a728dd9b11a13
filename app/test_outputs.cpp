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

nlohmann::json write_test_outputs(const Scene& scene, const TestResults& results,
                                  const HydrometerGeometry& hydrometer, const fs::path& out_dir) {
  for (const auto& t : results.granulometry.tests)
    write_atomically(out_dir / ("readings_" + t.test + ".csv"),
                     [&](std::ostream& out) { write_readings_csv(out, t.dem); });
  write_atomically(out_dir / "granulometry.csv",
                   [&](std::ostream& out) { write_granulometry_csv(out, results.granulometry); });
  if (!results.hydrometer.empty()) {
    render::HydrometerSeriesWriter bulb(out_dir, {hydrometer.heights, hydrometer.radii},
                                        scene.cylinder.height);
    for (const auto& h : results.hydrometer) bulb.write(h.time, h.tip_depth);
  }
  LabelledResults run{scene.name, results, scene.cylinder.height, scene.sample.particle_density};
  write_figures({run}, out_dir / "figures");
  return results_json(results);
}

}  // namespace sedem::app
