#include "core/observe/instrument_observer.h"

#include <algorithm>

#include "core/model/spread.h"
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
