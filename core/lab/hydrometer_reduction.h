#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace sedem {

// One hydrometer reading of a laboratory test (152H), SI except the reading.
struct LabReading {
  double time = 0;                  // s since the start of sedimentation
  double reading = 0;               // R, g/L, as read at the top of the meniscus corrected
  double temperature = 20;          // deg C of the suspension
  double composite_correction = 0;  // g/L: zero, meniscus, dispersant and temperature
  double meniscus_correction = 0;   // C_m, g/L: what the top of the meniscus reads low; the
                                    // effective depth is the 152H's at R + C_m
  std::size_t line = 0;             // the line of the file it was read from; 0: none
  std::string place = "line";       // how messages name `line` (LabTable::place)
};

// The widest composite correction accepted, g/L (the 152H's scale spans 65 g/L), and the
// largest percent finer a reduction may give (a little above 100 % is reading scatter; far
// above, a dry mass that does not belong to the readings).
inline constexpr double kMaxCompositeCorrection = 65;
inline constexpr double kMaxMeniscusCorrection = 5;
inline constexpr double kMaxPercentFiner = 110;
// The largest diameter a reduction may give, m: coarser than any grain a sedimentation test
// sorts (fine gravel), so a reading time too short to be true.
inline constexpr double kMaxLabDiameter = 2e-3;

// The specimen the readings belong to.
struct LabSpecimen {
  double specific_gravity = 2.65;  // Gs of the soil solids (at 20 C)
  double dry_mass = 50e-3;         // W, kg oven-dry
  // The suspension's volume, m^3: the 152H reads g/L, so the percent finer is of the dry mass
  // per litre (W / V); D422 and D7928 assume the 1000 mL cylinder.
  double suspension_volume = 1e-3;
};

// The standard a laboratory reduction follows: ASTM D7928 (the current one, the default) or
// D422 (withdrawn in 2016, kept for old records).
enum class LabMethod { d7928, d422 };
// "d7928" | "d422"; throws std::invalid_argument otherwise.
LabMethod parse_lab_method(const std::string& name);
// "ASTM D7928" | "ASTM D422".
std::string lab_method_name(LabMethod method);

struct LabPoint {
  double time = 0;               // s
  double diameter = 0;           // m
  double percent_finer = 0;      // %
  double corrected_reading = 0;  // R - composite correction, g/L
  double effective_depth = 0;    // L, m
  double viscosity = 0;          // Pa*s at the reading's temperature
};

// A reading that cannot be reduced: names the row, the field and the value. row() is
// 0-based (kSpecimen for the specimen's fields); the message counts rows from 1 and adds the
// file's line when the reading was read from one (LabReading::line). A reading from a
// workbook's sheet is named by the sheet and its row there instead (`place` other than
// "line"): the sheet's row numbers are the ones its user sees, and two "row"s would confuse.
class InvalidLabReading : public std::invalid_argument {
 public:
  static constexpr std::size_t kSpecimen = static_cast<std::size_t>(-1);
  InvalidLabReading(std::size_t row, std::string field, double value, const std::string& why,
                    std::size_t line = 0, const std::string& place = "line");
  std::size_t row() const { return row_; }
  const std::string& field() const { return field_; }
  double value() const { return value_; }

 private:
  std::size_t row_;
  std::string field_;
  double value_;
};

// ASTM D422 with the 152H: D = K sqrt(L / T) (mm, cm, min),
// K = sqrt(30 eta / (980 (Gs - G1))) with eta in poise and G1 the specific gravity of the
// water at the test temperature, L = 16.29 - 0.164 (R + C_m) cm (the reading corrected for
// the meniscus only: the bulb sits where the actual reading says, whatever the blank reads),
// P = (R - C) a / W' 100 with a = 1.65 Gs / ((Gs - 1) 2.65) and W' the dry mass per litre.
std::vector<LabPoint> reduce_astm_d422(const std::vector<LabReading>& readings,
                                       const LabSpecimen& specimen);

// ASTM D7928 form: Stokes' law in SI, D = sqrt(18 mu(T) H_m / ((rho_s - rho_w(T)) g t)),
// rho_s = Gs rho_w(20 C), g = 9.80665 m/s^2, H_m the 152H's effective depth; the percent
// finer N = Gs / (Gs - 1) (V_sp / M_d) rho_c (r - r_d) 100, which for a 152H reading in g/L
// of Gs = 2.65 soil is D422's (R - C) a / W' 100. H_m from r_m = R + C_m (meniscus only);
// the offset r_d (here the composite correction C) at each reading's own temperature, and
// the viscosity and water density at it.
std::vector<LabPoint> reduce_astm_d7928(const std::vector<LabReading>& readings,
                                        const LabSpecimen& specimen);

// The one reduction every command uses (sedem reduce, invert's standard beside its curve, a
// run's readings reduced again): reduce_astm_d7928 or reduce_astm_d422.
std::vector<LabPoint> reduce_lab_readings(const std::vector<LabReading>& readings,
                                          const LabSpecimen& specimen, LabMethod method);

// Checks what both reductions need: positive, finite, increasing times; readings on the
// -5..60 scale; temperatures in 0-40 C; meniscus corrections within 0-5 g/L; Gs in (1, 10];
// a positive, finite dry mass and suspension volume. Throws
// InvalidLabReading. Each reduction also refuses a result that is no finite number, a
// diameter above kMaxLabDiameter or a percent finer above kMaxPercentFiner.
void validate_lab_readings(const std::vector<LabReading>& readings, const LabSpecimen& specimen);

}  // namespace sedem
