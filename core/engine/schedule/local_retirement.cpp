#include "core/engine/schedule/local_stepper.h"

#include <algorithm>
#include <numbers>

namespace sedem {

// Grain id (coasting, or taken out of the members) leaves the dynamics at p at time t: it falls
// freely from there onto the top of its column of the coarse bed, which rises by its area.
void LocalStepper::retire(std::uint32_t id, double t, const FreeFlight::Point& p) {
  const double r = 0.5 * e_.sample.particles.diameter[id];
  const double hw = e_.model.half_width;
  const long columns = long(bed_.size());
  const long c = std::clamp(long((p.x + hw) / bed_column_), 0L, columns - 1);
  // It comes to rest in the lowest column within two of its own (nearest first): a pile
  // spreads, where one column for each grain would grow towers.
  long to = c;
  for (long k : {c - 1, c + 1, c - 2, c + 2})
    if (k >= 0 && k < columns && bed_[std::size_t(k)] < bed_[std::size_t(to)]) to = k;
  const double land = std::min(p.y, bed_[std::size_t(to)] + r);
  bed_[std::size_t(to)] += std::numbers::pi * r * r / (bed_column_ * kBedPacking);
  track_[id].flight = flight_of(id, p);
  track_[id].t0 = t;
  // A retired grain has no window (its heap entry, if any, is stale): t1_ holds the x of its
  // place on the bed.
  track_[id].t1 = std::clamp(p.x + double(to - c) * bed_column_, -hw + r, hw - r);
  land_y_[id] = land;
  kind_[id] = GrainKind::retired;
  if (e_.model.contact) boxes_.clear(id);
  move_deposit(id, track_[id].t1, land);
  ++e_.stats.retired;
}

FreeFlight::Point LocalStepper::retired_at(std::uint32_t id, double t) const {
  const FreeFlight::Point q = track_[id].flight.at(std::max(0.0, t - track_[id].t0));
  if (q.y > land_y_[id]) return q;
  return {track_[id].t1, land_y_[id], 0, 0};
}

// Members (moving or frozen) whose disc is wholly below the retirement height retire.
void LocalStepper::retire_members() {
  wake_.clear();
  for (std::size_t k = 0; k < e_.state.size(); ++k)
    if (e_.state.y[k] + 0.5 * e_.state.diameter[k] < retire_height_ &&
        !(own_steps_ && member_at_[k] >= 0))  // lagging (own steps): not at the members' time
      wake_.push_back(e_.state.origin[k]);
  std::sort(wake_.begin(), wake_.end());
  for (std::uint32_t id : wake_) {
    const std::size_t k = member_[id];
    const bool frozen = e_.state.frozen[k] != 0;
    const FreeFlight::Point p{e_.state.x[k], e_.state.y[k], frozen ? 0.0 : e_.state.vx[k],
                              frozen ? 0.0 : e_.state.vy[k]};
    remove_member(k);
    member_[id] = kNoMember;
    retire(id, e_.time, p);
  }
  wake_.clear();
}

}  // namespace sedem
