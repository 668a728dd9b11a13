#include "core/observe/instrument_state.h"

#include <cmath>
#include <cstdint>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace sedem::instrument_state {

namespace {

void put(std::ostream& out, double v) {
  out.write(reinterpret_cast<const char*>(&v), sizeof v);
}

void put_count(std::ostream& out, std::size_t n) {
  const std::uint64_t v = n;
  out.write(reinterpret_cast<const char*>(&v), sizeof v);
}

void put(std::ostream& out, const std::vector<double>& v) {
  put_count(out, v.size());
  for (double x : v) put(out, x);
}

double take(std::istream& in, const char* what) {
  double v = 0;
  in.read(reinterpret_cast<char*>(&v), sizeof v);
  if (!in) throw std::runtime_error(std::string("truncated at ") + what);
  if (!std::isfinite(v)) throw std::runtime_error(std::string(what) + " is not a number");
  return v;
}

std::size_t take_count(std::istream& in, std::size_t most, const char* what) {
  std::uint64_t n = 0;
  in.read(reinterpret_cast<char*>(&n), sizeof n);
  if (!in) throw std::runtime_error(std::string("truncated at the count of ") + what);
  if (n > most)
    throw std::runtime_error(std::to_string(n) + " " + what + ", more than the " +
                             std::to_string(most) + " the run can hold");
  return std::size_t(n);
}

void take(std::istream& in, std::vector<double>& v, std::size_t longest, const char* what) {
  v.resize(take_count(in, longest, what));
  for (double& x : v) x = take(in, what);
}

// Each record's numbers in one list, which writing and reading both walk: a field added to
// one direction cannot go missing in the other. `R` is the record, const or not.
template <class R, class Visit>
void scalars_of(R& r, Visit&& visit) {
  using Reading = std::remove_const_t<R>;
  if constexpr (std::is_same_v<Reading, HydrometerReading>) {
    for (auto* x : {&r.time, &r.tip_depth, &r.centre_depth, &r.reading, &r.standard_effective_depth,
                    &r.clear_water_tip_depth, &r.density_eq19, &r.bulb_mean_density, &r.diameter,
                    &r.percent_finer, &r.percent_finer_bulb_density})
      visit(*x);
  } else if constexpr (std::is_same_v<Reading, BuoyancyReading>) {
    for (auto* x : {&r.time, &r.depth, &r.mean_density, &r.apparent_mass,
                    &r.clear_water_apparent_mass, &r.diameter, &r.percent_finer})
      visit(*x);
  } else {
    static_assert(std::is_same_v<Reading, PipetteReading>);
    for (auto* x : {&r.time, &r.depth, &r.radius, &r.concentration, &r.dry_mass, &r.diameter,
                    &r.percent_finer})
      visit(*x);
  }
}

template <class Reading>
void write_readings(std::ostream& out, const std::vector<Reading>& v) {
  put_count(out, v.size());
  for (const Reading& r : v) scalars_of(r, [&](double x) { put(out, x); });
}

template <class Reading>
void read_readings(std::istream& in, std::vector<Reading>& v, std::size_t most, const char* what) {
  v.resize(take_count(in, most, what));
  for (Reading& r : v) scalars_of(r, [&](double& x) { x = take(in, what); });
}

}  // namespace

void write(std::ostream& out, const std::vector<HydrometerReading>& v) {
  write_readings(out, v);
  for (const HydrometerReading& r : v) {
    put(out, r.on_scale ? 1.0 : 0.0);
    put(out, r.profile_offset);
    put(out, r.profile_density);
  }
}

void read(std::istream& in, std::vector<HydrometerReading>& v, std::size_t most,
          std::size_t longest) {
  read_readings(in, v, most, "hydrometer readings");
  for (HydrometerReading& r : v) {
    r.on_scale = take(in, "hydrometer readings") != 0;
    take(in, r.profile_offset, longest, "bulb profile points");
    take(in, r.profile_density, longest, "bulb profile points");
    if (r.profile_offset.size() != r.profile_density.size())
      throw std::runtime_error("a bulb profile's offsets and densities differ in count");
  }
}

void write(std::ostream& out, const std::vector<BuoyancyReading>& v) {
  write_readings(out, v);
}

void read(std::istream& in, std::vector<BuoyancyReading>& v, std::size_t most) {
  read_readings(in, v, most, "buoyancy readings");
}

void write(std::ostream& out, const std::vector<PipetteReading>& v) {
  write_readings(out, v);
}

void read(std::istream& in, std::vector<PipetteReading>& v, std::size_t most) {
  read_readings(in, v, most, "pipette readings");
}

void write(std::ostream& out, const std::vector<LargestDiameterProfile>& v) {
  put_count(out, v.size());
  for (const LargestDiameterProfile& p : v) {
    put(out, p.time);
    put(out, p.depth);
    put(out, p.largest);
    put(out, p.limiting);
  }
}

void read(std::istream& in, std::vector<LargestDiameterProfile>& v, std::size_t most,
          std::size_t longest) {
  v.resize(take_count(in, most, "largest-diameter profiles"));
  for (LargestDiameterProfile& p : v) {
    p.time = take(in, "a largest-diameter profile");
    take(in, p.depth, longest, "profile layers");
    take(in, p.largest, longest, "profile layers");
    take(in, p.limiting, longest, "profile layers");
  }
}

}  // namespace sedem::instrument_state
