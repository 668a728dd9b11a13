#include "core/engine/schedule/local_stepper.h"

#include <algorithm>
#include <vector>

namespace sedem {

// Grain id joins the common step at p (at the members' time): appended to the state, its box
// registered by wake_around.
void LocalStepper::engage(std::uint32_t id, const FreeFlight::Point& p, bool frozen) {
  if (is_member(kind_[id])) return;  // a member already
  const Particles& s = e_.sample.particles;
  const std::size_t k = e_.state.size();
  e_.state.resize(k + 1);
  e_.state.x[k] = p.x;
  e_.state.y[k] = p.y;
  e_.state.vx[k] = frozen ? 0.0 : p.vx;
  e_.state.vy[k] = frozen ? 0.0 : p.vy;
  e_.state.omega[k] = 0;
  e_.state.diameter[k] = s.diameter[id];
  e_.state.weight[k] = s.weight[id];
  e_.state.origin[k] = id;
  e_.state.frozen[k] = frozen ? 1 : 0;
  const double reach = e_.model.lubrication_reach();
  e_.lists.search.push_back(0.5 * s.diameter[id] * (1 + reach + e_.model.skin + e_.lists.margin));
  e_.lists.x0.push_back(p.x);
  e_.lists.y0.push_back(p.y);
  e_.forces.stiffness.push_back(0.0);
  if (paced()) e_.allowance.push_back(HUGE_VAL);  // noted when wake_around anchors it
  member_[id] = std::uint32_t(k);
  if (own_steps_) {
    at_[id] = kInSync;
    member_at_.push_back(kInSync);
  }
  kind_[id] = frozen ? GrainKind::frozen : GrainKind::moving;
  move_deposit(id, p.x, p.y);
  member_track_.push_back({track_[id].flight.x, track_[id].flight.y, track_[id].deposit_cell});
  members_changed_ = true;
  ++e_.stats.engaged;
  wake_.push_back(id);
}

// Registers the boxes of the grains just engaged; whatever a moving one's box overlaps joins
// too (coasting grains where they are now, settled ones frozen), until nothing more does.
void LocalStepper::wake_around(std::uint32_t first) {
  if (first != kNoMember) wake_.push_back(first);
  std::vector<std::uint32_t>& found = found_;
  while (!wake_.empty()) {
    const std::uint32_t id = wake_.back();
    wake_.pop_back();
    const std::size_t k = member_[id];
    anchor(k);
    if (e_.state.frozen[k]) continue;
    found.clear();
    boxes_.overlapping(
        boxes_.box(id), id, [&](std::uint32_t j) { found.push_back(j); },
        [&](std::uint32_t j) {
          return (kind_[j] == GrainKind::coasting && !passes(j)) || kind_[j] == GrainKind::settled;
        });
    std::sort(found.begin(), found.end());
    const Box reach = boxes_.box(id);
    for (std::uint32_t j : found) {
      if (kind_[j] == GrainKind::coasting) {
        if (!resync_clear_of(j, reach)) engage(j, coasting_at(j, e_.time), false);
      } else {
        const FreeFlight& f = track_[j].flight;
        --settled_;
        engage(j, FreeFlight::Point{f.x, f.y, 0, 0}, true);
      }
    }
  }
}

void LocalStepper::anchor(std::size_t k) {
  const std::uint32_t id = e_.state.origin[k];
  track_[id].flight.x = member_track_[k].x = e_.state.x[k];
  track_[id].flight.y = member_track_[k].y = e_.state.y[k];
  if (e_.model.contact)
    boxes_.set(id, member_box(k),
               box_tag(e_.state.frozen[k] ? GrainKind::frozen : GrainKind::moving));
  if (paced()) note_allowance(id, k);
  if (own_steps_) own_.rerate.push_back(std::uint32_t(k));  // its pace may have changed
}

// The radius in which member k's box lets it move, read off the box itself (so that a
// checkpoint's boxes give the same bound to the last bit). A pace within rounding of the
// grain's own radius is its own radius, exactly.
void LocalStepper::note_allowance(std::uint32_t id, std::size_t k) {
  const double r = 0.5 * e_.state.diameter[k];
  const Box& b = boxes_.box(id);
  const double pace = std::max(0.0, 0.5 * (b.x1 - b.x0) - r * (1 + kSkin)) / kAllowance;
  e_.allowance[k] = e_.state.frozen[k] || std::abs(pace - r) <= 1e-9 * r ? r : pace;
}

Box LocalStepper::member_box(std::size_t k) const {
  const double r = 0.5 * e_.state.diameter[k];
  // With carried steps a grain held against a coarser one moves at its pace: its box allows
  // as many of the coarser one's radii.
  const std::vector<double>* carrier = e_.carried ? e_.integrator->carrier_radii() : nullptr;
  double pace = carrier ? std::max(r, (*carrier)[e_.state.origin[k]]) : r;
  // A box of a few steps' travel, where its radii would reach the neighbours' boxes: at a
  // million grains a coarse member's box of 2 radii crossed more than the mean spacing, though
  // the step the fine grains set moved it a tenth of a radius, and such boxes held each other
  // on the common step. The step then keeps it within that pace (travel_in_step).
  const double steps = e_.setup.integrator.member_box_steps;
  const double travel = steps > 0 && paced() ? e_.integrator->travel_in_step(e_.state, k) : 0.0;
  if (travel > 0)
    pace = std::min(pace,
                    std::max(least_pace_, steps * travel / e_.setup.integrator.crossing_fraction));
  const double reach = r * (1 + kSkin) + (e_.state.frozen[k] ? 0.0 : kAllowance * pace);
  return Box{e_.state.x[k] - reach, e_.state.x[k] + reach, e_.state.y[k] - reach,
             e_.state.y[k] + reach};
}

void LocalStepper::remove_member(std::size_t k) {
  const std::size_t last = e_.state.size() - 1;
  if (k != last) {
    for (auto* v :
         {&e_.state.x, &e_.state.y, &e_.state.vx, &e_.state.vy, &e_.state.omega, &e_.state.diameter,
          &e_.state.weight, &e_.lists.search, &e_.lists.x0, &e_.lists.y0, &e_.forces.stiffness})
      (*v)[k] = (*v)[last];
    e_.state.origin[k] = e_.state.origin[last];
    e_.state.frozen[k] = e_.state.frozen[last];
    if (paced()) e_.allowance[k] = e_.allowance[last];
    member_track_[k] = member_track_[last];
    member_[e_.state.origin[k]] = std::uint32_t(k);
  }
  e_.state.resize(last);
  if (paced()) e_.allowance.resize(last);
  member_track_.resize(last);
  if (own_steps_) {
    member_at_[k] = member_at_[last];
    member_at_.resize(last);
  }
  e_.lists.search.resize(last);
  e_.lists.x0.resize(last);
  e_.lists.y0.resize(last);
  e_.forces.stiffness.resize(last);
  members_changed_ = true;
  e_.lists.stale = true;  // the last member took k's place in the rows
}

// Moving members that touch nothing coast again where a window fits.
void LocalStepper::release_members() {
  Release& r = release_;
  std::vector<std::uint32_t>& free = r.free;
  free.clear();
  for (std::size_t k = 0; k < e_.state.size(); ++k)
    if (!e_.state.frozen[k] && e_.forces.stiffness[k] == 0) free.push_back(e_.state.origin[k]);
  std::sort(free.begin(), free.end());
  r.shortest.resize(free.size());
  for (std::size_t i = 0; i < free.size(); ++i) {
    const std::uint32_t id = free[i];
    const std::size_t k = member_[id];
    const FreeFlight::Point p{e_.state.x[k], e_.state.y[k], e_.state.vx[k], e_.state.vy[k]};
    // A window of one crossing time is enough: requiring four cut the churn of grains leaving
    // and rejoining, but kept settling grains on the common step and let a spreading pile's
    // overlaps reach 0.7 of a radius (DensePileHasNoDeepOverlap).
    if (!coast(id, e_.time, p, true, &r.shortest[i], &blocker_[id])) continue;
    remove_member(k);
    member_[id] = kNoMember;
    ++e_.stats.released;
  }
  // Most members that stay are held by others touching nothing, whose allowance boxes (not
  // their discs) are in their shortest windows' way, and that they hold in turn: two grains
  // falling side by side a radius apart, or a few. Each such group leaves together where all
  // its windows clear each other. (Found by queries, not by blocker_: which box a query meets
  // first depends on the cells' order, which a resumed run does not share.)
  const double hw = e_.model.half_width;
  auto index_of = [&](std::uint32_t id) {
    const auto at = std::lower_bound(free.begin(), free.end(), id);
    return at != free.end() && *at == id ? std::size_t(at - free.begin()) : free.size();
  };
  r.loose.assign(free.size(), 0);
  r.groups.assign(free.size());
  for (std::size_t i = 0; i < free.size(); ++i) {
    const std::uint32_t a = free[i];
    if (member_[a] == kNoMember) continue;
    const Box& window = r.shortest[i];
    bool ok = window.x0 > -hw && window.x1 < hw && window.y0 > 0;
    // Every stayed member in the way joins a's group, whatever else is (a query's order is
    // the cells'): a group that holds one that cannot leave stays, all of it.
    boxes_.overlapping(window, a, [&](std::uint32_t j) {
      if (passes(j)) return;
      const std::size_t m = index_of(j);
      const bool stayed = m < free.size() && member_[j] != kNoMember;
      ok = ok && stayed && !member_disc(member_[j]).overlaps(window);
      if (stayed) r.groups.unite(std::uint32_t(i), std::uint32_t(m));
    });
    r.loose[i] = ok;
  }
  r.groups.flatten();
  r.by_group.clear();
  r.whole.assign(free.size(), 1);
  for (std::size_t i = 0; i < free.size(); ++i) {
    if (member_[free[i]] == kNoMember) continue;
    const std::uint32_t root = r.groups.flat_root(std::uint32_t(i));
    r.whole[root] = r.whole[root] && r.loose[i];
    r.by_group.emplace_back(root, free[i]);
  }
  std::sort(r.by_group.begin(), r.by_group.end());
  for (std::size_t g = 0; g < r.by_group.size();) {
    const std::uint32_t root = r.by_group[g].first;
    r.group.clear();
    for (; g < r.by_group.size() && r.by_group[g].first == root; ++g)
      r.group.push_back(r.by_group[g].second);
    if (!r.whole[root] || !leave_together(r.group)) continue;
    for (std::uint32_t id : r.group) {
      remove_member(member_[id]);
      member_[id] = kNoMember;
      ++e_.stats.released;
    }
  }
}

// Member k's disc widened as a coasting grain's: inside any window it takes now.
Box LocalStepper::member_disc(std::size_t k) const {
  return coasting_disc(e_.state.x[k], e_.state.y[k], e_.state.diameter[k]);
}

// Members touching nothing take windows together, in turn: each clear of the discs of those
// after it (which their windows will hold, whatever their length) and of the windows of those
// before it. False: one found none, and all hold their boxes as before.
bool LocalStepper::leave_together(const std::vector<std::uint32_t>& group) {
  const std::uint8_t moving = box_tag(GrainKind::moving);
  std::vector<Release::Held>& held = release_.held;
  held.clear();
  for (std::uint32_t id : group) {
    held.push_back({boxes_.box(id), track_[id]});
    boxes_.set(id, member_disc(member_[id]), moving);
  }
  std::size_t left = 0;
  for (; left < group.size(); ++left) {
    const std::size_t k = member_[group[left]];
    const FreeFlight::Point p{e_.state.x[k], e_.state.y[k], e_.state.vx[k], e_.state.vy[k]};
    if (!coast(group[left], e_.time, p, true)) break;
  }
  if (left == group.size()) return true;
  for (std::size_t i = 0; i < group.size(); ++i) {
    // The windows' syncs, already queued, are stale once they are members again.
    if (i < left) {
      track_[group[i]] = held[i].track;
      kind_[group[i]] = GrainKind::moving;
    }
    boxes_.set(group[i], held[i].box, moving);
  }
  return false;
}

// Frozen members that no moving member can reach go back to the bed, out of the state.
void LocalStepper::settle_members() {
  std::vector<std::uint32_t> frozen;
  for (std::size_t k = 0; k < e_.state.size(); ++k)
    if (e_.state.frozen[k]) {
      anchor(k);
      frozen.push_back(e_.state.origin[k]);
    }
  std::sort(frozen.begin(), frozen.end());
  for (std::uint32_t id : frozen) {
    bool reachable = false;
    boxes_.overlapping(
        boxes_.box(id), id, [&](std::uint32_t) { reachable = true; },
        [&](std::uint32_t j) { return !reachable && kind_[j] == GrainKind::moving; });
    if (reachable) continue;
    const std::size_t k = member_[id];
    track_[id].flight = FreeFlight{e_.state.x[k], e_.state.y[k], 0, 0, 0, 0, 0};
    kind_[id] = GrainKind::settled;
    ++settled_;
    boxes_.set(id, boxes_.box(id), box_tag(GrainKind::settled));
    remove_member(k);
    member_[id] = kNoMember;
  }
}

void LocalStepper::index_members() {
  member_track_.resize(e_.state.size());
  if (own_steps_) member_at_.resize(e_.state.size());
  for (std::size_t k = 0; k < e_.state.size(); ++k) {
    prefetch_track(k + kPrefetchAhead);
    const std::uint32_t id = e_.state.origin[k];
    member_[id] = std::uint32_t(k);
    const Track& t = track_[id];
    member_track_[k] = {t.flight.x, t.flight.y, t.deposit_cell};
    if (own_steps_) member_at_[k] = at_[id];
  }
}

}  // namespace sedem
