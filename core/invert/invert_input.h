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

}  // namespace sedem::invert
