#pragma once

#include <istream>
#include <string>
#include <vector>

#include "core/instruments/granulometry.h"
#include "core/invert/inversion.h"
#include "core/lab/hydrometer_reduction.h"
#include "core/lab/lab_table.h"

namespace sedem::invert {

// How a test's readings are recorded and reduced.
struct ReadingFormat {
  // The laboratory CSV's column: reading_g_per_l (152H, read with core/lab's
  // read_lab_readings_csv), apparent_mass_g (sphere), dry_mass_g (pipette).
  const char* lab_column;
  // A run's readings_<test>.csv column, and its factor to the laboratory's unit: g/L as it
  // is; the sphere's apparent_mass_kg and the pipette's dry_mass_kg to g.
  const char* run_column;
  double run_to_lab;
  const char* standard_name;  // "ASTM D7928", "Eq. 22 (sphere)", "Eq. 17 (pipette)"
};
const ReadingFormat& reading_format(Test test);

// The sphere's or the pipette's readings: a CSV with time_min and the lab_column
// (any order, other columns ignored). Times to s, values as read (g). Throws LabCsvError.
std::vector<Measurement> read_measurements_csv(std::istream& in, Test test);
// The same from a table already read (a text file or a workbook's sheet); the columns may be
// named in the laboratory's words and units ("time (s)", "apparent mass (g)", "dry mass [mg]").
// `lines`, if given, receives each reading's line in the file (the table's `place` says what
// its numbers count), so that a message about the n-th reading can name where it is.
std::vector<Measurement> read_measurements(const LabTable& table, Test test,
                                           std::vector<std::size_t>* lines = nullptr);

// The standard reduction of the sphere's or the pipette's readings, as a DEM run reduces
// them: Stokes' diameter at the instrument's depth (Eq. 16), Eq. 22 (sphere) or Eq. 17
// (pipette) for the percent finer.
std::vector<GradingPoint> standard_reduction(const TestSetup& setup, Test test,
                                             const std::vector<Measurement>& data);

// The specimen a 152H reduction of the setup's readings takes: its Gs, dry mass and the
// suspension's volume (the cylinder's), so that the percent finer is of the mass per litre
// whatever the cylinder holds. `sedem reduce`, invert's standard and a run's readings reduced
// again all reduce through reduce_lab_readings with it.
LabSpecimen lab_specimen(const TestSetup& setup);

// A simulated test's readings as a laboratory records them: the instrument's own values
// (152H R in g/L, the sphere's apparent mass and the pipette's dry mass in g) rounded to
// `resolution` (0: the test's default), the 152H's less its reading in the setup's clear
// liquid (what a composite correction removes, taken as exact); and their standard
// reduction: reduce_lab_readings by `method` with lab_specimen for the 152H (its effective
// depth; 20 C), standard_reduction for the others.
struct RecordedTest {
  std::vector<Measurement> data;
  std::vector<GradingPoint> standard;
};
RecordedTest record_simulated(const TestSetup& setup, Test test, const std::vector<double>& times,
                              const std::vector<double>& raw, double resolution = 0,
                              LabMethod method = LabMethod::d7928);

}  // namespace sedem::invert
