#pragma once

#include <vector>

#include "core/instruments/granulometry.h"
#include "core/instruments/test_setup.h"
#include "core/model/particles.h"
#include "core/model/sample.h"

namespace sedem {

// The enabled tests of a TestSetup, built from its InstrumentsConfig, reading a field or the
// particles at their times. It never modifies what it reads.
class InstrumentPanel {
 public:
  InstrumentPanel(const TestSetup& setup, const Sample& sample);

  const Suspension& suspension() const { return suspension_; }
  const HydrometerGeometry& hydrometer() const { return hydrometer_; }
  const BuoyancySphere& sphere() const { return sphere_; }
  const Pipette& pipette() const { return pipette_; }
  std::size_t layers() const { return layers_; }

  // Every time at which an enabled test reads, ascending, without repeats, s.
  std::vector<double> reading_times() const;

  // Takes every reading due at `time` from the particles at that time (the engine must
  // stop there). The hydrometer and the sphere read the layer fields of Eq. 20, the
  // pipette its sampling circle.
  void observe(double time, const Particles& particles);
  // The same from a field uniform across the section (the pipette reads it by layers).
  void observe(double time, const LayerFields& fields);

  // Where the hydrometer would float at `time` and what it would read, recorded nowhere: the
  // density along its bulb at times other than its readings (Fig. 13).
  HydrometerReading hydrometer_at(double time, const Particles& particles) const;

  // The tests read so far, enabled ones only, in the order hydrometer, buoyancy, pipette.
  std::vector<TestReadings> readings() const;
  const std::vector<HydrometerReading>& hydrometer_readings() const { return hydrometer_readings_; }
  const std::vector<BuoyancyReading>& buoyancy_readings() const { return buoyancy_readings_; }
  const std::vector<PipetteReading>& pipette_readings() const { return pipette_readings_; }
  // A resumed run's readings so far (InstrumentObserver::load_state): each test's are the
  // first of its reading times, in order, and only an enabled test has any. Throws
  // std::runtime_error naming the test and the time that does not fit.
  void restore(std::vector<HydrometerReading> hydrometer, std::vector<BuoyancyReading> buoyancy,
               std::vector<PipetteReading> pipette);

 private:
  void read_fields(double time, const LayerFields& fields);

  bool hydrometer_on_, buoyancy_on_, pipette_on_;
  std::vector<double> hydrometer_times_, buoyancy_times_, pipette_times_;
  std::size_t layers_;
  Suspension suspension_;
  HydrometerGeometry hydrometer_;
  BuoyancySphere sphere_;
  Pipette pipette_;
  std::vector<HydrometerReading> hydrometer_readings_;
  std::vector<BuoyancyReading> buoyancy_readings_;
  std::vector<PipetteReading> pipette_readings_;
};

}  // namespace sedem
