#include "core/instruments/instrument_panel.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace sedem {

namespace {

bool due(const std::vector<double>& times, double t) {
  return std::any_of(times.begin(), times.end(), [t](double s) {
    return std::abs(s - t) <= 1e-9 * std::max(1.0, std::abs(s));
  });
}

// Readings restored for one test: its first reading times, in order.
template <class Reading>
void check_restored(const std::vector<Reading>& readings, bool on, const std::vector<double>& times,
                    const char* test) {
  if (readings.empty()) return;
  if (!on) throw std::runtime_error(std::string("readings of the ") + test + ", which is off");
  if (readings.size() > times.size())
    throw std::runtime_error(std::to_string(readings.size()) + " readings of the " + test +
                             ", which reads " + std::to_string(times.size()) + " times");
  for (std::size_t k = 0; k < readings.size(); ++k)
    if (!due({times[k]}, readings[k].time))
      throw std::runtime_error(std::string("a reading of the ") + test + " at " +
                               std::to_string(readings[k].time) + " s, where it reads at " +
                               std::to_string(times[k]) + " s");
}

}  // namespace

void InstrumentPanel::restore(std::vector<HydrometerReading> hydrometer,
                              std::vector<BuoyancyReading> buoyancy,
                              std::vector<PipetteReading> pipette) {
  check_restored(hydrometer, hydrometer_on_, hydrometer_times_, "hydrometer");
  check_restored(buoyancy, buoyancy_on_, buoyancy_times_, "buoyancy sphere");
  check_restored(pipette, pipette_on_, pipette_times_, "pipette");
  hydrometer_readings_ = std::move(hydrometer);
  buoyancy_readings_ = std::move(buoyancy);
  pipette_readings_ = std::move(pipette);
}

InstrumentPanel::InstrumentPanel(const TestSetup& setup, const Sample& sample)
    : hydrometer_on_(setup.instruments.hydrometer),
      buoyancy_on_(setup.instruments.buoyancy),
      pipette_on_(setup.instruments.pipette),
      hydrometer_times_(setup.instruments.hydrometer_times),
      buoyancy_times_(setup.instruments.buoyancy_times),
      pipette_times_(setup.instruments.pipette_times),
      layers_(static_cast<std::size_t>(setup.instruments.layers)) {
  const auto& cfg = setup.instruments;
  suspension_.fluid = setup.fluid;
  suspension_.cylinder = setup.cylinder;
  suspension_.particle_density = sample.particle_density;
  suspension_.initial_concentration = sample.section_mass / setup.cylinder.section_volume();
  HydrometerDesign design;
  design.tip_length = cfg.hydrometer_tip_length;
  design.shoulder_length = cfg.hydrometer_shoulder_length;
  hydrometer_ = make_hydrometer(design);
  sphere_.diameter = cfg.sphere_diameter;
  sphere_.mass = cfg.sphere_mass;
  sphere_.centre_depth = cfg.buoyancy_depth_fraction * setup.cylinder.height;
  pipette_.volume = cfg.pipette_volume;
  pipette_.depth = cfg.pipette_depth_fraction * setup.cylinder.height;
}

std::vector<double> InstrumentPanel::reading_times() const {
  std::vector<double> t;
  if (hydrometer_on_) t.insert(t.end(), hydrometer_times_.begin(), hydrometer_times_.end());
  if (buoyancy_on_) t.insert(t.end(), buoyancy_times_.begin(), buoyancy_times_.end());
  if (pipette_on_) t.insert(t.end(), pipette_times_.begin(), pipette_times_.end());
  std::sort(t.begin(), t.end());
  t.erase(std::unique(t.begin(), t.end()), t.end());
  return t;
}

void InstrumentPanel::read_fields(double time, const LayerFields& fields) {
  if (hydrometer_on_ && due(hydrometer_times_, time))
    hydrometer_readings_.push_back(read_hydrometer(hydrometer_, fields, time, suspension_));
  if (buoyancy_on_ && due(buoyancy_times_, time))
    buoyancy_readings_.push_back(read_buoyancy(sphere_, fields, time, suspension_));
}

void InstrumentPanel::observe(double time, const Particles& particles) {
  const bool fields_due = (hydrometer_on_ && due(hydrometer_times_, time)) ||
                          (buoyancy_on_ && due(buoyancy_times_, time));
  if (fields_due)
    read_fields(time, compute_layer_fields(particles, suspension_.cylinder, suspension_.fluid,
                                           suspension_.particle_density, layers_));
  if (pipette_on_ && due(pipette_times_, time))
    pipette_readings_.push_back(read_pipette(pipette_, particles, time, suspension_));
}

HydrometerReading InstrumentPanel::hydrometer_at(double time, const Particles& particles) const {
  return read_hydrometer(hydrometer_,
                         compute_layer_fields(particles, suspension_.cylinder, suspension_.fluid,
                                              suspension_.particle_density, layers_),
                         time, suspension_);
}

void InstrumentPanel::observe(double time, const LayerFields& fields) {
  read_fields(time, fields);
  if (pipette_on_ && due(pipette_times_, time))
    pipette_readings_.push_back(read_pipette(pipette_, fields, time, suspension_));
}

std::vector<TestReadings> InstrumentPanel::readings() const {
  std::vector<TestReadings> out;
  if (hydrometer_on_) out.push_back(to_readings(hydrometer_readings_));
  if (buoyancy_on_) out.push_back(to_readings(buoyancy_readings_));
  if (pipette_on_) out.push_back(to_readings(pipette_readings_));
  return out;
}

}  // namespace sedem
