// Local time stepping of the exponential integrator (integrator.local_steps).
//
// A grain that touches nothing moves on an exact trajectory (free_flight.h): weight, buoyancy
// and a drag held constant. The common step exists only so that no grain passes through
// another between two looks. So a grain that provably cannot reach any other grain, wall or
// the bed for a while need not share it: it *coasts* over a window of its own, evaluated
// exactly at any time inside it, and is looked at again only at the window's end (its
// *sync*), where its drag and the voidage it feels are taken anew.
//
// Proof that nothing is missed: every grain holds a box in a BoxRegistry that it cannot leave
// before it is looked at again — a coasting grain the box its trajectory sweeps over its
// window, a member of the common step its position with an allowance of kAllowance radii
// (re-anchored once it has used kReanchor of them; it moves at most crossing_fraction < 1 radius
// a step), a settled grain its disc — each widened by (1 + kSkin) radii. A window is chosen so
// that its box overlaps no other box and no wall; the longest such window up to
// integrator.max_coast_s, halved until it fits. A grain that cannot coast even over its own
// crossing time joins the common step (it is *engaged*), and whatever its box then overlaps
// joins with it: coasting grains at their exact position now, settled ones as frozen members.
// Members that touch nothing leave again as soon as a window fits (checked every
// kReleaseEvery steps); frozen members that no moving member can reach go back to the bed.
//
// The common step is the exponential integrator's, unchanged, over the members only: contacts,
// the bed and freezing are exactly those of the global scheme. Syncs are taken in time order
// from a heap; a step of the members ends early at a sync that engages, so that every grain
// joins the common step at the members' time. The voidage grid is kept up to date grain by
// grain (each sync or member step moves the grain's deposit when it changes cell), instead of
// being computed anew each step. The scheme is serial: its work is in syncs of O(log n) each,
// taken in one order, so a run is the same whatever the thread count.
//
// Below the lowest instrument (integrator.retire_below_instruments) a grain *retires*: nothing
// there can rise back into an instrument's reach, so it leaves the dynamics and falls freely
// onto a coarse bed (columns one largest grain wide, each raised by the area of the grains
// that land in it at a packing of kBedPacking), where it is drawn without contacts.

#include <algorithm>
#include <cmath>
#include <functional>
#include <istream>
#include <numbers>
#include <ostream>
#include <stdexcept>
#include <string>

#include "core/engine/engine.h"
#include "core/engine/state/checkpoint_io.h"
#include "core/physics/stokes.h"

namespace sedem {

namespace {

constexpr double kSkin = 0.5;        // boxes are widened by (1 + kSkin) radii
constexpr double kAllowance = 3.0;   // a member's box lets it travel this many radii
constexpr double kReanchor = 1.0;    // and moves with it once it has travelled this many
constexpr double kConverged = 1e-3;  // relative gap to the terminal velocity of a long window
constexpr double kResponses = 8.0;   // response times of a window still converging
constexpr double kTravel = 0.5;      // longest travel of a window, in mean spacings
constexpr std::int64_t kReleaseEvery = 16;
constexpr double kBedPacking = 0.8;  // area fraction of the coarse bed (discs packed at random)
constexpr std::uint32_t kNoMember = 0xFFFFFFFF;

using Sync = std::pair<double, std::uint32_t>;
constexpr auto kLater = std::greater<Sync>{};

}  // namespace

// Without suspension contacts, a grain that is coasting or moving with the members passes any
// other such grain: only the walls, the bed (frozen and settled grains) and, among the
// members, the contacts the projection finds stop it.
bool Engine::passes(std::uint32_t j) const {
  return !model_.suspension_contacts && (kind_[j] == kCoasting || kind_[j] == kMoving);
}

// A coasting grain's box, which nothing looks at when the free grains pass each other: then it
// holds none (a million long boxes filled the registry's cells with a hundred bytes a grain).
void Engine::hold_coasting_box(std::uint32_t id, const Box& box) {
  if (model_.suspension_contacts)
    boxes_.set(id, box, kCoasting);
  else
    boxes_.clear(id);
}

FreeFlight Engine::flight_of(std::uint32_t id, const FreeFlight::Point& p) const {
  const Particles& s = sample_.particles;
  const double d = s.diameter[id], mass = model_.mass(d);
  const double c = drag_.coefficient(d, s.weight[id], std::hypot(p.vx, p.vy), p.x, p.y);
  FreeFlight f{p.x, p.y, p.vx, p.vy, 0, 0, 0};
  const double force = model_.gravity_force(d);
  if (c > 0) {
    f.rate = c / mass;
    f.uy = force / c;
  } else {
    f.uy = force / mass;
  }
  return f;
}

// The longest window (up to max_coast_s) over which grain id, at p at time t, can coast
// without its box meeting another or a wall; with `commit`, takes it. False: none as long as
// its own crossing time (and nothing was changed; `needed`, if given, is then the box of that
// shortest window).
bool Engine::coast(std::uint32_t id, double t, const FreeFlight::Point& p, bool commit,
                   Box* needed) {
  const FreeFlight f = flight_of(id, p);
  const double r = 0.5 * sample_.particles.diameter[id], pad = r * (1 + kSkin);
  const double hw = model_.half_width;
  double window = setup_.integrator.max_coast;
  const double gap = std::hypot(f.vx - f.ux, f.vy - f.uy), terminal = std::hypot(f.ux, f.uy);
  // Di Felice drag depends on the speed: far from its terminal velocity a grain's drag is
  // taken again after a few response times, as the global step would.
  if (model_.drag == DragLaw::di_felice && f.rate > 0 && gap > kConverged * terminal)
    window = std::min(window, kResponses / f.rate);
  auto box = [&](double w) {
    const FreeFlight::Range g = f.sweep(w);
    return Box{g.x0 - pad, g.x1 + pad, g.y0 - pad, g.y1 + pad};
  };
  auto take = [&](double w) {
    if (!commit) return true;
    flight_[id] = f;
    t0_[id] = t;
    t1_[id] = t + w;
    kind_[id] = kCoasting;
    if (model_.contact) hold_coasting_box(id, box(w));
    syncs_.emplace_back(t + w, id);
    std::push_heap(syncs_.begin(), syncs_.end(), kLater);
    // Windows cut short (a grain synced early, engaged or retired) leave their entries behind
    // until their time comes: past 1.25 times the grains, the stale ones go (the heap pops in the
    // same order either way: entries compare by time, then id).
    if (syncs_.size() > kind_.size() + kind_.size() / 4 + 1024) {
      std::erase_if(syncs_, [&](const Sync& e) {
        return kind_[e.second] != kCoasting || t1_[e.second] != e.first;
      });
      std::make_heap(syncs_.begin(), syncs_.end(), kLater);
    }
    ++stats_.windows;
    return true;
  };
  if (!model_.contact) return take(window);

  const double speed = f.rate > 0 ? std::max(std::hypot(f.vx, f.vy), terminal)
                                  : std::hypot(f.vx, f.vy) + terminal * window;
  // A window's box stays within a fraction of the mean spacing: long boxes would crowd the
  // space the others need for theirs and engage grains that are nowhere near each other.
  // Without suspension contacts the free grains do not look at it, and the window is
  // bounded by the voidage grid instead: the drag is taken anew about once per cell crossed.
  if (speed > 0) window = std::min(window, travel_ / speed);
  const double shortest =
      speed > 0 ? std::min(window, setup_.integrator.crossing_fraction * r / speed) : window;
  near_.clear();
  boxes_.overlapping(box(window), id, [&](std::uint32_t j) {
    if (!passes(j)) near_.push_back(j);
  });
  for (double w = window; w >= shortest; w *= 0.5) {
    const Box b = box(w);
    if (b.x0 <= -hw || b.x1 >= hw || b.y0 <= 0) continue;
    bool clear = true;
    for (std::uint32_t j : near_)
      if (b.overlaps(boxes_.box(j))) {
        clear = false;
        break;
      }
    if (clear) return take(w);
  }
  if (needed) *needed = box(shortest);
  return false;
}

// Grain id, synced at t, found no window because its shortest box meets the boxes of coasting
// grains. Those boxes hold the grains' whole windows, long for slow grains, though the grains
// themselves may be far from id now: each of them is synced early, at t, which its exact
// trajectory allows, and takes a new window once id holds its own. True: id coasts (the grains
// that cannot are in failed_). False: something else is in the way (a member, a wall, a grain
// already close), and nothing was changed.
bool Engine::make_room(std::uint32_t id, double t, const FreeFlight::Point& p) {
  Box needed;
  if (coast(id, t, p, false, &needed)) return false;  // not called for a grain that can coast
  const double hw = model_.half_width;
  if (needed.x0 <= -hw || needed.x1 >= hw || needed.y0 <= 0) return false;
  const Particles& s = sample_.particles;
  room_.clear();
  bool movable = true;
  boxes_.overlapping(needed, id, [&](std::uint32_t j) {
    if (!movable) return;
    if (kind_[j] != kCoasting || t0_[j] > t || t1_[j] <= t) {
      movable = false;
      return;
    }
    const FreeFlight::Point q = coasting_at(j, t);
    const double pad = 0.5 * s.diameter[j] * (1 + kSkin);
    movable = !needed.overlaps(Box{q.x - pad, q.x + pad, q.y - pad, q.y + pad});
    room_.push_back({j, q, Box{}, 0.0});
  });
  if (!movable || room_.empty()) return false;
  std::sort(room_.begin(), room_.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
  for (Room& m : room_) {
    m.before = boxes_.box(m.id);
    m.t0 = t0_[m.id];
    const double pad = 0.5 * s.diameter[m.id] * (1 + kSkin);
    hold_coasting_box(m.id, Box{m.at.x - pad, m.at.x + pad, m.at.y - pad, m.at.y + pad});
    t1_[m.id] = HUGE_VAL;  // its heap entry is stale
  }
  const Box before = boxes_.box(id);
  const double t0_before = t0_[id];
  const bool coasting = coast(id, t, p, true);
  if (coasting) note_ahead(id, t, before, t0_before);
  for (const Room& m : room_) {
    stats_.particle_steps += 1;
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
void Engine::note_ahead(std::uint32_t id, double t, const Box& before, double t0_before) {
  if (!model_.contact) return;
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
FreeFlight::Point Engine::coasting_at(std::uint32_t id, double t) const {
  const FreeFlight& f = flight_[id];
  const double s = t - t0_[id];
  if (s >= 0) return f.at(s);
  return {f.x + s * f.vx, f.y + s * f.vy, f.vx, f.vy};
}

Box Engine::member_box(std::size_t k) const {
  const double r = 0.5 * state_.diameter[k];
  const double reach = r * (1 + kSkin) + (state_.frozen[k] ? 0.0 : kAllowance * r);
  return Box{state_.x[k] - reach, state_.x[k] + reach, state_.y[k] - reach, state_.y[k] + reach};
}

void Engine::move_deposit(std::uint32_t id, double x, double y) {
  if (model_.drag != DragLaw::di_felice) return;
  const std::size_t c = voidage_.cell(x, y);
  if (c == deposit_cell_[id]) return;
  const double d = sample_.particles.diameter[id];
  const double volume = sample_.particles.weight[id] * model_.volume(d);
  voidage_.deposit(deposit_cell_[id], -volume);
  voidage_.deposit(c, volume);
  deposit_cell_[id] = std::uint32_t(c);
}

// Grain id (coasting, or taken out of the members) leaves the dynamics at p at time t: it falls
// freely from there onto the top of its column of the coarse bed, which rises by its area.
void Engine::retire(std::uint32_t id, double t, const FreeFlight::Point& p) {
  const double r = 0.5 * sample_.particles.diameter[id];
  const double hw = model_.half_width;
  const long columns = long(bed_.size());
  const long c = std::clamp(long((p.x + hw) / bed_column_), 0L, columns - 1);
  // It comes to rest in the lowest column within two of its own (nearest first): a pile
  // spreads, where one column for each grain would grow towers.
  long to = c;
  for (long k : {c - 1, c + 1, c - 2, c + 2})
    if (k >= 0 && k < columns && bed_[std::size_t(k)] < bed_[std::size_t(to)]) to = k;
  const double land = std::min(p.y, bed_[std::size_t(to)] + r);
  bed_[std::size_t(to)] += std::numbers::pi * r * r / (bed_column_ * kBedPacking);
  flight_[id] = flight_of(id, p);
  t0_[id] = t;
  // A retired grain has no window (its heap entry, if any, is stale): t1_ holds the x of its
  // place on the bed.
  t1_[id] = std::clamp(p.x + double(to - c) * bed_column_, -hw + r, hw - r);
  land_y_[id] = land;
  kind_[id] = kRetired;
  if (model_.contact) boxes_.clear(id);
  move_deposit(id, t1_[id], land);
  ++stats_.retired;
}

FreeFlight::Point Engine::retired_at(std::uint32_t id, double t) const {
  const FreeFlight::Point q = flight_[id].at(std::max(0.0, t - t0_[id]));
  if (q.y > land_y_[id]) return q;
  return {t1_[id], land_y_[id], 0, 0};
}

// Members (moving or frozen) whose disc is wholly below the retirement height retire.
void Engine::retire_members() {
  wake_.clear();
  for (std::size_t k = 0; k < state_.size(); ++k)
    if (state_.y[k] + 0.5 * state_.diameter[k] < retire_height_) wake_.push_back(state_.origin[k]);
  std::sort(wake_.begin(), wake_.end());
  for (std::uint32_t id : wake_) {
    const std::size_t k = member_[id];
    const bool frozen = state_.frozen[k] != 0;
    const FreeFlight::Point p{state_.x[k], state_.y[k], frozen ? 0.0 : state_.vx[k],
                              frozen ? 0.0 : state_.vy[k]};
    remove_member(k);
    member_[id] = kNoMember;
    retire(id, time_, p);
  }
  wake_.clear();
}

// Grain id joins the common step at p (at the members' time): appended to the state, its box
// registered by wake_around.
void Engine::engage(std::uint32_t id, const FreeFlight::Point& p, bool frozen) {
  if (kind_[id] == kMoving || kind_[id] == kFrozen) return;  // a member already
  const Particles& s = sample_.particles;
  const std::size_t k = state_.size();
  state_.resize(k + 1);
  state_.x[k] = p.x;
  state_.y[k] = p.y;
  state_.vx[k] = frozen ? 0.0 : p.vx;
  state_.vy[k] = frozen ? 0.0 : p.vy;
  state_.omega[k] = 0;
  state_.diameter[k] = s.diameter[id];
  state_.weight[k] = s.weight[id];
  state_.origin[k] = id;
  state_.frozen[k] = frozen ? 1 : 0;
  const double reach = model_.lubrication_reach();
  search_.push_back(0.5 * s.diameter[id] * (1 + reach + model_.skin + margin_));
  x0_.push_back(p.x);
  y0_.push_back(p.y);
  forces_.stiffness.push_back(0.0);
  member_[id] = std::uint32_t(k);
  kind_[id] = frozen ? kFrozen : kMoving;
  move_deposit(id, p.x, p.y);
  members_changed_ = true;
  ++stats_.engaged;
  wake_.push_back(id);
}

// Registers the boxes of the grains just engaged; whatever a moving one's box overlaps joins
// too (coasting grains where they are now, settled ones frozen), until nothing more does.
void Engine::wake_around(std::uint32_t first) {
  if (first != kNoMember) wake_.push_back(first);
  std::vector<std::uint32_t>& found = found_;
  while (!wake_.empty()) {
    const std::uint32_t id = wake_.back();
    wake_.pop_back();
    const std::size_t k = member_[id];
    anchor(k);
    if (state_.frozen[k]) continue;
    found.clear();
    boxes_.overlapping(boxes_.box(id), id, [&](std::uint32_t j) {
      if ((kind_[j] == kCoasting && !passes(j)) || kind_[j] == kSettled) found.push_back(j);
    });
    std::sort(found.begin(), found.end());
    const Box reach = boxes_.box(id);
    for (std::uint32_t j : found) {
      if (kind_[j] == kCoasting) {
        if (!resync_clear_of(j, reach)) engage(j, coasting_at(j, time_), false);
      } else {
        const FreeFlight& f = flight_[j];
        --settled_;
        engage(j, FreeFlight::Point{f.x, f.y, 0, 0}, true);
      }
    }
  }
}

// A coasting grain whose box (its whole window) meets `reach` though the grain itself is clear
// of it now: synced now, at the members' time, it may take a new window clear of `reach`.
// True if it did (or retired); false: it is to join the members, and nothing was changed.
bool Engine::resync_clear_of(std::uint32_t j, const Box& reach) {
  if (!model_.contact || t0_[j] > time_ || t1_[j] <= time_) return false;
  const FreeFlight::Point q = coasting_at(j, time_);
  const double r = 0.5 * sample_.particles.diameter[j], pad = r * (1 + kSkin);
  const Box disc{q.x - pad, q.x + pad, q.y - pad, q.y + pad};
  if (disc.overlaps(reach)) return false;
  if (q.y + r < retire_height_) {
    retire(j, time_, q);
    return true;
  }
  const Box old = boxes_.box(j);
  hold_coasting_box(j, disc);
  if (coast(j, time_, q, true)) {
    stats_.particle_steps += 1;
    move_deposit(j, q.x, q.y);
    return true;
  }
  hold_coasting_box(j, old);
  return false;
}

void Engine::anchor(std::size_t k) {
  const std::uint32_t id = state_.origin[k];
  flight_[id].x = state_.x[k];
  flight_[id].y = state_.y[k];
  if (model_.contact) boxes_.set(id, member_box(k), state_.frozen[k] ? kFrozen : kMoving);
}

void Engine::remove_member(std::size_t k) {
  const std::size_t last = state_.size() - 1;
  if (k != last) {
    for (auto* v : {&state_.x, &state_.y, &state_.vx, &state_.vy, &state_.omega, &state_.diameter,
                    &state_.weight, &search_, &x0_, &y0_, &forces_.stiffness})
      (*v)[k] = (*v)[last];
    state_.origin[k] = state_.origin[last];
    state_.frozen[k] = state_.frozen[last];
    member_[state_.origin[k]] = std::uint32_t(k);
  }
  state_.resize(last);
  search_.resize(last);
  x0_.resize(last);
  y0_.resize(last);
  forces_.stiffness.resize(last);
  members_changed_ = true;
}

// Moving members that touch nothing coast again where a window fits.
void Engine::release_members() {
  std::vector<std::uint32_t> free;
  for (std::size_t k = 0; k < state_.size(); ++k)
    if (!state_.frozen[k] && forces_.stiffness[k] == 0) free.push_back(state_.origin[k]);
  std::sort(free.begin(), free.end());
  for (std::uint32_t id : free) {
    const std::size_t k = member_[id];
    const FreeFlight::Point p{state_.x[k], state_.y[k], state_.vx[k], state_.vy[k]};
    // A window of one crossing time is enough: requiring four cut the churn of grains leaving
    // and rejoining, but kept settling grains on the common step and let a spreading pile's
    // overlaps reach 0.7 of a radius (DensePileHasNoDeepOverlap).
    if (!coast(id, time_, p, true)) continue;
    remove_member(k);
    member_[id] = kNoMember;
    ++stats_.released;
  }
}

// Frozen members that no moving member can reach go back to the bed, out of the state.
void Engine::settle_members() {
  std::vector<std::uint32_t> frozen;
  for (std::size_t k = 0; k < state_.size(); ++k)
    if (state_.frozen[k]) {
      anchor(k);
      frozen.push_back(state_.origin[k]);
    }
  std::sort(frozen.begin(), frozen.end());
  for (std::uint32_t id : frozen) {
    bool reachable = false;
    boxes_.overlapping(boxes_.box(id), id,
                       [&](std::uint32_t j) { reachable = reachable || kind_[j] == kMoving; });
    if (reachable) continue;
    const std::size_t k = member_[id];
    flight_[id] = FreeFlight{state_.x[k], state_.y[k], 0, 0, 0, 0, 0};
    kind_[id] = kSettled;
    ++settled_;
    boxes_.set(id, boxes_.box(id), kSettled);
    remove_member(k);
    member_[id] = kNoMember;
  }
}

void Engine::index_members() {
  for (std::size_t k = 0; k < state_.size(); ++k) member_[state_.origin[k]] = std::uint32_t(k);
}

void Engine::start_local() {
  const Particles& s = sample_.particles;
  const std::size_t n = s.size();
  kind_.assign(n, kCoasting);
  flight_.assign(n, FreeFlight{});
  t0_.assign(n, 0.0);
  t1_.assign(n, 0.0);
  member_.assign(n, kNoMember);
  deposit_cell_.assign(n, 0);
  syncs_.clear();
  const Cylinder& cyl = setup_.cylinder;
  double dmax = 0;
  for (double d : s.diameter) dmax = std::max(dmax, d);
  // Cells about twice the mean spacing: a box spans a few of them and each holds a few boxes.
  const double spacing =
      std::sqrt(2 * cyl.half_width() * cyl.height / double(std::max<std::size_t>(n, 1)));
  travel_ = model_.suspension_contacts ? kTravel * spacing
                                       : std::max(kTravel * spacing, setup_.forces.voidage_cell);
  registry_cell_ = std::max(spacing, 4 * dmax);
  land_y_.assign(n, 0.0);
  ahead_slot_.assign(n, kNoMember);
  widened_.clear();
  bed_column_ = std::max(dmax, 1e-9);
  bed_.assign(std::max<std::size_t>(1, std::size_t(std::ceil(2 * cyl.half_width() / bed_column_))),
              0.0);
  stats_.retired = 0;
  if (model_.contact) boxes_.configure(registry_cell_, cyl.half_width(), cyl.height, n);
  if (model_.drag == DragLaw::di_felice) {
    voidage_.compute(n, state_.x.data(), state_.y.data(), state_.diameter.data(),
                     state_.weight.data());
    for (std::uint32_t id = 0; id < n; ++id)
      deposit_cell_[id] = std::uint32_t(voidage_.cell(state_.x[id], state_.y[id]));
  }
  // Every grain first holds its disc, as if settled, so that the first windows see them all.
  std::vector<FreeFlight::Point> start(n);
  for (std::uint32_t id = 0; id < n; ++id) {
    start[id] = {state_.x[id], state_.y[id], state_.vx[id], state_.vy[id]};
    flight_[id] = FreeFlight{start[id].x, start[id].y, start[id].vx, start[id].vy, 0, 0, 0};
    const double pad = 0.5 * s.diameter[id] * (1 + kSkin);
    if (model_.contact)
      hold_coasting_box(
          id, Box{start[id].x - pad, start[id].x + pad, start[id].y - pad, start[id].y + pad});
  }
  // The state holds the members only, a few thousand at most: the room it had for every
  // grain (a sixth of the memory at a million particles) goes back.
  state_ = EngineState{};
  forces_ = ForceAccumulators{};
  std::vector<double>().swap(search_);
  std::vector<double>().swap(x0_);
  std::vector<double>().swap(y0_);
  for (std::uint32_t id = 0; id < n; ++id)
    if (start[id].y + 0.5 * s.diameter[id] < retire_height_) retire(id, 0.0, start[id]);
  for (std::uint32_t id = 0; id < n; ++id) {
    if (kind_[id] != kCoasting) continue;  // engaged by a neighbour already, or retired
    if (coast(id, 0.0, start[id], true)) continue;
    engage(id, start[id], false);
    wake_around(kNoMember);
  }
  index_members();
  lists_stale_ = true;
  members_changed_ = false;
  integrator_->refresh_step(state_);
  stats_.members = state_.size();
}

void Engine::step_local(double limit) {
  auto count_moving = [&] {
    std::size_t m = 0;
    for (std::uint8_t f : state_.frozen) m += f == 0;
    return m;
  };
  std::size_t moving = count_moving();
  double dt = moving ? integrator_->next_step(facts_) : setup_.integrator.max_step;
  double target = time_ + dt >= limit ? limit : time_ + dt;
  // Syncs due within the step, in time order. A grain that cannot coast on joins the members
  // at their time, before they step, where its last window put it then (coasting_at). So no
  // member step is cut short by a sync (steps of a few ns would turn the projection's
  // corrections into runaway speeds).
  ahead_.clear();
  for (;;) {
    failed_.clear();
    while (!syncs_.empty() && syncs_.front().first <= target) {
      const auto [t, id] = syncs_.front();
      std::pop_heap(syncs_.begin(), syncs_.end(), kLater);
      syncs_.pop_back();
      if (kind_[id] != kCoasting || t1_[id] != t) continue;  // engaged since: stale
      const FreeFlight::Point p = flight_[id].at(t - t0_[id]);
      if (!std::isfinite(p.x + p.y + p.vx + p.vy))
        throw InstabilityError(sample_.particles.id[id], t, "position", p.x);
      stats_.particle_steps += 1;
      if (p.y + 0.5 * sample_.particles.diameter[id] < retire_height_) {
        retire(id, t, p);
        continue;
      }
      move_deposit(id, p.x, p.y);
      const Box before = model_.contact ? boxes_.box(id) : Box{};
      const double t0_before = t0_[id];
      if (coast(id, t, p, true)) {
        note_ahead(id, t, before, t0_before);
        continue;
      }
      if (model_.contact && make_room(id, t, p)) {
        if (failed_.empty()) continue;
        break;  // a grain it moved could not coast: the members' step is chosen again with it
      }
      t1_[id] = HUGE_VAL;  // its heap entry, if any, is stale
      failed_.push_back(id);
      break;  // the members' step is chosen again with it
    }
    if (failed_.empty()) break;
    // The members' step may shrink now, below the time of grains already synced within it:
    // their box covers their path from the members' time on, the old window's part included,
    // until their next sync. (Taken before the new members' boxes look for what they reach.)
    for (Ahead& a : ahead_) {
      if (a.widened || kind_[a.id] != kCoasting || t0_[a.id] != a.time) continue;
      hold_coasting_box(a.id, a.after.merged(a.before));
      a.widened = true;
    }
    for (std::uint32_t id : failed_)
      if (kind_[id] == kCoasting) engage(id, coasting_at(id, time_), false);
    wake_around(kNoMember);
    lists_stale_ = true;
    index_members();
    integrator_->refresh_step(state_);
    members_changed_ = false;
    moving = count_moving();
    dt = moving ? integrator_->next_step(facts_) : setup_.integrator.max_step;
    target = time_ + dt >= limit ? limit : time_ + dt;
    // Syncs still due before the new target are taken in the next round: no window may end
    // unlooked-at while the members step past it.
  }
  // Those synced within the step after all need their new box only; the others once the
  // members have passed their sync (until then a grain synced after them may be where their
  // old box was, which is what the widened boxes allow).
  for (const Ahead& a : ahead_)
    if (a.widened && kind_[a.id] == kCoasting && t0_[a.id] == a.time) {
      if (a.time <= target)
        hold_coasting_box(a.id, a.after);
      else
        widened_.push_back(a);
    }

  if (moving && target > time_) {
    if (lists_stale_) {
      if (stats_.steps - resorted_at_ >= 16) {
        resort();
        resorted_at_ = stats_.steps;
      }
      rebuild_lists();
      index_members();
    }
    Blowup blowup;
    integrator_->advance(state_, forces_, target - time_, blowup);
    integrator_->contact_facts(facts_);
    stats_.particle_steps += double(moving);
    stats_.contacts = facts_.contacts;
    stats_.max_overlap_ratio = std::max(stats_.max_overlap_ratio, facts_.max_overlap_ratio);
    if (blowup.found)
      throw InstabilityError(sample_.particles.id[blowup.particle], target, blowup.quantity,
                             blowup.value);
    lists_stale_ = lists_stale_ || moved_beyond_margin();
    for (std::size_t k = 0; k < state_.size(); ++k)
      if (!state_.frozen[k]) move_deposit(state_.origin[k], state_.x[k], state_.y[k]);
  }
  stats_.last_step = target - time_;
  time_ = target;
  stats_.steps += 1;
  if (!widened_.empty()) {
    std::size_t kept = 0;
    for (const Ahead& a : widened_) {
      if (kind_[a.id] != kCoasting || t0_[a.id] != a.time) continue;  // synced again since
      if (a.time <= time_)
        hold_coasting_box(a.id, a.after);
      else
        widened_[kept++] = a;
    }
    widened_.resize(kept);
  }

  if (moving) {
    // Which members touch something, from this step's projection, before any joins or leaves.
    if (stats_.steps % kReleaseEvery == 0) integrator_->mark_touching(forces_.stiffness);
    if (retire_height_ > 0) retire_members();
    // Members that used their allowance take a new box; whatever it reaches joins them.
    for (std::size_t k = 0; k < state_.size(); ++k) {
      if (state_.frozen[k]) continue;
      const std::uint32_t id = state_.origin[k];
      const double moved = std::hypot(state_.x[k] - flight_[id].x, state_.y[k] - flight_[id].y);
      if (moved > kReanchor * 0.5 * state_.diameter[k]) wake_.push_back(id);
    }
    wake_around(kNoMember);
    if (freeze_height_ > 0 && stats_.steps % 64 == 0) {
      freeze_resting();
      settle_members();
      stats_.frozen = settled_;
      for (std::uint8_t f : state_.frozen) stats_.frozen += f;
    }
    if (stats_.steps % kReleaseEvery == 0) release_members();
  }
  if (members_changed_) {
    lists_stale_ = true;
    index_members();
    integrator_->refresh_step(state_);
    members_changed_ = false;
  }
  stats_.members = state_.size();
}

void Engine::save_local(std::ostream& out) const {
  write_vector(out, kind_);
  write_vector(out, flight_);
  write_vector(out, t0_);
  write_vector(out, t1_);
  write_vector(out, deposit_cell_);
  write_vector(out, voidage_.solid());
  std::vector<Box> boxes(kind_.size());
  std::vector<std::uint8_t> kinds(kind_.size(), BoxRegistry::kNone);
  if (model_.contact)
    for (std::uint32_t id = 0; id < kind_.size(); ++id)
      if (boxes_.has(id)) {
        boxes[id] = boxes_.box(id);
        kinds[id] = boxes_.kind(id);
      }
  write_vector(out, boxes);
  write_vector(out, kinds);
  write_vector(out, land_y_);
  write_vector(out, bed_);
  std::vector<double> widened;  // id, sync time, the window's box (the old one is in boxes)
  for (const Ahead& a : widened_)
    widened.insert(widened.end(),
                   {double(a.id), a.time, a.after.x0, a.after.x1, a.after.y0, a.after.y1});
  write_vector(out, widened);
}

void Engine::load_local(std::istream& in) {
  read_vector(in, kind_);
  read_vector(in, flight_);
  read_vector(in, t0_);
  read_vector(in, t1_);
  read_vector(in, deposit_cell_);
  std::vector<double> solid(voidage_.solid().size());
  read_vector(in, solid);
  voidage_.set_solid(solid);
  std::vector<Box> boxes(kind_.size());
  std::vector<std::uint8_t> kinds(kind_.size());
  read_vector(in, boxes);
  read_vector(in, kinds);
  read_vector(in, land_y_);
  read_vector(in, bed_);
  std::vector<double> widened;
  read_vector_upto(in, widened, 6 * std::uint64_t(kind_.size()));
  widened_.clear();
  for (std::size_t k = 0; k + 6 <= widened.size(); k += 6) {
    const double id = widened[k];
    if (!(id >= 0 && id < double(kind_.size())))
      throw std::runtime_error("damaged checkpoint: a widened box names no grain");
    widened_.push_back({std::uint32_t(id), widened[k + 1], Box{},
                        Box{widened[k + 2], widened[k + 3], widened[k + 4], widened[k + 5]}, true});
  }
  if (land_y_.size() != kind_.size() || bed_.empty())
    throw std::runtime_error("damaged checkpoint: the coarse bed does not fit the sample");
  for (std::size_t id = 0; id < kind_.size(); ++id) {
    const FreeFlight& f = flight_[id];
    const bool finite = std::isfinite(f.x + f.y + f.vx + f.vy + f.rate + f.ux + f.uy + t0_[id]) &&
                        !std::isnan(t1_[id]) && f.rate >= 0;
    if (kind_[id] > kRetired || !finite || !std::isfinite(land_y_[id]) ||
        deposit_cell_[id] >= voidage_.cell_count() ||
        (kinds[id] != BoxRegistry::kNone && kinds[id] > kSettled))
      throw std::runtime_error("damaged checkpoint: grain " + std::to_string(id) +
                               " has a bad local-step state");
  }
  for (std::uint32_t id : state_.origin)
    if (id >= kind_.size() || (kind_[id] != kMoving && kind_[id] != kFrozen))
      throw std::runtime_error("damaged checkpoint: a member is not marked as one");
  if (model_.contact) {
    const Cylinder& cyl = setup_.cylinder;
    boxes_.configure(registry_cell_, cyl.half_width(), cyl.height, kind_.size());
    for (std::uint32_t id = 0; id < kind_.size(); ++id)
      if (kinds[id] != BoxRegistry::kNone) boxes_.set(id, boxes[id], kinds[id]);
  }
  syncs_.clear();
  for (std::uint32_t id = 0; id < kind_.size(); ++id)
    if (kind_[id] == kCoasting) syncs_.emplace_back(t1_[id], id);
  std::make_heap(syncs_.begin(), syncs_.end(), kLater);
  member_.assign(kind_.size(), kNoMember);
  index_members();
  settled_ = std::size_t(std::count(kind_.begin(), kind_.end(), kSettled));
  forces_.stiffness.assign(state_.size(), 0.0);
}

// The scheme's promise, checked grain by grain (for tests; O(n) queries): every grain is
// inside its box, no coasting grain's window has ended, and only grains that the common step
// handles (members, and settled grains beside frozen ones) hold overlapping boxes. One
// exception: a grain synced ahead of the members in a step a joining grain then shortened
// keeps its old box too, where a grain synced after it may have passed since.
std::string Engine::local_violation() const {
  if (!local_ || !model_.contact) return {};
  const Particles& s = sample_.particles;
  const std::size_t n = kind_.size();
  auto where = [&](std::uint32_t id) {
    if (kind_[id] == kCoasting) return coasting_at(id, time_);
    if (kind_[id] == kSettled) return FreeFlight::Point{flight_[id].x, flight_[id].y, 0, 0};
    if (kind_[id] == kRetired) return retired_at(id, time_);
    const std::size_t k = member_[id];
    return FreeFlight::Point{state_.x[k], state_.y[k], 0, 0};
  };
  auto name = [&](std::uint32_t id) {
    static const char* const kinds[] = {"coasting", "moving", "frozen", "settled", "retired"};
    return "grain " + std::to_string(id) + " (" + kinds[kind_[id]] + ")";
  };
  for (std::uint32_t id = 0; id < n; ++id) {
    if (kind_[id] == kCoasting && t1_[id] < time_)
      return name(id) + ": its window ended at " + std::to_string(t1_[id]) + " s, before " +
             std::to_string(time_) + " s";
    if (kind_[id] == kRetired) {
      if (boxes_.has(id)) return name(id) + " holds a box";
      continue;
    }
    if (!boxes_.has(id) && passes(id)) continue;  // a free grain that meets none
    const FreeFlight::Point p = where(id);
    const double r = 0.5 * s.diameter[id];
    const Box& b = boxes_.box(id);
    if (p.x - r < b.x0 || p.x + r > b.x1 || p.y - r < b.y0 || p.y + r > b.y1)
      return name(id) + " is outside its box";
  }
  for (std::uint32_t id = 0; id < n; ++id) {
    if (kind_[id] == kRetired) continue;
    std::string found;
    boxes_.overlapping(boxes_.box(id), id, [&](std::uint32_t j) {
      const int a = kind_[id], b = kind_[j];
      const bool ahead = (a == kCoasting && t0_[id] > time_) || (b == kCoasting && t0_[j] > time_);
      const bool passing = passes(id) && passes(j);
      const bool handled = ahead || passing ||
                           (a != kCoasting && b != kCoasting && !(a == kSettled && b == kMoving) &&
                            !(a == kMoving && b == kSettled));
      if (!handled && found.empty())
        found = "the boxes of " + name(id) + " and " + name(j) + " overlap";
    });
    if (!found.empty()) return found;
  }
  return {};
}

}  // namespace sedem
