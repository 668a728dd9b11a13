#include "app/figure_inputs.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <stdexcept>

namespace sedem::app {
namespace {

// A point some of whose values are no finite number (a reading that cannot be computed) is
// left out of a figure and of its CSV: no NaN or inf is drawn or written.
bool finite(std::initializer_list<double> values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

const TestComparison* find_test(const TestResults& r, const std::string& test) {
  for (const auto& t : r.granulometry.tests)
    if (t.test == test && !t.dem.rows.empty()) return &t;
  return nullptr;
}

std::size_t column(const TestReadings& t, const std::string& name) {
  auto it = std::find(t.extra_columns.begin(), t.extra_columns.end(), name);
  if (it == t.extra_columns.end())
    throw std::logic_error(t.test + " readings have no column " + name);
  return std::size_t(it - t.extra_columns.begin());
}

render::GradingCurve curve(const std::string& name, const TestReadings& t) {
  render::GradingCurve c{name, {}, {}};
  for (const auto& row : t.rows) {
    if (!finite({row.diameter, row.percent_finer})) continue;
    c.diameter_m.push_back(row.diameter);
    c.percent_finer.push_back(row.percent_finer);
  }
  return c;
}

// A scene value as a reader would write it: 3000, 0.3, true, equal_mass, [0.5, 1].
std::string short_value(const nlohmann::json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_float()) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v.get<double>());
    return buf;
  }
  if (v.is_array()) {
    std::string out = "[";
    for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + short_value(v[i]);
    return out + "]";
  }
  return v.dump();
}

}  // namespace

std::vector<std::string> run_labels(const std::vector<nlohmann::json>& scenes) {
  std::vector<std::string> names;
  for (const auto& s : scenes)
    names.push_back(s.is_object() && s.contains("name") ? short_value(s.at("name")) : "run");
  const std::set<std::string> distinct(names.begin(), names.end());
  if (distinct.size() == names.size()) return names;
  // Every key that some scene has with another value (or not at all), in key order.
  std::set<std::string> keys;
  for (const auto& s : scenes)
    if (s.is_object())
      for (const auto& item : s.items()) keys.insert(item.key());
  std::vector<std::string> differing;
  for (const auto& key : keys) {
    if (key == "name") continue;
    const auto value = [&](const nlohmann::json& s) {
      return s.is_object() && s.contains(key) ? s.at(key) : nlohmann::json();
    };
    for (const auto& s : scenes)
      if (value(s) != value(scenes.front())) {
        differing.push_back(key);
        break;
      }
  }
  constexpr std::size_t kShown = 3;
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    std::string label = distinct.size() > 1 ? names[i] : "";
    for (std::size_t k = 0; k < differing.size() && k < kShown; ++k) {
      const auto& s = scenes[i];
      const auto& key = differing[k];
      label += (label.empty() ? "" : ", ") + key + "=" +
               (s.is_object() && s.contains(key) ? short_value(s.at(key)) : "unset");
    }
    if (differing.size() > kShown)
      label += ", +" + std::to_string(differing.size() - kShown) + " more";
    if (differing.empty()) label = names[i] + " (run " + std::to_string(i + 1) + ")";
    labels.push_back(label);
  }
  return labels;
}

render::MassBandsFigure fig11_input(const std::vector<LabelledResults>& runs) {
  render::MassBandsFigure fig;
  fig.title = "Column: mass share per band of 100 layers, with zooms";
  for (const auto& run : runs) {
    if (run.columns.empty()) continue;
    fig.samples.push_back({run.label, run.columns});
    fig.height = run.column_height;
    fig.width = run.column_width;
  }
  return fig;
}

render::LargestDiameterInput fig12_input(const std::vector<LabelledResults>& runs) {
  render::LargestDiameterInput in;
  for (const auto& run : runs) {
    render::SampleDiameterProfiles s{run.label, {}};
    for (const auto& p : run.results.profiles) s.profiles.push_back({p.time, p.depth, p.largest});
    if (!s.profiles.empty()) in.samples.push_back(std::move(s));
    in.column_height_m = run.column_height;
    in.particle_density = run.particle_density;
  }
  return in;
}

std::vector<render::SampleBulbDensity> fig13_input(const std::vector<LabelledResults>& runs) {
  std::vector<render::SampleBulbDensity> out;
  for (const auto& run : runs) {
    render::SampleBulbDensity s{
        run.label, {}, run.simulated_count, run.column_height, run.homogeneous_density};
    for (const auto& h : run.results.bulb_profiles)
      s.profiles.push_back({h.time, h.profile_offset, h.profile_density});
    if (!s.profiles.empty()) out.push_back(std::move(s));
  }
  return out;
}

std::vector<render::BulbAverageSeries> fig14_input(const std::vector<LabelledResults>& runs) {
  std::vector<render::BulbAverageSeries> out;
  for (const auto& run : runs) {
    render::BulbAverageSeries s{run.label, {}, {}, {}};
    for (const auto& h : run.results.hydrometer) {
      if (!finite({h.time, h.bulb_mean_density, h.density_eq19})) continue;
      s.time_s.push_back(h.time);
      s.simulated_kg_m3.push_back(h.bulb_mean_density);
      s.eq19_kg_m3.push_back(h.density_eq19);
    }
    if (!s.time_s.empty()) out.push_back(std::move(s));
  }
  return out;
}

std::vector<render::HydrometerSeries> fig15_input(const std::vector<LabelledResults>& runs) {
  std::vector<render::HydrometerSeries> out;
  for (const auto& run : runs) {
    render::HydrometerSeries s{run.label, {}, {}, {}, {}};
    for (const auto& h : run.results.hydrometer) {
      if (!finite({h.time, h.centre_depth, h.diameter, h.percent_finer})) continue;
      s.time_s.push_back(h.time);
      s.centre_depth_m.push_back(h.centre_depth);
      s.diameter_m.push_back(h.diameter);
      s.percent_finer.push_back(h.percent_finer);
    }
    if (!s.time_s.empty()) out.push_back(std::move(s));
  }
  return out;
}

std::vector<render::BuoyancySeries> fig16_input(const std::vector<LabelledResults>& runs) {
  std::vector<render::BuoyancySeries> out;
  for (const auto& run : runs) {
    const auto* t = find_test(run.results, "buoyancy");
    if (!t) continue;
    const std::size_t mass = column(t->dem, "apparent_mass_kg");
    render::BuoyancySeries s{run.label, {}, {}, {}, {}};
    for (const auto& row : t->dem.rows) {
      if (!finite({row.time, row.extra[mass], row.diameter, row.percent_finer})) continue;
      s.time_s.push_back(row.time);
      s.apparent_mass_kg.push_back(row.extra[mass]);
      s.diameter_m.push_back(row.diameter);
      s.percent_finer.push_back(row.percent_finer);
    }
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<render::PipetteSeries> fig17_input(const std::vector<LabelledResults>& runs) {
  std::vector<render::PipetteSeries> out;
  for (const auto& run : runs) {
    const auto* t = find_test(run.results, "pipette");
    if (!t) continue;
    render::PipetteSeries s{run.label, {}, {}, {}};
    for (const auto& row : t->dem.rows) {
      if (!finite({row.time, row.diameter, row.percent_finer})) continue;
      s.time_s.push_back(row.time);
      s.diameter_m.push_back(row.diameter);
      s.percent_finer.push_back(row.percent_finer);
    }
    out.push_back(std::move(s));
  }
  return out;
}

std::vector<render::SampleGrading> fig18_input(const std::vector<LabelledResults>& runs) {
  std::vector<render::SampleGrading> out;
  for (const auto& run : runs) {
    render::SampleGrading s;
    s.sample = run.label;
    s.truth.name = "true";
    for (const auto& p : run.results.granulometry.true_curve) {
      s.truth.diameter_m.push_back(p.diameter);
      s.truth.percent_finer.push_back(p.percent_finer);
    }
    for (const auto& t : run.results.granulometry.tests) {
      if (t.dem.rows.empty()) continue;
      s.tests.push_back(curve(t.test, t.dem));
      s.references.push_back(curve(t.test + " (reference)", t.reference));
    }
    out.push_back(std::move(s));
  }
  return out;
}

render::FigureOutput figure_output(const OutputConfig& output) {
  render::FigureOutput f;
  f.formats = render::parse_figure_formats(output.figure_formats);
  if (output.vector_figures)
    for (auto format : {render::FigureFormat::svg, render::FigureFormat::pdf})
      if (std::find(f.formats.begin(), f.formats.end(), format) == f.formats.end())
        f.formats.push_back(format);
  f.width_px = int(output.figure_width_px);
  f.dpi = output.figure_dpi;
  return f;
}

void write_figures(const std::vector<LabelledResults>& runs, const std::filesystem::path& dir) {
  if (runs.empty()) return;
  render::FigureOutput svg = runs.front().figures;
  // One run drawn from a partial one makes the figure partial.
  for (const auto& r : runs)
    if (!r.figures.partial_note.empty()) svg.partial_note = r.figures.partial_note;
  if (auto in = fig11_input(runs); !in.samples.empty())
    render::write_mass_bands(in, dir / "fig11_column", svg);
  if (auto in = fig12_input(runs); !in.samples.empty()) render::write_fig12(in, dir, svg);
  if (auto in = fig13_input(runs); !in.empty()) render::write_fig13(in, dir, svg);
  if (auto in = fig14_input(runs); !in.empty()) render::write_fig14(in, dir, svg);
  if (auto in = fig15_input(runs); !in.empty()) render::write_fig15(in, dir, svg);
  if (auto in = fig16_input(runs); !in.empty()) render::write_fig16(in, dir, svg);
  if (auto in = fig17_input(runs); !in.empty()) render::write_fig17(in, dir, svg);
  if (auto in = fig18_input(runs); !in.empty()) render::write_fig18(in, dir, svg);
}

}  // namespace sedem::app
