#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <vtkImageData.h>
#include <vtkSmartPointer.h>

#include "core/model/particles.h"
#include "render/drawing/figure_files.h"

namespace sedem::render {

// Fig. 11 of the paper: the column as grey bands of mass (grey = the band's share of the
// total mass, white = none) beside a depth axis, with zoom insets that draw the particles as
// discs at true scale (at least kMinDiscPixels across, so that the finest still show). One
// panel per time (rows), several samples side by side (columns).

// Particle centres and diameters in the section (m; x across, axis at 0; y up, bottom at 0).
// Single precision: a disc is placed to 0.03 um, far below a pixel of the insets, and Fig. 11
// keeps one copy for each of its times (at ten million particles, 240 MB each in double).
struct ParticleDiscs {
  std::vector<float> x, y, diameter;
};
ParticleDiscs discs_of(const Particles& particles);

// The column at one time.
struct ColumnState {
  double time_s = 0;
  // Share of the total mass in each band, bands counted from the free surface down
  // (the paper's layers grouped by 100: 4000 layers give 40 bands). Fractions of 1.
  std::vector<double> band_mass_fraction;
  ParticleDiscs particles;  // what the insets show; may be empty
};

struct ColumnSample {
  std::string label;                // e.g. "sample 1"
  std::vector<ColumnState> states;  // one panel each, top to bottom
};

// A zoom window on one third of the column (top, middle or bottom), drawn beside it. It is
// placed on the grains there (centred on their median position). With a `magnification`
// (against the column's own scale in the picture, as the paper gives its zooms: 25x) it is
// that much enlarged, unless that window would hold fewer than kFewestZoomGrains (a run of
// far fewer particles than the paper's); otherwise it is sized to hold about `grains` of
// them, between 12 largest diameters and the column's width. Its magnification and the grains it
// holds are printed beside it. With no grain in its third it says so.
struct ColumnInset {
  enum class Where { top, middle, bottom } where;
  double magnification = 0;  // 0: from `grains`
  int grains = 40;
};

// A zoom window in the section (m): lower-left corner, side, and the whole discs inside.
struct ZoomWindow {
  double x0 = 0, y0 = 0, side = 0;
  std::size_t grains = 0;
};
// `side` (m), when positive, fixes the window's side instead of `inset.grains`.
ZoomWindow zoom_window(const ParticleDiscs& particles, double height, double width,
                       const ColumnInset& inset, double side = 0);

// A zoom at a fixed magnification that would hold fewer grains than this is widened instead.
inline constexpr std::size_t kFewestZoomGrains = 5;

// Discs smaller than this many pixels across are drawn this size, so that the finest show;
// every larger one at its true size.
inline constexpr double kMinDiscPixels = 1.0;

struct MassBandsFigure {
  std::string title;
  double height = 0.457;  // m, the column H
  double width = 0.0635;  // m, the section B
  std::vector<ColumnSample> samples;
  // The paper's zooms at 900 s: 25x on the top and middle, 62.5x on the bed.
  std::vector<ColumnInset> insets = {{ColumnInset::Where::top, 25},
                                     {ColumnInset::Where::middle, 25},
                                     {ColumnInset::Where::bottom, 62.5}};
  int panel_width = 270;  // pixels
  int panel_height = 380;
  // Share of the total mass drawn black; larger shares are black too, and the scale's top
  // reads "≥". 0: twice the share of a band in the homogeneous suspension (2 / bands), so
  // the suspension shows mid-grey whatever the bed holds.
  double full_scale_fraction = 0;
};

// The share drawn black when the figure sets none.
double default_full_scale(const MassBandsFigure& figure);

vtkSmartPointer<vtkImageData> render_mass_bands(const MassBandsFigure& figure);

// CSV: per sample and time, "<sample> t=<time> s:band_top_depth_m" and
// "<sample> t=<time> s:mass_percent".
// `note`, when given, is written first as a comment ("# partial: ...").
void write_mass_bands_csv(const MassBandsFigure& figure, const std::filesystem::path& file,
                          const std::string& note = "");

// Writes `<base>.<format>` for each of `output`'s formats and `<base>.csv`; returns the files.
std::vector<std::filesystem::path> write_mass_bands(const MassBandsFigure& figure,
                                                    const std::filesystem::path& base,
                                                    const FigureOutput& output = {});

// Groups per-layer masses (from the free surface down) into bands of `layers_per_band`
// layers (the last band takes the remainder) and divides by the total mass.
std::vector<double> band_fractions_from_layers(const std::vector<double>& layer_mass,
                                               int layers_per_band = 100);

// The same from particles directly: mass of particle i taken as weight_i * diameter_i^3
// (one density), bands of equal height from the free surface at y = height down.
std::vector<double> band_fractions_from_particles(const Particles& particles, double height,
                                                  int bands);

}  // namespace sedem::render
