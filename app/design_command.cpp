#include "app/design_command.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>

#include <nlohmann/json.hpp>

#include "app/exit_codes.h"
#include "app/figure_inputs.h"
#include "app/run_folder.h"
#include "core/design/schedule_design.h"
#include "core/run/schedule_confirmation.h"
#include "core/run/stage_setups.h"
#include "core/scene/scene.h"
#include "core/scene/scene_loader.h"
#include "render/plot.h"

namespace sedem::app {

namespace {

namespace fs = std::filesystem;

nlohmann::json schedule_json(const ReadingSchedule& s) {
  nlohmann::json j;
  std::vector<double> minutes;
  for (double t : s.times) minutes.push_back(t / 60);
  j["times_min"] = minutes;
  if (!std::isnan(s.depth_fraction)) j["depth_fraction"] = s.depth_fraction;
  return j;
}

nlohmann::json score_json(const ScheduleScore& s) {
  return {{"worst_error_pp", s.worst_error},
          {"mean_error_pp", s.mean_error},
          {"at_diameter_um", s.worst_diameter * 1e6},
          {"curve_percent_finer", s.worst_curve},
          {"true_percent_finer", s.worst_truth}};
}

void write_csv_rows(std::ofstream& out, const std::string& schedule, const std::string& source,
                    const ScheduleScore& score, const TruthGrid& truth, double depth_fraction) {
  // The hydrometer floats: no depth of its own.
  char depth[32] = "";
  if (!std::isnan(depth_fraction)) std::snprintf(depth, sizeof depth, "%.6g", depth_fraction);
  for (const auto& r : score.readings) {
    char line[256];
    std::snprintf(line, sizeof line, "%s,%s,%.6g,%s,%.9g,%.9g,%.9g\n", schedule.c_str(),
                  source.c_str(), r.time / 60, depth, r.diameter * 1e6, r.percent_finer,
                  truth.percent_at(r.diameter));
    out << line;
  }
}

render::PlotSeries curve_series(const std::string& name, const ScheduleScore& score,
                                render::SeriesStyle style) {
  render::PlotSeries s;
  s.name = name;
  s.style = style;
  auto rows = score.readings;
  std::sort(rows.begin(), rows.end(),
            [](const Reading& a, const Reading& b) { return a.diameter < b.diameter; });
  for (const auto& r : rows) {
    s.x.push_back(r.diameter * 1e6);
    s.y.push_back(r.percent_finer);
  }
  return s;
}

std::string minutes_list(const std::vector<double>& times) {
  std::string s;
  for (double t : times) {
    char b[32];
    std::snprintf(b, sizeof b, "%s%g", s.empty() ? "" : ", ", t / 60);
    s += b;
  }
  return s;
}

int run_design(const DesignCommandOptions& o) {
  Scene scene = load_scene(o.scene, o.overrides);
  DesignOptions options;
  options.test = o.test;
  if (o.readings != -1 && (o.readings < 2 || o.readings > 200))
    throw std::invalid_argument("--readings " + std::to_string(o.readings) + ": allowed 2 to 200");
  options.readings = o.readings == -1 ? 0 : std::size_t(o.readings);
  options.size_count = o.sizes;
  const TestSetup setup = test_setup(scene);
  check_design_options(setup, options);
  if (o.dem_count < -1 || o.dem_count > 100'000'000)
    throw std::invalid_argument("--dem-count " + std::to_string(o.dem_count) +
                                ": allowed 0 (no DEM run) to 100000000");
  const std::string out =
      o.out.empty() ? "out/design/" + safe_folder_name(scene.name + "_" + o.test) : o.out;
  fs::create_directories(out);

  const auto start = std::chrono::steady_clock::now();
  const ScheduleDesign design = design_schedule(setup, sample_setup(scene), options);
  const double search_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::int64_t dem_count = o.dem_count < 0 ? scene.sample.simulated_count : o.dem_count;
  std::optional<ScheduleConfirmation> dem;
  if (dem_count > 0) {
    if (!o.quiet)
      std::fprintf(stderr, "sedem design: confirming with a DEM run of %lld particles\n",
                   static_cast<long long>(dem_count));
    dem = confirm_with_dem(scene, design, dem_count, o.sizes);
  }

  nlohmann::json j;
  j["scene"] = o.scene;
  j["test"] = o.test;
  j["sizes"] = o.sizes;
  j["range_um"] = {design.truth.low * 1e6, design.truth.high * 1e6};
  j["search_seconds"] = search_s;
  j["readings"] = design.designed.times.size();
  for (auto [name, schedule, score] :
       {std::tuple{"standard", &design.standard, &design.standard_score},
        std::tuple{"designed", &design.designed, &design.designed_score},
        std::tuple{"floor", &design.floor, &design.floor_score}}) {
    j[name] = schedule_json(*schedule);
    j[name]["reference"] = score_json(*score);
  }
  if (!design.depth_floor.times.empty()) {
    j["depth_floor"] = schedule_json(design.depth_floor);
    j["depth_floor"]["reference"] = score_json(design.depth_floor_score);
  }
  if (dem) {
    j["dem"] = {{"particles", dem->particles}, {"wall_seconds", dem->wall_seconds}};
    j["standard"]["dem"] = score_json(dem->standard);
    j["designed"]["dem"] = score_json(dem->designed);
  }
  {
    std::ofstream f(fs::path(out) / "design.json");
    f << j.dump(2) << '\n';
    if (!f) return exit_code::io_failure;
  }
  {
    std::ofstream f(fs::path(out) / "design.csv");
    f << "schedule,source,time_min,depth_fraction,diameter_um,percent_finer,true_percent_finer\n";
    write_csv_rows(f, "standard", "reference", design.standard_score, design.truth,
                   design.standard.depth_fraction);
    write_csv_rows(f, "designed", "reference", design.designed_score, design.truth,
                   design.designed.depth_fraction);
    write_csv_rows(f, "floor", "reference", design.floor_score, design.truth,
                   design.floor.depth_fraction);
    if (!design.depth_floor.times.empty())
      write_csv_rows(f, "depth_floor", "reference", design.depth_floor_score, design.truth,
                     design.depth_floor.depth_fraction);
    if (dem) {
      write_csv_rows(f, "standard", "dem", dem->standard, design.truth,
                     design.standard.depth_fraction);
      write_csv_rows(f, "designed", "dem", dem->designed, design.truth,
                     design.designed.depth_fraction);
    }
    if (!f) return exit_code::io_failure;
  }

  render::Plot plot;
  plot.title = scene.name + ", " + o.test + ": the standard schedule and the designed one";
  plot.x = render::axis("diameter", "µm", true);
  plot.y = render::axis("percent finer", "%", 0, 100);
  render::PlotSeries truth("true curve", {}, {}, render::SeriesStyle::line);
  for (std::size_t k = 0; k < design.truth.diameters.size(); ++k) {
    truth.x.push_back(design.truth.diameters[k] * 1e6);
    truth.y.push_back(design.truth.percent[k]);
  }
  plot.series.push_back(truth);
  plot.series.push_back(curve_series("standard schedule", design.standard_score,
                                     render::SeriesStyle::line_and_points));
  plot.series.push_back(curve_series("designed schedule", design.designed_score,
                                     render::SeriesStyle::line_and_points));
  if (dem)
    plot.series.push_back(
        curve_series("designed, DEM", dem->designed, render::SeriesStyle::dashed));
  // design_figure, not design: the figure's own CSV must not replace design.csv.
  render::write_figure(render::single_plot(plot, 760, 480), fs::path(out) / "design_figure",
                       figure_output(scene.output));

  if (!o.quiet) {
    std::printf("%s, %s, over %.2f-%.2f um (searched in %.2f s):\n", scene.name.c_str(),
                o.test.c_str(), design.truth.low * 1e6, design.truth.high * 1e6, search_s);
    auto line = [&](const char* name, const ReadingSchedule& s, const ScheduleScore& ref,
                    const ScheduleScore* d) {
      std::printf("  %-11s worst %6.2f pp at %6.2f um, mean %5.2f pp", name, ref.worst_error,
                  ref.worst_diameter * 1e6, ref.mean_error);
      if (d) std::printf(" (DEM: %.2f, mean %.2f)", d->worst_error, d->mean_error);
      if (!std::isnan(s.depth_fraction)) std::printf(", depth %.2f H", s.depth_fraction);
      if (s.times.size() <= 30)
        std::printf(", at %s min", minutes_list(s.times).c_str());
      else
        std::printf(", %zu readings", s.times.size());
      std::printf("\n");
    };
    line("standard", design.standard, design.standard_score, dem ? &dem->standard : nullptr);
    line("designed", design.designed, design.designed_score, dem ? &dem->designed : nullptr);
    line("floor", design.floor, design.floor_score, nullptr);
    if (!design.depth_floor.times.empty())
      line("depth floor", design.depth_floor, design.depth_floor_score, nullptr);
    std::printf("wrote %s\n", out.c_str());
  }
  return exit_code::ok;
}

}  // namespace

int design(const DesignCommandOptions& options) {
  try {
    return run_design(options);
  } catch (const SceneError& e) {
    std::fprintf(stderr, "sedem: %s\n", e.what());
    return exit_code::invalid_scene;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "sedem design: %s\n", e.what());
    return exit_code::invalid_scene;
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "sedem design: %s\n", e.what());
    return exit_code::engine_failure;
  }
}

}  // namespace sedem::app
