#pragma once

// What makes a run's results doubtful though every value is in its range: too few simulated
// particles in an instrument's sampled volume, a suspension beyond one-way coupling or too
// dilute to read, a percent finer outside 0-100 % by more than the sampling noise, an error
// larger than the span the test reads. Before a run (from its set-up) and after it (from its
// results); the scene check refuses what cannot mean anything, run.json lists the rest.

#include <string>
#include <vector>

#include "core/instruments/granulometry.h"
#include "core/instruments/test_setup.h"

namespace sedem {

// One doubt: a short stable code ("few_particles", ...) and a sentence for the user.
struct Doubt {
  std::string code;
  std::string message;
};

// The share of the section an enabled instrument samples at the start, and the simulated
// particles expected in it (the suspension being uniform then): the hydrometer's bulb and the
// sphere read the layers they span across the whole width, the pipette its circle.
struct SampledVolume {
  std::string test;  // "hydrometer" | "buoyancy" | "pipette"
  std::string key;   // the scene key that sizes it
  double share = 0;
  double particles = 0;
};
std::vector<SampledVolume> sampled_volumes(const TestSetup& setup, double particle_count);

// Below this many particles expected in its volume an instrument's reading means nothing (the
// scene check refuses it); below kDoubtfulSampled its sampling noise (about 1/sqrt(n)) is
// above 18 % of the reading (a warning).
inline constexpr double kMinSampled = 1;
inline constexpr double kDoubtfulSampled = 30;

// The paper's limits of one-way coupling (the grains do not stir the water): 1.6 % solids by
// volume, 4 % by mass, which its own 60 g in the ASTM cylinder reach; beyond them by more than
// kCouplingTolerance (relative) the hindrance the model leaves out grows.
inline constexpr double kOneWayVolumeFraction = 0.016;
inline constexpr double kOneWayMassFraction = 0.04;
inline constexpr double kCouplingTolerance = 0.05;
// Below this concentration (kg/m^3 = g/L) a 152H reading (graduated in 1 g/L) resolves the
// grading curve no better than 20 %.
inline constexpr double kDiluteConcentration = 5;

// Solids by volume and by mass of the suspension at the start.
double solids_volume_fraction(const TestSetup& setup);
double solids_mass_fraction(const TestSetup& setup);

// Doubts known before a run: few particles in a volume, coupling, dilution.
std::vector<Doubt> setup_doubts(const TestSetup& setup, double particle_count);

// Doubts on a run's results (its DEM readings against the reference); setup_doubts' are not
// repeated.
std::vector<Doubt> result_doubts(const Granulometry& granulometry, const TestSetup& setup,
                                 double particle_count);

}  // namespace sedem
