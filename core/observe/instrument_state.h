#pragma once

// What the instruments have read so far, as a resumed run restores it from the checkpoint
// (InstrumentObserver::save_state): every reading and profile, field by field, in binary.
// Reading back checks every count against a bound and every number for finiteness, so that a
// damaged file is refused with what it got wrong.

#include <cstddef>
#include <iosfwd>
#include <vector>

#include "core/fields/layer_fields.h"
#include "core/instruments/buoyancy_sphere.h"
#include "core/instruments/hydrometer.h"
#include "core/instruments/pipette.h"

namespace sedem::instrument_state {

void write(std::ostream& out, const std::vector<HydrometerReading>& v);
void write(std::ostream& out, const std::vector<BuoyancyReading>& v);
void write(std::ostream& out, const std::vector<PipetteReading>& v);
void write(std::ostream& out, const std::vector<LargestDiameterProfile>& v);

// At most `most` records (of at most `longest` values in each of their lists).
void read(std::istream& in, std::vector<HydrometerReading>& v, std::size_t most,
          std::size_t longest);
void read(std::istream& in, std::vector<BuoyancyReading>& v, std::size_t most);
void read(std::istream& in, std::vector<PipetteReading>& v, std::size_t most);
void read(std::istream& in, std::vector<LargestDiameterProfile>& v, std::size_t most,
          std::size_t longest);

}  // namespace sedem::instrument_state
