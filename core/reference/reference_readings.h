#pragma once

#include <vector>

#include "core/instruments/granulometry.h"
#include "core/reference/reference_field.h"

namespace sedem {

// The setup's reference options from its InstrumentsConfig.
ReferenceOptions reference_options(const TestSetup& setup);

// Every enabled test of the setup applied to the reference solution at its times, with the
// same instrument models as the DEM run.
std::vector<TestReadings> reference_readings(const TestSetup& setup, const Sample& sample);
// The same from a reference already solved (its fronts cost O(sizes^2)), so that many
// schedules can read one solution.
std::vector<TestReadings> reference_readings(const TestSetup& setup, const Sample& sample,
                                             const ReferenceSolution& reference);

}  // namespace sedem
