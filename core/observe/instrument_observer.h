#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/fields/layer_fields.h"
#include "core/instruments/granulometry.h"
#include "core/instruments/instrument_panel.h"
#include "core/instruments/test_setup.h"
#include "core/observe/observer.h"

namespace sedem {

// Everything the laboratory tests of a run produced, DEM and reference side by side.
struct TestResults {
  Granulometry granulometry;                     // DEM, reference, true curve, error, bias
  std::vector<HydrometerReading> hydrometer;     // Figs. 13-15, hydrometer.pvd
  std::vector<LargestDiameterProfile> profiles;  // Fig. 12
  std::vector<HydrometerReading> bulb_profiles;  // Fig. 13, at instruments.bulb_profile_times
  std::vector<TestReadings> dem() const;
};

// The enabled tests read from the particles at their times, plus the Fig. 12 profiles at
// instruments.profile_times_min. The reference solution is computed in closed form for the
// same setup, so the run's error and bias come out when the last reading is in.
class InstrumentObserver : public Observer {
 public:
  InstrumentObserver(const TestSetup& setup, const Sample& sample);
  std::string name() const override { return "instruments"; }
  std::vector<double> wanted_times() const override { return times_; }
  void observe(double time, const Particles& particles) override;
  bool accumulates() const override { return true; }
  // Its readings and profiles so far go into the run's checkpoint (instrument_state.h).
  bool keeps_state() const override { return true; }
  void save_state(std::ostream& out) const override;
  void load_state(std::istream& in) override;

  // The readings taken so far against the reference at the same times, with at most
  // `max_profiles` of the profiles, spread evenly over them (spread_indices).
  TestResults results(std::size_t max_profiles = SIZE_MAX) const;
  // Their granulometry alone: no copy of the profiles (thousands of them, 96 kB each at the
  // paper's 4000 layers, for a long instruments.profile_times_min).
  Granulometry granulometry() const;
  const HydrometerGeometry& hydrometer() const { return panel_.hydrometer(); }
  const Suspension& suspension() const { return panel_.suspension(); }

 private:
  TestSetup setup_;
  std::vector<SizeClass> classes_;
  double particle_density_;
  InstrumentPanel panel_;
  std::vector<double> reading_times_, profile_times_, bulb_times_, times_;
  std::vector<TestReadings> reference_;
  std::vector<LargestDiameterProfile> profiles_;
  std::vector<HydrometerReading> bulb_profiles_;
};

}  // namespace sedem
