#pragma once

#include <optional>
#include <string>

#include "app/lab_input_options.h"

namespace sedem::app {

struct InvertOptions {
  std::string readings;  // CSV: 152H as for `reduce`; sphere time_min, apparent_mass_g;
                         // pipette time_min, dry_mass_g
  std::string run;       // or a sedem run's folder: its readings_<test>.csv, scene and true curve
  bool partial = false;  // accept a run folder that did not complete
  std::string test = "hydrometer";
  std::string scene;  // set-up from a scene file; empty: a laboratory's, from the flags
  std::string out = "invert-out";
  // The laboratory's set-up, when no scene is given (or to override the scene's).
  std::optional<double> specific_gravity;  // Gs, default 2.65
  std::optional<double> dry_mass_g;        // default 50
  std::optional<double> volume_ml;         // suspension volume, default 1000
  std::optional<double> area_cm2;          // cylinder's inside area, default 27.8
  std::optional<double> depth_cm;          // sphere's or pipette's depth; default 0.3 H
  std::optional<double> temperature_c;     // sphere and pipette without a scene; default 20
  std::optional<double> liquid_density;    // kg/m^3 of the clear liquid; default water's
  std::optional<double> blank_g;           // the sphere's apparent mass in the clear liquid
  std::optional<double> pipette_ml;        // the pipette's volume; default 35 or the scene's
  std::string method = "d7928";            // the 152H's standard reduction: d7928 | d422
  // The readings' sheet and the sieve analysis: whole_curve.csv then holds the whole curve.
  LabInputOptions lab;
  double resolution = 0;  // 0: the test's default
  int refine = 2;
  int replicas = 200;
  double coverage = 0.9;
  unsigned long seed = 1;
  bool quiet = false;
};

// `sedem invert READINGS.csv --test T`: the grading curve whose simulated test reproduces
// the readings (docs/invert.md), with its band, the standard reduction beside it, a figure
// and CSVs in --out. With --run DIR instead of READINGS.csv, a simulated run's readings,
// rounded as a laboratory records them, and both curves against the run's true one.
// Returns the exit status: 1 for neither or both inputs, 2 for invalid readings or set-up.
int invert(const InvertOptions& options);

}  // namespace sedem::app
