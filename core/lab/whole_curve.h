#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "core/lab/sieve_analysis.h"

namespace sedem {

// One point of a sample's whole grading curve, from the largest sieve to the finest reading,
// marked by where it comes from.
struct CurvePoint {
  std::string source;        // "sieve", or the sedimentation's ("hydrometer", "inverted", ...)
  double diameter = 0;       // m: the sieve's opening, or the reading's diameter
  double percent_finer = 0;  // % of the whole sample
  double time = 0;           // s; NaN for a sieve (and an inverted curve's node)
  double fraction_percent_finer = 0;  // % of the fraction passing the separating sieve; NaN
                                      // for a sieve
  double retained_g = 0;              // the sieve's mass retained; NaN for the others
};

// A sedimentation test's point as its reduction gives it: % finer of the fraction that
// passed the separating sieve, the specimen the test was made on.
struct SedimentationPoint {
  double diameter = 0;  // m
  double percent_finer = 0;
  double time = 0;  // s; NaN when not a reading
};

// The percent passing the separating sieve (the one the sedimentation specimen passed: the
// No. 10, 2 mm, or a finer one) in the sieve analysis: the sieve of that opening (within
// 1 %). Throws std::invalid_argument naming the openings there are when none is.
double separating_sieve_passing(const std::vector<SievePoint>& sieves, double separating_mm);

// The whole curve (ASTM D6913 with D7928 or D422): every sieve's percent passing of the total
// dry mass, and each sedimentation point's percent finer of its fraction scaled by the percent
// passing the separating sieve, N_total = N_fraction PP_sep / 100; from the coarsest diameter
// to the finest (a sieve before a reading at the same diameter).
std::vector<CurvePoint> whole_curve(const std::vector<SievePoint>& sieves, double separating_mm,
                                    const std::string& source,
                                    const std::vector<SedimentationPoint>& sedimentation);
// Appends another sedimentation part (an inversion's curve beside the standard's) to a whole
// curve, scaled alike, keeping the order.
void add_to_whole_curve(std::vector<CurvePoint>& curve, double passing_percent,
                        const std::string& source,
                        const std::vector<SedimentationPoint>& sedimentation);

// The tolerance, pp, within which a finer point may read above a coarser sieve (reading
// scatter) before whole_curve_conflict says so.
inline constexpr double kWholeCurveTolerancePp = 2.0;

// A grading curve never rises toward finer sizes: the largest excess, beyond
// kWholeCurveTolerancePp, of a sedimentation point's percent finer over a coarser sieve's
// percent passing, in words ("hydrometer: 62.2 % finer at 28.4 um, above the 50 % passing the
// 0.075 mm sieve: ..."), or "" when there is none. A separating sieve or dry mass that
// does not belong to the readings shows this way.
std::string whole_curve_conflict(const std::vector<CurvePoint>& curve);

// source, diameter_m, diameter_mm, diameter_um, percent_finer, time_s, time_min,
// percent_finer_of_fraction, mass_retained_g (empty cells where a source has no value).
void write_whole_curve_csv(std::ostream& out, const std::vector<CurvePoint>& curve,
                           const std::string& note = "");

}  // namespace sedem
