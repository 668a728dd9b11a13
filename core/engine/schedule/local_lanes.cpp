// The syncs, lane by lane. Where grains meet there is one lane and its syncs are taken one at a
// time (local_stepper.cpp). Where the free grains pass each other (no suspension contacts), a
// coasting grain's sync reads and changes nothing but its own trajectory, the voidage of its
// own column of cells (its deposit leaves one cell of the column for another), and the boxes of
// the walls, the bed and the members, which no sync changes. Each column is then a lane whose
// syncs are taken in its own time order, apart from the others and on the engine's threads.
// What a sync would change outside its lane is taken after every lane, in time order, on one
// thread: a grain that retires onto the coarse bed (shared by all) or whose sync finds it in
// another column. A grain that cannot coast on joins the members after the lanes, as where
// grains meet. Nothing depends on which thread took a lane, so a run is the same bit for bit
// whatever the thread count.

#include <algorithm>
#include <cmath>

#include "core/engine/instability.h"
#include "core/engine/schedule/local_stepper.h"

namespace sedem {

// Windows cut short (a grain synced early, engaged or retired) leave their entries behind until
// their time comes: past 1.25 times the lane's entries at the last clean-up, the stale ones go
// (the queue takes the rest in the same order either way: entries compare by time, then id).
void LocalStepper::push_sync(Lane& lane, double t, std::uint32_t id) {
  lane.syncs.push(t, id);
  if (lane.syncs.size() <= lane.clean_at) return;
  lane.syncs.erase_if([&](const Sync& e) {
    return kind_[e.second] != GrainKind::coasting || track_[e.second].t1 != e.first;
  });
  lane.clean_at = lane.syncs.size() + lane.syncs.size() / 4 + 1024;
}

// Every sync of lane l due by `target`, in its time order. Touches only the lane's grains and
// cells: it runs beside the other lanes.
void LocalStepper::take_lane(std::size_t l, double target) {
  Lane& lane = lanes_[l];
  const Particles& s = e_.sample.particles;
  while (!lane.syncs.empty() && lane.syncs.front().first <= target) {
    const auto [t, id] = lane.syncs.front();
    lane.syncs.pop();
    prefetch_next(lane.syncs);
    if (kind_[id] != GrainKind::coasting || track_[id].t1 != t) continue;  // stale
    const FreeFlight::Point p = track_[id].flight.at(t - track_[id].t0);
    if (!std::isfinite(p.x + p.y + p.vx + p.vy)) {
      lane.blown_at = t;
      lane.blown_id = id;
      lane.blown_x = p.x;
      return;
    }
    lane.particle_steps += 1;
    ++lane.taken;
    if (p.y + 0.5 * s.diameter[id] < retire_height_ || lane_of(p.x) != l) {
      track_[id].t1 = HUGE_VAL;  // no window until it is taken
      lane.leaving.push_back({t, id, p});
      continue;
    }
    move_deposit(id, p.x, p.y);
    if (coast(id, t, p, true)) continue;
    track_[id].t1 = HUGE_VAL;  // its heap entry, if any, is stale
    lane.failed.push_back(id);
  }
}

// Every sync due by `target`, every lane: those that cannot coast on are in failed_.
void LocalStepper::take_lanes(double target) {
  const long lanes = long(lanes_.size());
  for (;;) {
    // Waking the second thread costs a few microseconds, a sync a fraction of one: the lanes
    // go on threads when the last round took enough syncs to pay for it, or when most lanes
    // have one due (syncs come in bursts: grains of one size that started together keep
    // syncing together, between rounds that take none). Which thread takes a lane changes no
    // result.
    std::size_t lanes_due = 0;
    for (Lane& lane : lanes_)
      lanes_due += !lane.syncs.empty() && lane.syncs.front().first <= target;
    if (lane_threads_ > 1 && (recent_syncs_ >= kThreadedSyncs || 2 * lanes_due >= lanes_.size())) {
#pragma omp parallel for schedule(static) num_threads(lane_threads_)
      for (long l = 0; l < lanes; ++l) take_lane(std::size_t(l), target);
    } else {
      for (long l = 0; l < lanes; ++l) take_lane(std::size_t(l), target);
    }
    recent_syncs_ = 0;
    for (Lane& lane : lanes_) {
      recent_syncs_ += lane.taken;
      lane.taken = 0;
    }
    // The first blow-up in time (then id) is reported, whichever lane met it first.
    const Lane* blown = nullptr;
    for (const Lane& lane : lanes_)
      if (lane.blown_at != HUGE_VAL && (!blown || std::pair(lane.blown_at, lane.blown_id) <
                                                      std::pair(blown->blown_at, blown->blown_id)))
        blown = &lane;
    if (blown)
      throw InstabilityError(e_.sample.particles.id[blown->blown_id], blown->blown_at, "position",
                             blown->blown_x);
    leaving_.clear();
    for (Lane& lane : lanes_) {
      leaving_.insert(leaving_.end(), lane.leaving.begin(), lane.leaving.end());
      lane.leaving.clear();
      failed_.insert(failed_.end(), lane.failed.begin(), lane.failed.end());
      lane.failed.clear();
    }
    std::sort(leaving_.begin(), leaving_.end(), [](const Lane::Leaving& a, const Lane::Leaving& b) {
      return std::pair(a.t, a.id) < std::pair(b.t, b.id);
    });
    for (const Lane::Leaving& g : leaving_) {
      if (g.at.y + 0.5 * e_.sample.particles.diameter[g.id] < retire_height_) {
        retire(g.id, g.t, g.at);
        continue;
      }
      move_deposit(g.id, g.at.x, g.at.y);
      if (!coast(g.id, g.t, g.at, true)) failed_.push_back(g.id);
    }
    // A grain that crossed into another lane may be due again before the target there.
    const bool due = std::any_of(lanes_.begin(), lanes_.end(), [&](Lane& lane) {
      return !lane.syncs.empty() && lane.syncs.front().first <= target;
    });
    if (!due) return;
  }
}

// With no member moving, a step would take every sync due within max_step_s: the step ends
// instead where some lane has taken its share of kIdleStepSyncs (a step is the engine's unit of
// stopping). Syncs at the horizon's time are all taken.
double LocalStepper::idle_horizon(double target) {
  const std::size_t share = std::max<std::size_t>(1, kIdleStepSyncs / lanes_.size());
  double horizon = target;
  for (Lane& lane : lanes_) horizon = lane.syncs.nth_time(share, horizon);
  return horizon;
}

// The lanes' counts into the engine's statistics.
void LocalStepper::count_lanes() {
  for (Lane& lane : lanes_) {
    e_.stats.particle_steps += lane.particle_steps;
    e_.stats.windows += lane.windows;
    lane.particle_steps = 0;
    lane.windows = 0;
  }
}

}  // namespace sedem
