#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "core/instruments/granulometry.h"
#include "core/model/fluid.h"
#include "render/plot.h"

namespace sedem::render {

// The paper's Figs. 12-18 as recipes: plain inputs in SI units (filled from the fields and
// the instruments' results), a Figure out (plots in user-facing units: µm, cm, g, s).
// write_figNN(input, dir, output) writes dir/<name>.<format> for each of output's formats
// (PNG, SVG, PDF) and dir/<name>.csv; docs/figures.md lists
// the CSV columns.

// Fig. 12: the largest diameter still above each depth (from the particles) against the
// limiting diameter of Eq. 16, one panel per time.
struct DiameterProfile {
  double time_s = 0;
  std::vector<double> depth_m;             // below the free surface
  std::vector<double> largest_diameter_m;  // of the particles above that depth
};
struct SampleDiameterProfiles {
  std::string sample;
  std::vector<DiameterProfile> profiles;  // one per time
};
struct LargestDiameterInput {
  std::vector<SampleDiameterProfiles> samples;
  double column_height_m = 0.457;
  double particle_density = 2500.0;  // kg/m^3, for Eq. 16
  Fluid fluid;
};
// One panel per time, at most kFig12MaxPanels: of more times (instruments.profile_times_min
// can list thousands), that many spread evenly over them, the first and the last among them.
inline constexpr std::size_t kFig12MaxPanels = 12;
Figure fig12_largest_diameter(const LargestDiameterInput& input);

// Fig. 13: suspension density along the hydrometer's bulb, one panel per sample, one curve
// per time on a dark-to-light ramp. The raw layers (thousands, most holding no simulated
// grain at the counts people run) are averaged over bands along the bulb whose width follows
// from the particle count: about kFig13GrainsPerBand simulated grains per band in the
// homogeneous suspension, between 2 and 40 bands, the width printed on the x axis. The
// sampling spread of each band's mean (its standard error over the band's layers) is drawn
// as a translucent band around the curve. The homogeneous suspension at t = 0 is drawn as a
// black dashed line.
struct BulbDensityProfile {
  double time_s = 0;
  std::vector<double> position_m;  // along the bulb, 0 at its top, 0.14 at its tip
  std::vector<double> density_kg_m3;
};
struct SampleBulbDensity {
  std::string sample;
  std::vector<BulbDensityProfile> profiles;
  double simulated_count = 0;      // simulated particles in the column; 0: 40 bands
  double column_height_m = 0.457;  // to know how many of them the bulb spans
  double homogeneous_kg_m3 = 0;    // the suspension at t = 0; 0: not drawn
};
inline constexpr double kFig13GrainsPerBand = 25;
// The number of bands Fig. 13 averages a sample over.
int fig13_band_count(const SampleBulbDensity& sample);
Figure fig13_bulb_density(const std::vector<SampleBulbDensity>& samples);

// Fig. 14: the density averaged along the bulb (from the layers) against Eq. 19 (from the
// hydrometer's depth), over time; one panel per sample.
struct BulbAverageSeries {
  std::string sample;
  std::vector<double> time_s;
  std::vector<double> simulated_kg_m3;  // average of the layers along the bulb
  std::vector<double> eq19_kg_m3;       // r_s rho_f of Eq. 19
};
Figure fig14_bulb_average(const std::vector<BulbAverageSeries>& samples);

// Figs. 15-17: where every sample's curve is the same (the limiting diameter at a fixed depth
// depends on time alone), a panel draws one black curve named kAllSamples and says so in its
// title ("..., all samples").
inline constexpr const char* kAllSamples = "all samples";

// Fig. 15: the hydrometer's readings against time, one curve per sample.
struct HydrometerSeries {
  std::string sample;
  std::vector<double> time_s;
  std::vector<double> centre_depth_m;  // y_go, the bulb's centre below the free surface
  std::vector<double> diameter_m;      // phi_o, Eq. 16
  std::vector<double> percent_finer;   // w_o, Eq. 18
};
Figure fig15_hydrometer(const std::vector<HydrometerSeries>& samples);

// Fig. 16: the buoyancy sphere's readings against time.
struct BuoyancySeries {
  std::string sample;
  std::vector<double> time_s;
  std::vector<double> apparent_mass_kg;  // m_sp
  std::vector<double> diameter_m;
  std::vector<double> percent_finer;  // Eq. 22
};
Figure fig16_buoyancy(const std::vector<BuoyancySeries>& samples);

// Fig. 17: the pipette's readings against time.
struct PipetteSeries {
  std::string sample;
  std::vector<double> time_s;
  std::vector<double> diameter_m;
  std::vector<double> percent_finer;  // Eq. 17
};
Figure fig17_pipette(const std::vector<PipetteSeries>& samples);

// Fig. 18: each test's grading curve against the true one, one panel per sample. A test's
// reference curve (the same instrument applied to the continuum solution) is drawn dashed
// in the test's colour.
struct GradingCurve {
  std::string name;  // "true", "hydrometer", ...
  std::vector<double> diameter_m;
  std::vector<double> percent_finer;
};
struct SampleGrading {
  std::string sample;
  GradingCurve truth;
  std::vector<GradingCurve> tests;       // from the simulation
  std::vector<GradingCurve> references;  // same order as `tests`; may be empty
};
Figure fig18_granulometry(const std::vector<SampleGrading>& samples);

// File names (without extension) used by the writers below.
inline constexpr const char* kFig12Name = "fig12_largest_diameter";
inline constexpr const char* kFig13Name = "fig13_bulb_density";
inline constexpr const char* kFig14Name = "fig14_bulb_average";
inline constexpr const char* kFig15Name = "fig15_hydrometer";
inline constexpr const char* kFig16Name = "fig16_buoyancy";
inline constexpr const char* kFig17Name = "fig17_pipette";
inline constexpr const char* kFig18Name = "fig18_granulometry";

void write_fig12(const LargestDiameterInput& input, const std::filesystem::path& dir,
                 const FigureOutput& output = {});
void write_fig13(const std::vector<SampleBulbDensity>& input, const std::filesystem::path& dir,
                 const FigureOutput& output = {});
void write_fig14(const std::vector<BulbAverageSeries>& input, const std::filesystem::path& dir,
                 const FigureOutput& output = {});
void write_fig15(const std::vector<HydrometerSeries>& input, const std::filesystem::path& dir,
                 const FigureOutput& output = {});
void write_fig16(const std::vector<BuoyancySeries>& input, const std::filesystem::path& dir,
                 const FigureOutput& output = {});
void write_fig17(const std::vector<PipetteSeries>& input, const std::filesystem::path& dir,
                 const FigureOutput& output = {});
void write_fig18(const std::vector<SampleGrading>& input, const std::filesystem::path& dir,
                 const FigureOutput& output = {});

}  // namespace sedem::render
