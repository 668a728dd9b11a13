#pragma once

#include <ostream>

#include "core/instruments/granulometry.h"

namespace sedem {

// readings_<test>.csv: time_s, diameter_m, percent_finer, then the test's own columns.
void write_readings_csv(std::ostream& out, const TestReadings& readings);

// granulometry.csv, one row per point: test (true | hydrometer | buoyancy | pipette), source
// (true | dem | reference), time_s (empty for the true curve), diameter_m, percent_finer;
// then one summary row per test with source "error_pp" and "bias_pp" in percent_finer.
void write_granulometry_csv(std::ostream& out, const Granulometry& granulometry);

}  // namespace sedem
