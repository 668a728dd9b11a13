#include "core/lab/whole_curve.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace sedem {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The shortest text that reads back as the same double; "" for NaN (no value).
std::string cell(double v) {
  if (std::isnan(v)) return "";
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, result.ptr);
}

void sort_coarse_first(std::vector<CurvePoint>& curve) {
  std::stable_sort(curve.begin(), curve.end(), [](const CurvePoint& a, const CurvePoint& b) {
    if (a.diameter != b.diameter) return a.diameter > b.diameter;
    return a.source == "sieve" && b.source != "sieve";
  });
}

}  // namespace

double separating_sieve_passing(const std::vector<SievePoint>& sieves, double separating_mm) {
  for (const auto& s : sieves)
    if (std::abs(s.opening_mm - separating_mm) <= 0.01 * separating_mm) return s.percent_passing;
  std::ostringstream why;
  why << "the separating sieve (" << separating_mm
      << " mm, the one the sedimentation specimen passed) is not in the sieve analysis; its "
         "openings are";
  for (std::size_t i = 0; i < sieves.size(); ++i) why << (i ? ", " : " ") << sieves[i].opening_mm;
  why << " mm (give the right one with --separating-sieve-mm)";
  throw std::invalid_argument(why.str());
}

void add_to_whole_curve(std::vector<CurvePoint>& curve, double passing_percent,
                        const std::string& source,
                        const std::vector<SedimentationPoint>& sedimentation) {
  for (const auto& p : sedimentation)
    curve.push_back({source, p.diameter, p.percent_finer * passing_percent / 100.0, p.time,
                     p.percent_finer, kNaN});
  sort_coarse_first(curve);
}

std::vector<CurvePoint> whole_curve(const std::vector<SievePoint>& sieves, double separating_mm,
                                    const std::string& source,
                                    const std::vector<SedimentationPoint>& sedimentation) {
  const double passing = separating_sieve_passing(sieves, separating_mm);
  std::vector<CurvePoint> curve;
  for (const auto& s : sieves)
    curve.push_back({"sieve", s.opening_mm * 1e-3, s.percent_passing, kNaN, kNaN, s.retained_g});
  add_to_whole_curve(curve, passing, source, sedimentation);
  return curve;
}

std::string whole_curve_conflict(const std::vector<CurvePoint>& curve) {
  const CurvePoint *worst_point = nullptr, *worst_sieve = nullptr;
  double worst = kWholeCurveTolerancePp;
  for (const auto& p : curve) {
    if (p.source == "sieve") continue;
    for (const auto& s : curve)
      if (s.source == "sieve" && s.diameter > p.diameter &&
          p.percent_finer - s.percent_finer > worst) {
        worst = p.percent_finer - s.percent_finer;
        worst_point = &p;
        worst_sieve = &s;
      }
  }
  if (!worst_point) return "";
  std::ostringstream why;
  why.precision(3);
  why << worst_point->source << ": " << worst_point->percent_finer << " % finer at "
      << worst_point->diameter * 1e6 << " um, above the " << worst_sieve->percent_finer
      << " % passing the " << worst_sieve->diameter * 1e3
      << " mm sieve: a curve cannot rise toward finer sizes (check the separating sieve, the "
         "dry masses and the sieves)";
  return why.str();
}

void write_whole_curve_csv(std::ostream& out, const std::vector<CurvePoint>& curve,
                           const std::string& note) {
  if (!note.empty()) out << "# " << note << '\n';
  out << "source,diameter_m,diameter_mm,diameter_um,percent_finer,time_s,time_min,"
         "percent_finer_of_fraction,mass_retained_g\n";
  for (const auto& p : curve)
    out << p.source << ',' << cell(p.diameter) << ',' << cell(p.diameter * 1e3) << ','
        << cell(p.diameter * 1e6) << ',' << cell(p.percent_finer) << ',' << cell(p.time) << ','
        << cell(p.time / 60.0) << ',' << cell(p.fraction_percent_finer) << ',' << cell(p.retained_g)
        << '\n';
}

}  // namespace sedem
