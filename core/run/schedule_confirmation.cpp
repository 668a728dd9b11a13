#include "core/run/schedule_confirmation.h"

#include <algorithm>
#include <cmath>

#include "core/run/simulation.h"
#include "core/run/stage_setups.h"
#include "core/sample/sample_builder.h"

namespace sedem {

namespace {

bool same_depth(double a, double b) {
  return (std::isnan(a) && std::isnan(b)) || a == b;
}

// The DEM readings of `test` at the times of every schedule given (all at one depth).
std::vector<Reading> dem_readings(const Scene& scene, const std::string& test,
                                  std::vector<const ReadingSchedule*> schedules, double& wall) {
  ReadingSchedule all;
  all.depth_fraction = schedules.front()->depth_fraction;
  for (const auto* s : schedules)
    all.times.insert(all.times.end(), s->times.begin(), s->times.end());
  std::sort(all.times.begin(), all.times.end());
  all.times.erase(std::unique(all.times.begin(), all.times.end()), all.times.end());
  const Scene s = scene_for_schedule(scene, test, all);
  const SimulationRun run = simulate(s, build_sample(sample_setup(s)));
  wall += run.wall_seconds;
  for (const auto& t : run.results.granulometry.tests)
    if (t.test == test) return t.dem.rows;
  return {};
}

std::vector<Reading> at_times(const std::vector<Reading>& rows, const std::vector<double>& times) {
  std::vector<Reading> out;
  for (const auto& r : rows)
    if (std::any_of(times.begin(), times.end(),
                    [&](double t) { return std::abs(t - r.time) <= 1e-9 * std::max(1.0, t); }))
      out.push_back(r);
  return out;
}

}  // namespace

Scene scene_for_schedule(const Scene& scene, const std::string& test,
                         const ReadingSchedule& schedule) {
  Scene s = scene;
  s.instruments = instruments_for_schedule(s.instruments, test, schedule);
  s.end_time = schedule.times.back();
  return s;
}

ScheduleConfirmation confirm_with_dem(const Scene& scene, const ScheduleDesign& design,
                                      std::int64_t particles, std::int64_t size_count) {
  Scene s = scene;
  s.sample.simulated_count = particles;
  s.sample.mass_fraction = 0;
  s.sample.size_count = size_count;
  ScheduleConfirmation c;
  c.particles = particles;
  std::vector<Reading> standard, designed;
  if (same_depth(design.standard.depth_fraction, design.designed.depth_fraction)) {
    const auto rows =
        dem_readings(s, design.test, {&design.standard, &design.designed}, c.wall_seconds);
    standard = at_times(rows, design.standard.times);
    designed = at_times(rows, design.designed.times);
  } else {
    standard = dem_readings(s, design.test, {&design.standard}, c.wall_seconds);
    designed = dem_readings(s, design.test, {&design.designed}, c.wall_seconds);
  }
  c.standard = score_readings(standard, design.truth);
  c.designed = score_readings(designed, design.truth);
  return c;
}

}  // namespace sedem
