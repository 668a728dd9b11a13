#include "core/observe/instrument_observer.h"

#include <algorithm>
#include <stdexcept>

#include "core/model/spread.h"
#include "core/observe/instrument_state.h"
#include "core/reference/reference_readings.h"

namespace sedem {

std::vector<TestReadings> TestResults::dem() const {
  std::vector<TestReadings> out;
  for (const auto& t : granulometry.tests) out.push_back(t.dem);
  return out;
}

InstrumentObserver::InstrumentObserver(const TestSetup& setup, const Sample& sample)
    : setup_(setup),
      classes_(sample.classes),
      particle_density_(sample.particle_density),
      panel_(setup, sample),
      reading_times_(panel_.reading_times()),
      profile_times_(setup.instruments.profile_times),
      bulb_times_(setup.instruments.hydrometer ? setup.instruments.bulb_profile_times
                                               : std::vector<double>{}),
      times_(merge_times({reading_times_, profile_times_, bulb_times_})),
      reference_(reference_readings(setup, sample)) {
  std::erase_if(times_, [&](double t) { return t > setup.end_time * (1 + 1e-12); });
}

void InstrumentObserver::observe(double time, const Particles& particles) {
  if (contains_time(reading_times_, time)) panel_.observe(time, particles);
  if (contains_time(profile_times_, time))
    profiles_.push_back(largest_diameter_profile(particles, setup_.cylinder, setup_.fluid,
                                                 particle_density_,
                                                 std::size_t(setup_.instruments.layers), time));
  if (contains_time(bulb_times_, time))
    bulb_profiles_.push_back(panel_.hydrometer_at(time, particles));
}

void InstrumentObserver::save_state(std::ostream& out) const {
  instrument_state::write(out, panel_.hydrometer_readings());
  instrument_state::write(out, panel_.buoyancy_readings());
  instrument_state::write(out, panel_.pipette_readings());
  instrument_state::write(out, profiles_);
  instrument_state::write(out, bulb_profiles_);
}

void InstrumentObserver::load_state(std::istream& in) {
  // A profile has a value per layer; a bulb profile at most one per layer along the bulb.
  const std::size_t layers = std::size_t(setup_.instruments.layers) + 1;
  std::vector<HydrometerReading> hydrometer, bulbs;
  std::vector<BuoyancyReading> buoyancy;
  std::vector<PipetteReading> pipette;
  std::vector<LargestDiameterProfile> profiles;
  instrument_state::read(in, hydrometer, reading_times_.size(), layers);
  instrument_state::read(in, buoyancy, reading_times_.size());
  instrument_state::read(in, pipette, reading_times_.size());
  instrument_state::read(in, profiles, profile_times_.size(), layers);
  instrument_state::read(in, bulbs, bulb_times_.size(), layers);
  panel_.restore(std::move(hydrometer), std::move(buoyancy), std::move(pipette));
  // Each taken at one of the run's times, in time order.
  auto check = [](const auto& taken, const std::vector<double>& times, const char* what) {
    for (std::size_t k = 0; k < taken.size(); ++k)
      if (!contains_time(times, taken[k].time) || (k > 0 && taken[k].time <= taken[k - 1].time))
        throw std::runtime_error(std::string("a ") + what + " at " + std::to_string(taken[k].time) +
                                 " s, not one of the run's times in order");
  };
  check(profiles, profile_times_, "largest-diameter profile");
  check(bulbs, bulb_times_, "bulb profile");
  profiles_ = std::move(profiles);
  bulb_profiles_ = std::move(bulbs);
}

TestResults InstrumentObserver::results(std::size_t max_profiles) const {
  TestResults r;
  r.granulometry = granulometry();
  r.hydrometer = panel_.hydrometer_readings();
  for (std::size_t i : spread_indices(profiles_.size(), max_profiles))
    r.profiles.push_back(profiles_[i]);
  r.bulb_profiles = bulb_profiles_;
  return r;
}

Granulometry InstrumentObserver::granulometry() const {
  // The reference covers every reading time; compare only those the run reached.
  std::vector<TestReadings> dem = panel_.readings();
  std::vector<TestReadings> reference = reference_;
  for (auto& ref : reference) {
    auto it =
        std::find_if(dem.begin(), dem.end(), [&](const auto& d) { return d.test == ref.test; });
    const std::size_t reached = it == dem.end() ? 0 : it->rows.size();
    if (ref.rows.size() > reached) ref.rows.resize(reached);
  }
  return compare(dem, reference, classes_);
}

}  // namespace sedem
