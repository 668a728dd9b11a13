#include "render/mass_bands.h"

#include "core/fields/layer_fields.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "render/atomic_write.h"
#include "render/drawing/figure_files.h"
#include "render/pixel_canvas.h"
#include "render/plot.h"
#include "render/text_fit.h"

namespace sedem::render {
namespace {

constexpr int kTitleHeight = 34;
constexpr int kScaleWidth = 110;       // the grey scale's strip on the right
constexpr double kSeamOverlap = 0.75;  // pixels one band reaches into the next
constexpr PixelCanvas::Rgb kDiscColor = {25, 25, 25};

std::string format(const char* fmt, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, fmt, v);
  return buf;
}

std::string time_label(double t) {
  return format(std::abs(t - std::round(t)) < 1e-9 ? "%.0f s" : "%.1f s", t);
}

unsigned char grey_of(double fraction, double full_scale) {
  const double share = std::clamp(fraction / full_scale, 0.0, 1.0);
  return static_cast<unsigned char>(std::lround(255.0 * (1.0 - share)));
}

struct PanelGeometry {
  double col_x0, col_y0, col_y1, scale;  // column's lower-left corner, top, pixels per metre
  double inset_x0, inset_side;
};

PanelGeometry panel_geometry(const MassBandsFigure& f, double px0, double py0) {
  PanelGeometry g;
  g.col_x0 = px0 + 36;  // the depth axis' labels on the left
  g.col_y0 = py0 + 26;  // its title below
  g.col_y1 = py0 + f.panel_height - 30;
  g.scale = (g.col_y1 - g.col_y0) / f.height;
  const double col_w = f.width * g.scale;
  g.inset_x0 = g.col_x0 + col_w + 26;
  const double gap = 8;
  g.inset_side =
      std::min(px0 + f.panel_width - 42 - g.inset_x0, (g.col_y1 - g.col_y0 - 2 * gap) / 3.0);
  return g;
}

// Depth below the free surface, every 10 cm, on the column's left.
void draw_depth_axis(PixelCanvas& canvas, const MassBandsFigure& f, const PanelGeometry& g) {
  for (int cm = 0; cm <= int(100 * f.height + 1e-9); cm += 10) {
    const double y = g.col_y1 - 0.01 * cm * g.scale;
    canvas.line(g.col_x0 - 4, y, g.col_x0, y);
    canvas.text(std::to_string(cm), g.col_x0 - 15, y, 10, true);
  }
  canvas.text("depth (cm)", g.col_x0 + 0.5 * f.width * g.scale - 6, g.col_y0 - 13, 10, true);
}

void draw_panel(PixelCanvas& canvas, const MassBandsFigure& f, const ColumnSample& sample,
                const ColumnState& state, double full_scale, double px0, double py0) {
  const auto g = panel_geometry(f, px0, py0);
  const double col_w = f.width * g.scale;
  // Within its panel: a run named by several scene keys would run into the next one.
  const auto title =
      fit_text(sample.label + ", t = " + time_label(state.time_s), f.panel_width - 8, 13, 8, true);
  canvas.text(title.text, px0 + 0.5 * f.panel_width, py0 + f.panel_height - 15, title.size, true,
              true);

  const auto& bands = state.band_mass_fraction;
  const double band_h = bands.empty() ? 0 : (g.col_y1 - g.col_y0) / double(bands.size());
  for (std::size_t k = 0; k < bands.size(); ++k) {
    const unsigned char v = grey_of(bands[k], full_scale);
    const double top = g.col_y1 - double(k) * band_h;
    // Each band reaches a little into the next (drawn over it), or anti-aliasing leaves a
    // light seam between two dark bands in every renderer.
    const double bottom = k + 1 < bands.size() ? top - band_h - kSeamOverlap : top - band_h;
    canvas.rectangle(g.col_x0, bottom, g.col_x0 + col_w, top, {v, v, v});
  }
  canvas.frame(g.col_x0, g.col_y0, g.col_x0 + col_w, g.col_y1);
  draw_depth_axis(canvas, f, g);

  const auto& p = state.particles;
  const std::size_t n = std::min({p.x.size(), p.y.size(), p.diameter.size()});
  const double col_h = g.col_y1 - g.col_y0;
  const double side = g.inset_side;
  for (const auto& inset : f.insets) {
    const double fixed = inset.magnification > 0 ? side / (inset.magnification * g.scale) : 0;
    auto w = zoom_window(p, f.height, f.width, inset, fixed);
    // At the paper's magnification a run of a few thousand particles leaves the window all but
    // empty: then it widens until about `grains` show, and the printed magnification says so.
    if (fixed > 0 && w.grains < kFewestZoomGrains) w = zoom_window(p, f.height, f.width, inset);
    const double zoom = side / w.side;  // pixels per metre inside the inset
    double inset_y0 = 0;
    switch (inset.where) {
      case ColumnInset::Where::top:
        inset_y0 = g.col_y1 - side;
        break;
      case ColumnInset::Where::middle:
        inset_y0 = g.col_y0 + 0.5 * (col_h - side);
        break;
      case ColumnInset::Where::bottom:
        inset_y0 = g.col_y0;
        break;
    }
    canvas.rectangle(g.inset_x0, inset_y0, g.inset_x0 + side, inset_y0 + side, {255, 255, 255});
    for (std::size_t i = 0; i < n; ++i) {
      const double r = 0.5 * p.diameter[i];
      const double u = p.x[i] - w.x0, v = p.y[i] - w.y0;
      if (u - r < 0 || v - r < 0 || u + r > w.side || v + r > w.side) continue;  // whole discs
      canvas.disc(g.inset_x0 + u * zoom, inset_y0 + v * zoom,
                  std::max(r * zoom, 0.5 * kMinDiscPixels), kDiscColor);
    }
    canvas.frame(g.inset_x0, inset_y0, g.inset_x0 + side, inset_y0 + side);
    // The zoomed window marked on the column, and a leader to its inset.
    const double mx0 = g.col_x0 + 0.5 * col_w + w.x0 * g.scale;
    const double my0 = g.col_y0 + w.y0 * g.scale;
    const double m = std::max(w.side * g.scale, 3.0);
    canvas.frame(mx0, my0, mx0 + m, my0 + m);
    canvas.line(mx0 + m, my0 + 0.5 * m, g.inset_x0, inset_y0 + 0.5 * side);
    // Beside the inset, not over its grains: the magnification, then the grains it holds.
    const double magnification = side / (w.side * g.scale);
    const double tx = g.inset_x0 + side + 4;
    canvas.text(format("\u00d7%.3g", magnification), tx, inset_y0 + side - 6, 10, false);
    canvas.text(w.grains == 0 ? std::string("no") : std::to_string(w.grains), tx, inset_y0 + 19, 10,
                false);
    canvas.text(w.grains == 1 ? "grain" : "grains", tx, inset_y0 + 7, 10, false);
  }
}

void draw_grey_scale(PixelCanvas& canvas, double x0, double y0, double h, double full_scale) {
  constexpr int steps = 20;
  const double w = 18, step_h = h / steps;
  for (int i = 0; i < steps; ++i) {
    const double fraction = full_scale * (i + 0.5) / steps;
    const unsigned char v = grey_of(fraction, full_scale);
    canvas.rectangle(x0, y0 + i * step_h, x0 + w,
                     y0 + (i + 1) * step_h + (i + 1 < steps ? kSeamOverlap : 0), {v, v, v});
  }
  canvas.frame(x0, y0, x0 + w, y0 + h);
  for (int i = 0; i <= 4; ++i) {
    const double y = y0 + h * i / 4.0;
    canvas.line(x0 + w, y, x0 + w + 4, y);
    // The top is every share from full scale up: say so.
    canvas.text((i == 4 ? "\u2265" : "") + format("%.3g", 100.0 * full_scale * i / 4.0), x0 + w + 7,
                y, 11, false);
  }
  canvas.text("mass share", x0 + 0.5 * w + 20, y0 + h + 30, 12, true, true);
  canvas.text("(% of total)", x0 + 0.5 * w + 20, y0 + h + 14, 11, true);
  canvas.text("zooms: grains", x0 + 0.5 * w + 20, y0 - 20, 10, true);
  canvas.text("at true size,", x0 + 0.5 * w + 20, y0 - 33, 10, true);
  canvas.text(format("\u2265 %.0f px", kMinDiscPixels), x0 + 0.5 * w + 20, y0 - 46, 10, true);
}

std::size_t row_count(const MassBandsFigure& f) {
  std::size_t rows = 0;
  for (const auto& s : f.samples) rows = std::max(rows, s.states.size());
  return rows;
}

}  // namespace

ParticleDiscs discs_of(const Particles& particles) {
  auto narrow = [](const std::vector<double>& v) { return std::vector<float>(v.begin(), v.end()); };
  return {narrow(particles.x), narrow(particles.y), narrow(particles.diameter)};
}

ZoomWindow zoom_window(const ParticleDiscs& p, double height, double width,
                       const ColumnInset& inset, double fixed_side) {
  const int third = inset.where == ColumnInset::Where::top      ? 2
                    : inset.where == ColumnInset::Where::middle ? 1
                                                                : 0;
  const double lo = height * third / 3.0, hi = height * (third + 1) / 3.0;
  const std::size_t n = std::min({p.x.size(), p.y.size(), p.diameter.size()});
  std::vector<double> xs, ys;
  double largest = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (p.y[i] < lo || p.y[i] >= hi || std::abs(p.x[i]) > 0.5 * width) continue;
    xs.push_back(p.x[i]);
    ys.push_back(p.y[i]);
    largest = std::max(largest, double(p.diameter[i]));
  }
  ZoomWindow w;
  const double widest = std::min(width, hi - lo);
  if (xs.empty()) {  // nothing to show: a window of the column's width in the third's middle
    w.side = fixed_side > 0 ? std::min(fixed_side, widest) : widest;
    w.x0 = -0.5 * w.side;
    w.y0 = 0.5 * (lo + hi - w.side);
    return w;
  }
  // As wide as holds about `grains` of the third's grains at their mean spacing there, over
  // the height they fill (twice their interquartile range: the third for a suspension, a
  // few millimetres for a bed).
  auto quantile = [](std::vector<double> v, double q) {
    const auto k = std::ptrdiff_t(q * double(v.size() - 1));
    std::nth_element(v.begin(), v.begin() + k, v.end());
    return v[std::size_t(k)];
  };
  const double filled =
      std::clamp(2.0 * (quantile(ys, 0.75) - quantile(ys, 0.25)), 12.0 * largest, hi - lo);
  const double per_grain = width * filled / double(xs.size());
  w.side = fixed_side > 0 ? std::min(fixed_side, widest)
                          : std::clamp(std::sqrt(std::max(inset.grains, 1) * per_grain),
                                       std::min(12.0 * largest, widest), widest);
  auto median = [](std::vector<double>& v) {
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  w.x0 = std::clamp(median(xs) - 0.5 * w.side, -0.5 * width, 0.5 * width - w.side);
  w.y0 = std::clamp(median(ys) - 0.5 * w.side, lo, hi - w.side);
  for (std::size_t i = 0; i < n; ++i) {
    const double r = 0.5 * p.diameter[i], u = p.x[i] - w.x0, v = p.y[i] - w.y0;
    if (u - r >= 0 && v - r >= 0 && u + r <= w.side && v + r <= w.side) ++w.grains;
  }
  return w;
}

double default_full_scale(const MassBandsFigure& f) {
  std::size_t bands = 0;
  for (const auto& s : f.samples)
    for (const auto& st : s.states) bands = std::max(bands, st.band_mass_fraction.size());
  return bands > 0 ? std::min(1.0, 2.0 / double(bands)) : 1.0;
}

namespace {

// The whole figure on a canvas of `width` x `height` pixels, for a picture or an SVG.
PixelCanvas draw_mass_bands(const MassBandsFigure& f, int& width, int& height) {
  const std::size_t rows = row_count(f);
  if (f.samples.empty() || rows == 0)
    throw std::invalid_argument("a mass-band figure needs a sample with a state");
  const double full_scale =
      f.full_scale_fraction > 0 ? f.full_scale_fraction : default_full_scale(f);
  const int title_h = f.title.empty() ? 0 : kTitleHeight;
  width = int(f.samples.size()) * f.panel_width + kScaleWidth;
  height = int(rows) * f.panel_height + title_h;

  PixelCanvas canvas(width, height, f.title);
  for (std::size_t c = 0; c < f.samples.size(); ++c)
    for (std::size_t r = 0; r < f.samples[c].states.size(); ++r)
      draw_panel(canvas, f, f.samples[c], f.samples[c].states[r], full_scale,
                 double(c) * f.panel_width, double(rows - 1 - r) * f.panel_height);
  const double body_h = double(rows) * f.panel_height;
  draw_grey_scale(canvas, width - kScaleWidth + 16, 0.5 * body_h - 100, 200, full_scale);
  if (title_h > 0) {
    const auto title = fit_text(f.title, width - 16, 18, 8, true);
    canvas.text(title.text, 0.5 * width, height - 0.5 * title_h, title.size, true, true);
  }
  return canvas;
}

}  // namespace

vtkSmartPointer<vtkImageData> render_mass_bands(const MassBandsFigure& f) {
  int width = 0, height = 0;
  return rasterize(draw_mass_bands(f, width, height).drawing());
}

void write_mass_bands_csv(const MassBandsFigure& f, const std::filesystem::path& file,
                          const std::string& note) {
  std::vector<std::string> header;
  std::vector<std::vector<double>> columns;
  for (const auto& s : f.samples) {
    for (const auto& st : s.states) {
      const std::string pre = s.label + " t=" + time_label(st.time_s) + ":";
      const auto& bands = st.band_mass_fraction;
      std::vector<double> depth(bands.size()), percent(bands.size());
      for (std::size_t k = 0; k < bands.size(); ++k) {
        depth[k] = f.height * double(k) / double(bands.size());
        percent[k] = 100.0 * bands[k];
      }
      header.push_back(pre + "band_top_depth_m");
      columns.push_back(std::move(depth));
      header.push_back(pre + "mass_percent");
      columns.push_back(std::move(percent));
    }
  }
  std::size_t rows = 0;
  for (const auto& c : columns) rows = std::max(rows, c.size());
  if (file.has_parent_path()) std::filesystem::create_directories(file.parent_path());
  write_atomically(file, [&](std::ostream& out) {
    if (!note.empty()) out << "# " << note << "\n";
    for (std::size_t j = 0; j < header.size(); ++j) out << (j ? "," : "") << header[j];
    out << "\n";
    for (std::size_t i = 0; i < rows; ++i) {
      for (std::size_t j = 0; j < columns.size(); ++j) {
        if (j) out << ",";
        if (i < columns[j].size()) out << format("%.9g", columns[j][i]);
      }
      out << "\n";
    }
  });
}

std::vector<std::filesystem::path> write_mass_bands(const MassBandsFigure& figure,
                                                    const std::filesystem::path& base,
                                                    const FigureOutput& output) {
  int width = 0, height = 0;
  MassBandsFigure shown = figure;
  if (!output.partial_note.empty()) shown.title += shown.title.empty() ? "(partial)" : " (partial)";
  auto files = write_drawing(draw_mass_bands(shown, width, height).drawing(), base, output);
  auto csv = base;
  csv += ".csv";
  write_mass_bands_csv(figure, csv, output.partial_note);
  files.push_back(csv);
  return files;
}

std::vector<double> band_fractions_from_layers(const std::vector<double>& layer_mass,
                                               int layers_per_band) {
  if (layers_per_band < 1) throw std::invalid_argument("layers_per_band must be at least 1");
  const std::size_t per = std::size_t(layers_per_band);
  std::vector<double> bands((layer_mass.size() + per - 1) / per, 0.0);
  double total = 0;
  for (std::size_t j = 0; j < layer_mass.size(); ++j) {
    bands[j / per] += layer_mass[j];
    total += layer_mass[j];
  }
  if (total > 0)
    for (auto& b : bands) b /= total;
  return bands;
}

std::vector<double> band_fractions_from_particles(const Particles& p, double height, int bands) {
  if (bands < 1) throw std::invalid_argument("bands must be at least 1");
  return band_fractions_from_layers(layer_solid_volume(p, height, std::size_t(bands)), 1);
}

}  // namespace sedem::render
