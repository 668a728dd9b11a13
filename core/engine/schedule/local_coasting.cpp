#include "core/engine/schedule/local_stepper.h"

#include <algorithm>
#include <cmath>
#include <span>

namespace sedem {

// Without suspension contacts, a grain that is coasting or moving with the members passes any
// other such grain: only the walls, the bed (frozen and settled grains) and, among the
// members, the contacts the projection finds stop it.
bool LocalStepper::passes(std::uint32_t j) const {
  return !e_.model.suspension_contacts &&
         (kind_[j] == GrainKind::coasting || kind_[j] == GrainKind::moving);
}

// A coasting grain's box, which nothing looks at when the free grains pass each other: then it
// holds none (a million long boxes filled the registry's cells with a hundred bytes a grain).
void LocalStepper::hold_coasting_box(std::uint32_t id, const Box& box) {
  if (e_.model.suspension_contacts)
    boxes_.set(id, box, box_tag(GrainKind::coasting));
  else
    boxes_.clear(id);
}

// A coasting grain's box at one point of its path (a window's box holds it wherever it goes).
Box LocalStepper::coasting_disc(double x, double y, double diameter) {
  const double pad = 0.5 * diameter * (1 + kCoastSkin);
  return Box{x - pad, x + pad, y - pad, y + pad};
}

FreeFlight LocalStepper::flight_of(std::uint32_t id, const FreeFlight::Point& p,
                                   DragMemo* memo) const {
  return flight_with(id, p, drag_at(id, p, std::hypot(p.vx, p.vy), memo));
}

// `memo` (or nullptr): the grain's voidage found by an earlier look at the same point, read
// instead of its log and exponential where the cell's solids have not changed (the same bits).
double LocalStepper::drag_at(std::uint32_t id, const FreeFlight::Point& p, double speed,
                             DragMemo* memo) const {
  const Particles& s = e_.sample.particles;
  return e_.drag.coefficient(s.diameter[id], s.weight[id], speed, p.x, p.y, memo, id);
}

FreeFlight LocalStepper::flight_with(std::uint32_t id, const FreeFlight::Point& p, double c) const {
  const double d = e_.sample.particles.diameter[id], mass = e_.model.mass(d);
  FreeFlight f{p.x, p.y, p.vx, p.vy, 0, 0, 0};
  const double force = e_.model.gravity_force(d);
  if (c > 0) {
    f.rate = c / mass;
    f.uy = force / c;
  } else {
    f.uy = force / mass;
  }
  return f;
}

// Grain id at p, still far from its terminal velocity, with flight f: where its drag at the
// terminal speed f relaxes to is within integrator.coast_drag_change of the drag f holds, f
// takes the drag at its terminal speed instead, and true. That drag is found by looking at the
// law again at the speed it gives: each look brings it nearer the fixed point by the drag's
// slope in the speed (d ln c / d ln v, a few hundredths where the check passes), so the grain
// settles at its terminal velocity as the global step's would, to about 1e-7 of it.
bool LocalStepper::relax_drag(std::uint32_t id, const FreeFlight::Point& p, FreeFlight& f,
                              DragMemo* memo) const {
  const double tolerance = e_.setup.integrator.coast_drag_change;
  if (tolerance <= 0) return false;
  const double d = e_.sample.particles.diameter[id];
  const double held = f.rate * e_.model.mass(d), force = std::abs(e_.model.gravity_force(d));
  double c = drag_at(id, p, force / held, memo);
  if (std::abs(c - held) > tolerance * held) return false;
  c = drag_at(id, p, force / c, memo);
  f = flight_with(id, p, c);
  return true;
}

// The longest window (up to max_coast_s) over which grain id, at p at time t, can coast
// without its box meeting another or a wall; with `commit`, takes it. False: none as long as
// its own crossing time (and nothing was changed; `needed`, if given, is then the box of that
// shortest window).
bool LocalStepper::coast(std::uint32_t id, double t, const FreeFlight::Point& p, bool commit,
                         Box* needed, std::uint32_t* blocker) {
  // The drag is looked at up to three times at p (relax_drag): the voidage once.
  DragMemo memo;
  FreeFlight f = flight_of(id, p, &memo);
  const double r = 0.5 * e_.sample.particles.diameter[id], pad = r * (1 + kCoastSkin);
  const double hw = e_.model.half_width;
  Lane& lane = lanes_[lane_of(p.x)];
  double window = e_.setup.integrator.max_coast;
  const double gap = std::hypot(f.vx - f.ux, f.vy - f.uy);
  // Di Felice drag depends on the speed: far from its terminal velocity a grain's drag is
  // taken again after a few response times, as the global step would, unless the drag at the
  // speed it relaxes to differs from the one it holds by integrator.coast_drag_change or less
  // (it then coasts with that drag). At a low Reynolds number the drag hardly depends on the
  // speed (d ln c / d ln v is about 0.13 sqrt(Re)), and a voidage that had changed at their
  // syncs cut a quarter of sample 5's windows at 10^5 grains to a few response times,
  // microseconds for a fine grain (docs/results/engine.md, "Windows the drag allows").
  if (e_.model.drag == DragLaw::di_felice && f.rate > 0 &&
      gap > kConverged * std::hypot(f.ux, f.uy) && !relax_drag(id, p, f, &memo))
    window = std::min(window, kResponses / f.rate);
  const double terminal = std::hypot(f.ux, f.uy);
  auto box = [&](double w) {
    const FreeFlight::Range g = f.sweep(w);
    return Box{g.x0 - pad, g.x1 + pad, g.y0 - pad, g.y1 + pad};
  };
  // `swept`: the window's box, computed once by the caller (a sweep costs an exponential or
  // three); without contacts no box is held.
  auto take = [&](double w, const Box& swept) {
    if (!commit) return true;
    track_[id] = {f, t, t + w, track_[id].deposit_cell};
    // Sixty-four grains share a line of kind_, and lanes on two threads sync grains of
    // neighbouring ids: a grain already coasting is not written again.
    if (kind_[id] != GrainKind::coasting) kind_[id] = GrainKind::coasting;
    if (e_.model.contact) hold_coasting_box(id, swept);
    push_sync(lane, t + w, id);
    ++lane.windows;
    return true;
  };
  if (!e_.model.contact) return take(window, Box{});

  const double speed = f.rate > 0 ? std::max(std::hypot(f.vx, f.vy), terminal)
                                  : std::hypot(f.vx, f.vy) + terminal * window;
  // A window's box stays within integrator.coast_travel mean spacings (2): each window is a
  // sync, and most of a whole test's time at 10^5 grains went to the syncs at half a spacing,
  // while boxes much longer would crowd the space the others need for theirs where many grains
  // meet (at 3x10^5 grains in the first minute, 2 spacings took 1.05 times as long as half a
  // spacing; docs/results/engine.md, "Longer windows"). Without suspension contacts the free
  // grains do not look at it, and the window is bounded by the voidage grid instead: the drag
  // is taken anew about once per cell crossed.
  if (speed > 0) window = std::min(window, travel_ / speed);
  const double shortest =
      speed > 0 ? std::min(window, e_.setup.integrator.crossing_fraction * r / speed) : window;
  const Box longest = box(window);
  // Whether box b meets no wall and none of the boxes of `near`. If not, `in_way` is what
  // stood in its way (kNoMember: a wall).
  std::uint32_t in_way = kNoMember;
  auto clear = [&](std::span<const std::uint32_t> near, const Box& b) {
    in_way = kNoMember;
    if (b.x0 <= -hw || b.x1 >= hw || b.y0 <= 0) return false;
    for (std::uint32_t j : near)
      if (b.overlaps(boxes_.box(j))) {
        in_way = j;
        return false;
      }
    return true;
  };
  // Tries the windows longest first, halving down to the shortest, against the boxes of `near`;
  // true with the first clear one. False: none is, and `in_way` is what stood in the last
  // (shortest) one's way.
  auto first_clear = [&](std::span<const std::uint32_t> near, double& clear_w, Box& clear_b) {
    for (double w = window; w >= shortest; w *= 0.5) {
      const Box b = w == window ? longest : box(w);
      if (clear(near, b)) {
        clear_w = w;
        clear_b = b;
        return true;
      }
    }
    return false;
  };
  double w = 0;
  Box b;
  // A member that failed to leave mostly fails again for the same neighbour: if that one's
  // box (which the query would find: it meets the longest window's) is in every window's way,
  // the answer is known without the query, exactly.
  if (blocker && *blocker != kNoMember && *blocker != id && boxes_.has(*blocker) &&
      !passes(*blocker) && boxes_.box(*blocker).overlaps(longest)) {
    if (!first_clear({blocker, 1}, w, b)) {
      if (needed) *needed = box(shortest);
      return false;
    }
  }
  lane.near.clear();
  boxes_.overlapping(longest, id, [&](std::uint32_t j) {
    if (!passes(j)) lane.near.push_back(j);
  });
  if (first_clear(lane.near, w, b)) {
    // Halving found the clear length w and the blocked 2w: a window's box grows with its
    // length, so the longest clear one lies between, and kBisections looks narrow it down
    // (every sample's whole test at 10^5 took 1.09-1.16 times less: fewer syncs, and fewer
    // grains joining the members; docs/results/engine.md, "Windows between the halvings").
    if (w < window) {
      double blocked = std::min(2 * w, window);
      for (int k = 0; k < kBisections; ++k) {
        const double mid = 0.5 * (w + blocked);
        const Box m = box(mid);
        if (clear(lane.near, m)) {
          w = mid;
          b = m;
        } else {
          blocked = mid;
        }
      }
    }
    return take(w, b);
  }
  if (blocker) *blocker = in_way;
  if (needed) *needed = box(shortest);
  return false;
}

// Grain id, synced at t, found no window because its shortest box meets the boxes of coasting
// grains. Those boxes hold the grains' whole windows, long for slow grains, though the grains
// themselves may be far from id now: each of them is synced early, at t, which its exact
// trajectory allows, and takes a new window once id holds its own. True: id coasts (the grains
// that cannot are in failed_). False: something else is in the way (a member, a wall, a grain
// already close), and nothing was changed.
bool LocalStepper::make_room(std::uint32_t id, double t, const FreeFlight::Point& p) {
  Box needed;
  if (coast(id, t, p, false, &needed)) return false;  // not called for a grain that can coast
  const double hw = e_.model.half_width;
  if (needed.x0 <= -hw || needed.x1 >= hw || needed.y0 <= 0) return false;
  const Particles& s = e_.sample.particles;
  room_.clear();
  bool movable = true;
  boxes_.overlapping(needed, id, [&](std::uint32_t j) {
    if (!movable) return;
    if (kind_[j] != GrainKind::coasting || track_[j].t0 > t || track_[j].t1 <= t) {
      movable = false;
      return;
    }
    const FreeFlight::Point q = coasting_at(j, t);
    movable = !needed.overlaps(coasting_disc(q.x, q.y, s.diameter[j]));
    room_.push_back({j, q, Box{}, 0.0});
  });
  if (!movable || room_.empty()) return false;
  std::sort(room_.begin(), room_.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
  for (Room& m : room_) {
    m.before = boxes_.box(m.id);
    m.t0 = track_[m.id].t0;
    hold_coasting_box(m.id, coasting_disc(m.at.x, m.at.y, s.diameter[m.id]));
    track_[m.id].t1 = HUGE_VAL;  // its heap entry is stale
  }
  const Box before = boxes_.box(id);
  const double t0_before = track_[id].t0;
  const bool coasting = coast(id, t, p, true);
  if (coasting) note_ahead(id, t, before, t0_before);
  for (const Room& m : room_) {
    e_.stats.particle_steps += 1;
    if (m.at.y + 0.5 * s.diameter[m.id] < retire_height_) {
      retire(m.id, t, m.at);
      continue;
    }
    move_deposit(m.id, m.at.x, m.at.y);
    if (coast(m.id, t, m.at, true)) {
      note_ahead(m.id, t, m.before, m.t0);
    } else {
      // Joins the members at their time, on the window it had (still in flight_, from m.t0),
      // with its old box, which holds its path from then on.
      hold_coasting_box(m.id, m.before);
      failed_.push_back(m.id);
    }
  }
  return coasting;
}

// A grain synced at t, ahead of the members' time, with the box it had before: kept so that the
// box can be widened should the members' step shrink below t.
void LocalStepper::note_ahead(std::uint32_t id, double t, const Box& before, double t0_before) {
  if (!e_.model.contact) return;
  // Synced ahead twice within the step: its path from the members' time on lies in the box it
  // had before the first of the two syncs and in the window between.
  Box from = before;
  const std::uint32_t slot = ahead_slot_[id];
  if (slot < ahead_.size() && ahead_[slot].id == id && ahead_[slot].time == t0_before)
    from = ahead_[slot].before.merged(before);
  ahead_slot_[id] = std::uint32_t(ahead_.size());
  ahead_.push_back({id, t, from, boxes_.box(id), false});
}

// A coasting grain at time t. Inside its window, exactly. Before it (a grain synced ahead of the
// members within their step, joining them at their time), along the straight line of its
// velocity at the window's start: run backwards, the exponential would amplify the tiny gap to
// its terminal velocity by e^(dt/tau); that far back (less than a member step, so less than a
// crossing time) the grain is at its terminal velocity to round-off.
FreeFlight::Point LocalStepper::coasting_at(std::uint32_t id, double t) const {
  const FreeFlight& f = track_[id].flight;
  const double s = t - track_[id].t0;
  if (s >= 0) return f.at(s);
  return {f.x + s * f.vx, f.y + s * f.vy, f.vx, f.vy};
}

// A coasting grain whose box (its whole window) meets `reach` though the grain itself is clear
// of it now: synced now, at the members' time, it may take a new window clear of `reach`.
// True if it did (or retired); false: it is to join the members, and nothing was changed.
bool LocalStepper::resync_clear_of(std::uint32_t j, const Box& reach) {
  if (!e_.model.contact || track_[j].t0 > e_.time || track_[j].t1 <= e_.time) return false;
  const FreeFlight::Point q = coasting_at(j, e_.time);
  const double d = e_.sample.particles.diameter[j];
  const Box disc = coasting_disc(q.x, q.y, d);
  if (disc.overlaps(reach)) return false;
  if (q.y + 0.5 * d < retire_height_) {
    retire(j, e_.time, q);
    return true;
  }
  const Box old = boxes_.box(j);
  hold_coasting_box(j, disc);
  if (coast(j, e_.time, q, true)) {
    e_.stats.particle_steps += 1;
    move_deposit(j, q.x, q.y);
    return true;
  }
  hold_coasting_box(j, old);
  return false;
}

}  // namespace sedem
