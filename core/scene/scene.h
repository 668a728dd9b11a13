#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "core/engine/engine_config.h"
#include "core/instruments/instruments_config.h"
#include "core/model/cylinder.h"
#include "core/model/fluid.h"
#include "core/sample/sample_config.h"
#include "core/scene/schema.h"

namespace sedem {

// What to write and when.
struct OutputConfig {
  double interval = 10.0;               // s between snapshots (particles, fields, frames)
  bool particles = true;                // particles.pvd series
  bool frames = true;                   // PNG of the column per snapshot
  bool fields = true;                   // fields.pvd: layer density and concentration per snapshot
  std::string figure_formats = "png";   // any of png, svg, pdf, comma-separated
  std::int64_t figure_width_px = 1600;  // a PNG figure's width
  double figure_dpi = 200;              // pixels per inch: the figures' printed size
  bool vector_figures = false;          // former switch: adds svg and pdf
  // Fig. 11: the column at these times (paper: 60, 300, 900 s).
  std::vector<double> fig11_times{60, 300, 900};
  std::int64_t frame_width = 300;
  std::int64_t frame_height = 720;
};

// A scene: everything a run needs, validated, in SI units. Defaults are the paper's.
struct Scene {
  std::string name = "scene";
  Fluid fluid;
  Cylinder cylinder;
  SampleConfig sample;
  ForcesConfig forces;
  IntegratorConfig integrator;
  InstrumentsConfig instruments;
  OutputConfig output;
  double end_time = 60.0;  // s of simulated time
  // s of wall time between the checkpoints written while the run goes on (0: none), so that a
  // kill or a power cut loses at most this much work.
  double checkpoint_interval = 180.0;

  // The table of every key, bound to this scene's fields. The Scene must outlive it and
  // must not move while it is in use.
  Schema schema();
};

}  // namespace sedem
