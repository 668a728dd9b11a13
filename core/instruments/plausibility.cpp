#include "core/instruments/plausibility.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/instruments/hydrometer.h"
#include "core/instruments/pipette.h"

namespace sedem {

namespace {

std::string fixed(double v, int digits) {
  std::ostringstream os;
  os.setf(std::ios::fixed);
  os.precision(digits);
  os << v;
  return os.str();
}

std::string round_count(double n) {
  return n >= 10 ? fixed(n, 0) : n >= 0.1 ? fixed(n, 1) : fixed(n, 4);
}

const SampledVolume* sampled(const std::vector<SampledVolume>& volumes, const std::string& test) {
  for (const auto& v : volumes)
    if (v.test == test) return &v;
  return nullptr;
}

}  // namespace

std::vector<SampledVolume> sampled_volumes(const TestSetup& setup, double particle_count) {
  const auto& in = setup.instruments;
  const Cylinder& c = setup.cylinder;
  std::vector<SampledVolume> out;
  const auto add = [&](const char* test, const char* key, double share) {
    share = std::clamp(share, 0.0, 1.0);
    out.push_back({test, key, share, share * particle_count});
  };
  if (in.hydrometer)
    add("hydrometer", "cylinder.height_m", HydrometerDesign{}.bulb_length / c.height);
  if (in.buoyancy)
    add("buoyancy", "instruments.buoyancy.sphere_diameter_cm", in.sphere_diameter / c.height);
  if (in.pipette) {
    Pipette p;
    p.volume = in.pipette_volume;
    const double r = p.radius(c);
    add("pipette", "instruments.pipette.volume_ml",
        std::numbers::pi * r * r / (c.diameter * c.height));
  }
  return out;
}

double solids_volume_fraction(const TestSetup& s) {
  const double volume =
      std::numbers::pi / 4 * s.cylinder.diameter * s.cylinder.diameter * s.cylinder.height;
  return s.total_mass / s.particle_density / volume;
}

double solids_mass_fraction(const TestSetup& s) {
  const double volume =
      std::numbers::pi / 4 * s.cylinder.diameter * s.cylinder.diameter * s.cylinder.height;
  const double solids = s.total_mass / s.particle_density;
  const double liquid = std::max(0.0, volume - solids) * s.fluid.density;
  return s.total_mass / (s.total_mass + liquid);
}

std::vector<Doubt> setup_doubts(const TestSetup& setup, double particle_count) {
  std::vector<Doubt> out;
  for (const auto& v : sampled_volumes(setup, particle_count))
    if (v.particles < kDoubtfulSampled)
      out.push_back(
          {"few_particles", v.test + ": its sampled volume holds about " +
                                round_count(v.particles) + " of the " + fixed(particle_count, 0) +
                                " simulated particles at the start (" + fixed(100 * v.share, 3) +
                                " % of the section); below " + fixed(kDoubtfulSampled, 0) +
                                " its reading carries more than 18 % sampling noise: raise "
                                "sample.simulated_count or " +
                                v.key});
  const double by_volume = solids_volume_fraction(setup), by_mass = solids_mass_fraction(setup);
  if (by_volume > kOneWayVolumeFraction * (1 + kCouplingTolerance) ||
      by_mass > kOneWayMassFraction * (1 + kCouplingTolerance))
    out.push_back(
        {"coupling", "the suspension holds " + fixed(100 * by_volume, 2) + " % solids by volume, " +
                         fixed(100 * by_mass, 2) +
                         " % by mass, beyond the one-way coupling the model assumes (the paper's "
                         "limits: 1.6 % by volume, 4 % by mass): the grains' stirring of the "
                         "water, left out, then matters; lower sample.mass_g"});
  const double volume = std::numbers::pi / 4 * setup.cylinder.diameter * setup.cylinder.diameter *
                        setup.cylinder.height;
  const double concentration = setup.total_mass / volume;
  if (setup.instruments.hydrometer && concentration < kDiluteConcentration)
    out.push_back({"dilute", "the suspension starts at " + fixed(concentration, 2) +
                                 " g/L of soil, below " + fixed(kDiluteConcentration, 0) +
                                 " g/L: a 152H reading (1 g/L graduations) resolves its percent "
                                 "finer no better than 20 %; raise sample.mass_g or lower "
                                 "cylinder.height_m"});
  return out;
}

std::vector<Doubt> result_doubts(const Granulometry& g, const TestSetup& setup,
                                 double particle_count) {
  std::vector<Doubt> out;
  const auto volumes = sampled_volumes(setup, particle_count);
  for (const auto& t : g.tests) {
    const SampledVolume* v = sampled(volumes, t.test);
    const double n = v ? std::max(v->particles, 1.0) : particle_count;
    // Three standard deviations of the count in the volume, as percentage points.
    const double noise = std::max(1.0, 300.0 / std::sqrt(n));
    const Reading* worst = nullptr;
    double beyond = 0;
    for (const auto& r : t.dem.rows) {
      const double off = std::max(r.percent_finer - 100.0, -r.percent_finer);
      if (off > beyond) {
        beyond = off;
        worst = &r;
      }
    }
    if (worst && beyond > noise)
      out.push_back(
          {"percent_finer_out_of_range", t.test + " reads " + fixed(worst->percent_finer, 1) +
                                             " % finer at " + fixed(worst->time, 1) +
                                             " s, outside 0-100 % by more than its sampling "
                                             "noise (" +
                                             fixed(noise, 1) + " pp with about " + round_count(n) +
                                             " particles in its volume)"});
    double lo = 100, hi = 0;
    for (const auto& r : t.reference.rows) {
      lo = std::min(lo, r.percent_finer);
      hi = std::max(hi, r.percent_finer);
    }
    const double span = std::max(hi - lo, 5.0);
    if (std::isfinite(t.error) && !t.reference.rows.empty() && t.error > span)
      out.push_back({"error_beyond_range",
                     t.test + ": its error (" + fixed(t.error, 1) +
                         " pp) is larger than the span its readings cover (" + fixed(hi - lo, 1) +
                         " pp of percent finer, at least 5 counted): its curve says nothing of "
                         "the soil"});
  }
  return out;
}

}  // namespace sedem
