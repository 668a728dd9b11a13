#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "core/lab/lab_table.h"

namespace sedem {

// A sieve analysis of the whole sample (ASTM D6913): each sieve's opening and the dry mass it
// retained, the pan's, and the sample's total dry mass.
struct Sieve {
  double opening_mm = 0;
  double retained_g = 0;
  std::size_t line = 0;
};
struct SieveAnalysis {
  std::vector<Sieve> sieves;      // coarsest first; the pan not among them
  std::optional<double> pan_g;    // the pan's row, if the file has one
  std::optional<double> total_g;  // the total dry mass: the file's "total" row or a flag
  std::string place = "line";     // how messages name a sieve's line (LabTable::place)
};

// The widest sieve opening, mm (a 125 mm coarse sieve and then some) and the largest mass, g.
inline constexpr double kMaxSieveOpeningMm = 1000;
inline constexpr double kMaxSieveMassG = 1e6;

// Reads the sieve analysis from a laboratory table: columns opening_mm and mass_retained_g
// (under the laboratory's names and units: "opening (mm)", "sieve [µm]", "retained (g)").
// A row whose cell says "pan" (or whose opening is 0) is the pan; one that says "total" holds
// the total dry mass (its opening cell may be empty). Openings in (0, kMaxSieveOpeningMm],
// none twice; masses in [0, kMaxSieveMassG]. Throws LabCsvError naming the line and column.
SieveAnalysis read_sieve_analysis(const LabTable& table);

// One sieve's point of the grading curve (D6913): the cumulative mass retained on it and on
// every coarser sieve, and the percent passing, 100 (M_total - cumulative) / M_total.
struct SievePoint {
  double opening_mm = 0;
  double retained_g = 0;
  double cumulative_retained_g = 0;
  double percent_passing = 0;
};
// M_total is `total_g` (a flag) if given, else the analysis' total row, else the sum of the
// sieves' and the pan's masses (then the pan's row is needed). Throws std::invalid_argument
// for no total, a total below the sieves' sum, or a total not positive.
std::vector<SievePoint> sieve_percent_passing(const SieveAnalysis& analysis,
                                              std::optional<double> total_g = std::nullopt);
// The total dry mass sieve_percent_passing takes, and how far the sieves' and the pan's sum
// falls from it, % of it (NaN without a pan: then nothing to compare).
double sieve_total_g(const SieveAnalysis& analysis, std::optional<double> total_g);
double sieve_mass_difference_percent(const SieveAnalysis& analysis, std::optional<double> total_g);

}  // namespace sedem
