#pragma once

#include <istream>
#include <string>
#include <vector>

#include "core/instruments/granulometry.h"
#include "core/invert/inversion.h"

namespace sedem::invert {

// The column of a test's reading in a laboratory CSV: reading_g_per_l (152H, read with
// core/lab's read_lab_readings_csv), apparent_mass_g (sphere), dry_mass_g (pipette).
std::string reading_column(Test test);

// The sphere's or the pipette's readings: a CSV with time_min and reading_column(test)
// (any order, other columns ignored). Times to s, values as read (g). Throws LabCsvError.
std::vector<Measurement> read_measurements_csv(std::istream& in, Test test);

// The standard reduction of the sphere's or the pipette's readings, as a DEM run reduces
// them: Stokes' diameter at the instrument's depth (Eq. 16), Eq. 22 (sphere) or Eq. 17
// (pipette) for the percent finer.
std::vector<GradingPoint> standard_reduction(const Scene& scene, Test test,
                                             const std::vector<Measurement>& data);

// A simulated test's readings as a laboratory records them: the instrument's own values
// (152H R in g/L, the sphere's apparent mass and the pipette's dry mass in g) rounded to
// `resolution` (0: the test's default), the 152H's less its reading in the scene's clear
// liquid (what a composite correction removes, taken as exact); and their standard
// reduction: ASTM D422 for the 152H (its effective depth; the specimen's mass per litre of
// the scene's cylinder, as D422 assumes 1000 mL; 20 C), standard_reduction for the others.
struct RecordedTest {
  std::vector<Measurement> data;
  std::vector<GradingPoint> standard;
  std::string standard_name;  // "ASTM D422", "Eq. 22 (sphere)", "Eq. 17 (pipette)"
};
RecordedTest record_simulated(const Scene& scene, Test test, const std::vector<double>& times,
                              const std::vector<double>& raw, double resolution = 0);

// The instrument's own value of a reading of a run (readings_<test>.csv's columns), in the
// laboratory's unit: reading_g_per_l; apparent_mass_kg and dry_mass_kg in g.
std::string run_reading_column(Test test);
double run_reading_to_lab_unit(Test test, double value);

}  // namespace sedem::invert
