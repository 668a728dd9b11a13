#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/observe/instrument_observer.h"
#include "core/scene/scene.h"
#include "render/mass_bands.h"
#include "render/paper_figures.h"

namespace sedem::app {

// One run's test results with what the figures need to label and scale them.
struct LabelledResults {
  std::string label;  // the scene's name: one panel or curve per sample
  TestResults results;
  std::vector<render::ColumnState> columns;  // Fig. 11
  double column_height = 0.457;
  double column_width = 0.0635;
  double particle_density = 2500;
  double simulated_count = 0;      // simulated particles: Fig. 13's band width
  double homogeneous_density = 0;  // kg/m^3, the suspension at t = 0 (Fig. 13)
  render::FigureOutput figures;    // formats and size (output.figure_*)
};

// The figures' formats and size a scene's output keys ask for.
render::FigureOutput figure_output(const OutputConfig& output);

// Labels for runs drawn side by side, from their resolved scenes (run.json's "scene"): each
// scene's name when the names tell the runs apart; otherwise what differs between the scenes,
// as "key=value" (at most three keys, then "+N more"), after the name where names differ in
// part. Runs whose scenes are the same are numbered.
std::vector<std::string> run_labels(const std::vector<nlohmann::json>& scenes);

render::MassBandsFigure fig11_input(const std::vector<LabelledResults>& runs);

// The inputs of Figs. 12-18 from the results of one or more runs (one panel per run).
render::LargestDiameterInput fig12_input(const std::vector<LabelledResults>& runs);
std::vector<render::SampleBulbDensity> fig13_input(const std::vector<LabelledResults>& runs);
std::vector<render::BulbAverageSeries> fig14_input(const std::vector<LabelledResults>& runs);
std::vector<render::HydrometerSeries> fig15_input(const std::vector<LabelledResults>& runs);
std::vector<render::BuoyancySeries> fig16_input(const std::vector<LabelledResults>& runs);
std::vector<render::PipetteSeries> fig17_input(const std::vector<LabelledResults>& runs);
std::vector<render::SampleGrading> fig18_input(const std::vector<LabelledResults>& runs);

// Writes every figure the runs have data for into `dir` (CSV and each format the first run
// asks for); several runs share each figure, one panel (or column of panels) per run.
void write_figures(const std::vector<LabelledResults>& runs, const std::filesystem::path& dir);

}  // namespace sedem::app
