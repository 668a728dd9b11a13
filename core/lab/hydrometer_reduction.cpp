#include "core/lab/hydrometer_reduction.h"

#include <cmath>
#include <sstream>
#include <utility>

#include "core/lab/water.h"

namespace sedem {

namespace {

std::string describe_invalid(std::size_t row, const std::string& field, double value,
                             const std::string& why, std::size_t line, const std::string& place) {
  // A sheet's row is what its user looks for; a text file's line is said after the row.
  const bool sheet = line > 0 && place != "line";
  std::ostringstream s;
  if (row == InvalidLabReading::kSpecimen)
    s << "specimen";
  else if (sheet)
    s << place << " " << line;
  else
    s << "row " << row + 1;
  s << ", " << field << " = " << value << ": " << why;
  if (line > 0 && !sheet) s << " (line " << line << " of the file)";
  return s.str();
}

// 152H: the D422 effective depth, cm.
double effective_depth_cm(double reading) {
  return 16.29 - 0.164 * reading;
}

// D422's a: the 152H reads g/L of Gs = 2.65 soil.
double specific_gravity_factor(double gs) {
  return 1.65 * gs / ((gs - 1.0) * 2.65);
}

double percent_finer(const LabReading& r, const LabSpecimen& s) {
  // g per litre of suspension: the 152H reads g/L.
  const double dry_mass_g = s.dry_mass * 1e3 / (s.suspension_volume * 1e3);
  return (r.reading - r.composite_correction) * specific_gravity_factor(s.specific_gravity) /
         dry_mass_g * 100.0;
}

// A result that is no number, or a share finer far above the whole specimen, comes from
// inputs that cannot be right: refused, naming the row, rather than written.
void check_point(std::size_t row, const LabReading& r, const LabPoint& p, const LabSpecimen& s) {
  for (const auto& [name, v] : {std::pair<const char*, double>{"diameter_m", p.diameter},
                                {"percent_finer", p.percent_finer},
                                {"effective_depth_m", p.effective_depth}})
    if (!std::isfinite(v))
      throw InvalidLabReading(row, name, v, "the reduction gives no finite number; check the row",
                              r.line, r.place);
  if (p.diameter > kMaxLabDiameter) {
    std::ostringstream why;
    why << "coarser than " << kMaxLabDiameter * 1e3
        << " mm, which no sedimentation test sorts: the reading time (" << r.time / 60.0
        << " min) is too short to be true; check time_min";
    throw InvalidLabReading(row, "diameter_m", p.diameter, why.str(), r.line, r.place);
  }
  if (p.percent_finer > kMaxPercentFiner) {
    std::ostringstream why;
    why << "more than " << kMaxPercentFiner << " % of the specimen cannot be finer; the dry mass ("
        << s.dry_mass * 1e3 << " g) is too small for this reading: check --mass-g";
    throw InvalidLabReading(row, "percent_finer", p.percent_finer, why.str(), r.line, r.place);
  }
}

}  // namespace

InvalidLabReading::InvalidLabReading(std::size_t row, std::string field, double value,
                                     const std::string& why, std::size_t line,
                                     const std::string& place)
    : std::invalid_argument(describe_invalid(row, field, value, why, line, place)),
      row_(row),
      field_(std::move(field)),
      value_(value) {}

void validate_lab_readings(const std::vector<LabReading>& readings, const LabSpecimen& s) {
  const std::size_t n = readings.size();
  constexpr auto kSpecimen = InvalidLabReading::kSpecimen;
  if (!(s.dry_mass > 0) || !std::isfinite(s.dry_mass))
    throw InvalidLabReading(kSpecimen, "dry_mass_kg", s.dry_mass,
                            "the dry mass must be positive and finite");
  if (!(s.specific_gravity > 1 && s.specific_gravity <= 10))
    throw InvalidLabReading(kSpecimen, "specific_gravity", s.specific_gravity,
                            "the soil must be denser than water and no denser than 10 (Gs in "
                            "(1, 10])");
  if (!(s.suspension_volume > 0) || !std::isfinite(s.suspension_volume))
    throw InvalidLabReading(kSpecimen, "suspension_volume_m3", s.suspension_volume,
                            "the suspension's volume must be positive and finite");
  for (std::size_t i = 0; i < n; ++i) {
    const auto& r = readings[i];
    if (!(r.time > 0) || !std::isfinite(r.time))
      throw InvalidLabReading(i, "time_s", r.time, "times must be positive and finite", r.line,
                              r.place);
    if (i > 0 && !(r.time > readings[i - 1].time))
      throw InvalidLabReading(
          i, "time_s", r.time,
          "times must increase (previous row: " + std::to_string(readings[i - 1].time) + " s)",
          r.line, r.place);
    if (!(r.reading >= -5 && r.reading <= 60))
      throw InvalidLabReading(i, "reading_g_per_l", r.reading, "off the 152H scale (-5 to 60 g/L)",
                              r.line, r.place);
    if (!(r.temperature >= 0 && r.temperature <= 40))
      throw InvalidLabReading(i, "temperature_c", r.temperature,
                              "outside 0-40 C, where the water density formula holds", r.line,
                              r.place);
    if (!(std::abs(r.composite_correction) <= kMaxCompositeCorrection))
      throw InvalidLabReading(i, "composite_correction_g_per_l", r.composite_correction,
                              "must be a number between -65 and 65 g/L (a correction wider than "
                              "the whole 152H scale is no correction)",
                              r.line, r.place);
    if (!(r.meniscus_correction >= 0 && r.meniscus_correction <= kMaxMeniscusCorrection))
      throw InvalidLabReading(i, "meniscus_correction_g_per_l", r.meniscus_correction,
                              "must be between 0 and 5 g/L (the top of the meniscus reads low "
                              "by about 1 g/L on a 152H)",
                              r.line, r.place);
  }
}

std::vector<LabPoint> reduce_astm_d422(const std::vector<LabReading>& readings,
                                       const LabSpecimen& s) {
  validate_lab_readings(readings, s);
  std::vector<LabPoint> out;
  for (const auto& r : readings) {
    LabPoint p;
    p.time = r.time;
    p.viscosity = water::viscosity(r.temperature);
    const double eta_poise = 10.0 * p.viscosity;
    // G1: the water's specific gravity against water at 4 C (1000 kg/m^3 to 0.003 %).
    const double g1 = water::density(r.temperature) / 1000.0;
    const double k = std::sqrt(30.0 * eta_poise / (980.0 * (s.specific_gravity - g1)));
    const double depth_cm = effective_depth_cm(r.reading + r.meniscus_correction);
    const double time_min = r.time / 60.0;
    p.diameter = k * std::sqrt(depth_cm / time_min) * 1e-3;  // mm -> m
    p.effective_depth = depth_cm * 1e-2;
    p.corrected_reading = r.reading - r.composite_correction;
    p.percent_finer = percent_finer(r, s);
    check_point(out.size(), r, p, s);
    out.push_back(p);
  }
  return out;
}

std::vector<LabPoint> reduce_astm_d7928(const std::vector<LabReading>& readings,
                                        const LabSpecimen& s) {
  validate_lab_readings(readings, s);
  constexpr double g = 9.80665;
  const double rho_solids = s.specific_gravity * water::density(20.0);
  std::vector<LabPoint> out;
  for (const auto& r : readings) {
    LabPoint p;
    p.time = r.time;
    p.viscosity = water::viscosity(r.temperature);
    p.effective_depth = effective_depth_cm(r.reading + r.meniscus_correction) * 1e-2;
    const double rho_w = water::density(r.temperature);
    p.diameter =
        std::sqrt(18.0 * p.viscosity * p.effective_depth / ((rho_solids - rho_w) * g * r.time));
    p.corrected_reading = r.reading - r.composite_correction;
    p.percent_finer = percent_finer(r, s);
    check_point(out.size(), r, p, s);
    out.push_back(p);
  }
  return out;
}

LabMethod parse_lab_method(const std::string& name) {
  if (name == "d7928") return LabMethod::d7928;
  if (name == "d422") return LabMethod::d422;
  throw std::invalid_argument("method '" + name + "': expected d7928 or d422");
}

std::string lab_method_name(LabMethod method) {
  return method == LabMethod::d422 ? "ASTM D422" : "ASTM D7928";
}

std::vector<LabPoint> reduce_lab_readings(const std::vector<LabReading>& readings,
                                          const LabSpecimen& specimen, LabMethod method) {
  return method == LabMethod::d422 ? reduce_astm_d422(readings, specimen)
                                   : reduce_astm_d7928(readings, specimen);
}

}  // namespace sedem
