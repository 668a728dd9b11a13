#include "core/engine/schedule/local_stepper.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/engine/instability.h"

namespace sedem {

LocalStepper::LocalStepper(EngineParts& parts) : e_(parts) {
  // Below the lowest instrument nothing rises back into any instrument's reach: a grain that
  // falls there can leave the dynamics (only where some instrument reads).
  if (e_.model.contact && e_.setup.integrator.retire_below && e_.setup.instruments_read)
    retire_height_ = std::max(0.0, e_.setup.lowest_measured_height);
  const Particles& s = e_.sample.particles;
  const std::size_t n = s.size();
  kind_.assign(n, GrainKind::coasting);
  track_.assign(n, Track{});
  member_.assign(n, kNoMember);
  // Lanes apart where the free grains pass each other (local_lanes.cpp).
  const bool apart = !e_.model.contact || !e_.model.suspension_contacts;
  lanes_.assign(apart ? e_.voidage.columns() : 1, Lane{});
  lane_threads_ = apart ? e_.sync_threads : 1;
  own_steps_ = e_.setup.integrator.own_steps && e_.model.contact && !apart && !e_.carried;
  at_.assign(own_steps_ ? n : 0, kInSync);
  lagging_ = 0;
  lag_cap_ = HUGE_VAL;
  const Cylinder& cyl = e_.setup.cylinder;
  double dmax = 0;
  for (double d : s.diameter) dmax = std::max(dmax, d);
  // Cells about twice the mean spacing: a box spans a few of them and each holds a few boxes.
  const double spacing =
      std::sqrt(2 * cyl.half_width() * cyl.height / double(std::max<std::size_t>(n, 1)));
  const double travel = e_.setup.integrator.coast_travel * spacing;
  travel_ = e_.model.suspension_contacts ? travel : std::max(travel, e_.setup.forces.voidage_cell);
  registry_cell_ = std::max(spacing, 4 * dmax);
  least_pace_ = kLeastPace * spacing;
  land_y_.assign(n, 0.0);
  ahead_slot_.assign(n, kNoMember);
  blocker_.assign(n, kNoMember);
  widened_.clear();
  bed_column_ = std::max(dmax, 1e-9);
  bed_.assign(std::max<std::size_t>(1, std::size_t(std::ceil(2 * cyl.half_width() / bed_column_))),
              0.0);
  e_.stats.retired = 0;
  if (e_.model.contact) boxes_.configure(registry_cell_, cyl.half_width(), cyl.height, n);
  if (e_.model.drag == DragLaw::di_felice) {
    e_.voidage.compute(n, e_.state.x.data(), e_.state.y.data(), e_.state.diameter.data(),
                       e_.state.weight.data());
    for (std::uint32_t id = 0; id < n; ++id)
      track_[id].deposit_cell = std::uint32_t(e_.voidage.cell(e_.state.x[id], e_.state.y[id]));
  }
  // Every grain first holds its disc, as if settled, so that the first windows see them all.
  std::vector<FreeFlight::Point> start(n);
  for (std::uint32_t id = 0; id < n; ++id) {
    start[id] = {e_.state.x[id], e_.state.y[id], e_.state.vx[id], e_.state.vy[id]};
    track_[id].flight = FreeFlight{start[id].x, start[id].y, start[id].vx, start[id].vy, 0, 0, 0};
    if (e_.model.contact)
      hold_coasting_box(id, coasting_disc(start[id].x, start[id].y, s.diameter[id]));
  }
  // The state holds the members only, a few thousand at most: the room it had for every
  // grain (a sixth of the memory at a million particles) goes back.
  e_.state = EngineState{};
  member_track_.clear();
  member_at_.clear();
  e_.forces = ForceAccumulators{};
  std::vector<double>().swap(e_.lists.search);
  std::vector<double>().swap(e_.lists.x0);
  std::vector<double>().swap(e_.lists.y0);
  for (std::uint32_t id = 0; id < n; ++id)
    if (start[id].y + 0.5 * s.diameter[id] < retire_height_) retire(id, 0.0, start[id]);
  for (std::uint32_t id = 0; id < n; ++id) {
    if (kind_[id] != GrainKind::coasting) continue;  // engaged by a neighbour already, or retired
    if (coast(id, 0.0, start[id], true)) continue;
    engage(id, start[id], false);
    wake_around(kNoMember);
  }
  index_members();
  e_.lists.stale = true;
  members_changed_ = false;
  e_.integrator->refresh_step(e_.state);
  e_.stats.members = e_.state.size();
  count_lanes();
}

void LocalStepper::step(double limit) {
  // Moving members from `from` on: a round of syncs only appends members.
  auto count_moving = [&](std::size_t from) {
    std::size_t m = 0;
    for (std::size_t k = from; k < e_.state.size(); ++k) m += e_.state.frozen[k] == 0;
    return m;
  };
  std::size_t moving = count_moving(0);
  // Own steps: no lagging cluster's lag may pass its own step.
  auto choose_step = [&] {
    const double step = moving ? e_.integrator->next_step(e_.facts) : e_.setup.integrator.max_step;
    return own_steps_ ? std::min(step, lag_cap_) : step;
  };
  lag_cap_ = HUGE_VAL;  // found again below, for the step the members allow
  double dt = choose_step();
  // Those a step of dt would carry past their own step catch up first (the step is then
  // chosen again: their speeds changed).
  while (own_steps_ && lagging_ > 0 && settle_lags(moving ? dt : 0.0)) {
    moving = count_moving(0);
    dt = choose_step();
  }
  double target = e_.time + dt >= limit ? limit : e_.time + dt;
  const bool apart = lanes_.size() > 1;
  if (apart && !moving) target = idle_horizon(target);
  // Syncs due within the step, in time order. A grain that cannot coast on joins the members
  // at their time, before they step, where its last window put it then (coasting_at). So no
  // member step is cut short by a sync (steps of a few ns would turn the projection's
  // corrections into runaway speeds).
  ahead_.clear();
  std::size_t ahead_looked = 0;
  std::size_t idle_syncs = 0;
  double last_sync = e_.time;
  SyncQueue& syncs = lanes_[0].syncs;
  bool first_round = true;
  for (;;) {
    failed_.clear();
    if (apart) take_lanes(target);
    while (!apart && !syncs.empty() && syncs.front().first <= target) {
      // Nothing moves between syncs, so ending the step between two of them changes nothing
      // but where a stop may come (syncs at one time are all taken: none ends unlooked-at).
      if (!moving && idle_syncs >= kIdleStepSyncs && syncs.front().first > last_sync) {
        target = last_sync;
        break;
      }
      const auto [t, id] = syncs.front();
      last_sync = t;
      ++idle_syncs;
      syncs.pop();
      prefetch_next(syncs);
      if (kind_[id] != GrainKind::coasting || track_[id].t1 != t) continue;  // engaged since: stale
      const FreeFlight::Point p = track_[id].flight.at(t - track_[id].t0);
      if (!std::isfinite(p.x + p.y + p.vx + p.vy))
        throw InstabilityError(e_.sample.particles.id[id], t, "position", p.x);
      e_.stats.particle_steps += 1;
      if (p.y + 0.5 * e_.sample.particles.diameter[id] < retire_height_) {
        retire(id, t, p);
        continue;
      }
      move_deposit(id, p.x, p.y);
      const Box before = e_.model.contact ? boxes_.box(id) : Box{};
      const double t0_before = track_[id].t0;
      if (coast(id, t, p, true)) {
        note_ahead(id, t, before, t0_before);
        continue;
      }
      if (e_.model.contact && make_room(id, t, p)) {
        if (failed_.empty()) continue;
        break;  // a grain it moved could not coast: the members' step is chosen again with it
      }
      track_[id].t1 = HUGE_VAL;  // its heap entry, if any, is stale
      failed_.push_back(id);
      break;  // the members' step is chosen again with it
    }
    if (failed_.empty()) break;
    // The members' step may shrink now, below the time of grains already synced within it:
    // their box covers their path from the members' time on, the old window's part included,
    // until their next sync. (Taken before the new members' boxes look for what they reach.)
    // Those looked at in an earlier round were widened then, or had joined, retired or synced
    // again since, none of which a later round undoes: each round looks at the new ones only
    // (at a million grains, rounds over all of them were a tenth of the run).
    for (std::size_t i = ahead_looked; i < ahead_.size(); ++i) {
      Ahead& a = ahead_[i];
      if (a.widened || kind_[a.id] != GrainKind::coasting || track_[a.id].t0 != a.time) continue;
      hold_coasting_box(a.id, a.after.merged(a.before));
      a.widened = true;
    }
    ahead_looked = ahead_.size();
    const std::size_t before = e_.state.size();
    for (std::uint32_t id : failed_)
      if (kind_[id] == GrainKind::coasting) engage(id, coasting_at(id, e_.time), false);
    wake_around(kNoMember);
    e_.extend_lists();  // the joiners come last, the others' rows stand
    // (Own steps: a joiner listed with a lagging cluster brings it to the members' time as the
    // step begins, advance_own. Taken here, at every round, those catch-ups and the passes they
    // take were a third of a million grains' first 0.3 s.)
    // The first round chooses the step afresh (a grain may have frozen since it was chosen);
    // the next ones only add the joiners' bounds.
    e_.integrator->refresh_step(e_.state, first_round ? 0 : before);
    first_round = false;
    members_changed_ = false;
    moving += count_moving(before);
    dt = choose_step();
    target = e_.time + dt >= limit ? limit : e_.time + dt;
    // Syncs still due before the new target are taken in the next round: no window may end
    // unlooked-at while the members step past it.
  }
  // Those synced within the step after all need their new box only; the others once the
  // members have passed their sync (until then a grain synced after them may be where their
  // old box was, which is what the widened boxes allow).
  for (const Ahead& a : ahead_)
    if (a.widened && kind_[a.id] == GrainKind::coasting && track_[a.id].t0 == a.time) {
      if (a.time <= target)
        hold_coasting_box(a.id, a.after);
      else
        widened_.push_back(a);
    }

  const StepLimit chosen = moving ? e_.integrator->step_limit() : StepLimit{};
  e_.stats.pushed = chosen.pushed;
  // Cut where the step was (the run's end, a reading), or not known: the step itself.
  const double taken = target - e_.time;
  e_.stats.unpushed_step = chosen.unpushed_step <= 0 ? 0
                           : chosen.unpushed_step <= dt
                               ? taken
                               : std::max(taken, std::min(chosen.unpushed_step, limit - e_.time));
  e_.stats.fast_set = e_.stats.substeps = 0;
  if (moving && target > e_.time) {
    if (e_.lists.stale) {
      // Only a re-sort moves the members (joins and departures keep member_ up to date).
      if (e_.resort_and_rebuild_lists()) index_members();
    }
    Blowup blowup;
    std::size_t stepped = moving;
    if (own_steps_) {
      // Every cluster at the members' time where a reading or a release looks at them.
      const bool all =
          target == limit || (e_.stats.steps + 1) % kReleaseEvery == 0 || moving < kOwnStepsFrom;
      stepped = advance_own(target - e_.time, all, target);  // throws its own blow-ups
    } else {
      e_.integrator->advance(e_.state, e_.forces, target - e_.time, blowup);
    }
    e_.integrator->contact_facts(e_.facts);
    const SubstepReport sub = e_.integrator->substeps();
    e_.stats.fast_set = sub.fast;
    e_.stats.substeps = sub.taken;
    // Every sub-step of the fast set counts, the first as its share of the step.
    e_.stats.particle_steps +=
        double(stepped) + double(sub.fast) * double(sub.taken > 0 ? sub.taken - 1 : 0);
    e_.stats.contacts = e_.facts.contacts;
    e_.stats.max_overlap_ratio = std::max(e_.stats.max_overlap_ratio, e_.facts.max_overlap_ratio);
    if (blowup.found) e_.throw_blowup(blowup, target);
    e_.lists.stale = e_.lists.stale || e_.lists.moved_beyond_margin(e_.state);
    if (e_.model.drag == DragLaw::di_felice)
      for (std::size_t k = 0; k < e_.state.size(); ++k) {
        if (e_.state.frozen[k]) continue;
        const auto cell = std::uint32_t(e_.voidage.cell(e_.state.x[k], e_.state.y[k]));
        if (cell == member_track_[k].cell) continue;
        move_deposit(e_.state.origin[k], e_.state.x[k], e_.state.y[k]);
        member_track_[k].cell = cell;
      }
  } else if (!moving) {
    e_.stats.contacts = 0;  // no force pass this step: nothing was found touching
  }
  e_.stats.last_step = target - e_.time;
  e_.time = target;
  e_.stats.steps += 1;
  if (!widened_.empty()) {
    std::size_t kept = 0;
    for (const Ahead& a : widened_) {
      if (kind_[a.id] != GrainKind::coasting || track_[a.id].t0 != a.time)
        continue;  // synced again since
      if (a.time <= e_.time)
        hold_coasting_box(a.id, a.after);
      else
        widened_[kept++] = a;
    }
    widened_.resize(kept);
  }

  e_.stats.own_step_share = e_.stats.largest_cluster = 0;
  if (moving && e_.model.contact && e_.stats.steps % kClusterLookEvery == 0)
    look_at_clusters();  // the members as they stepped
  if (moving) {
    // Which members touch something, from this step's projection, before any joins or leaves.
    if (e_.stats.steps % kReleaseEvery == 0) e_.integrator->mark_touching(e_.forces.stiffness);
    // A member leaving makes the lists stale: members retire when the lists are to be built
    // anyway, or at the release's look (a few steps' wait below every instrument changes no
    // reading; at 10^6 grains retirements had caused half of the builds).
    if (retire_height_ > 0 && (e_.lists.stale || e_.stats.steps % kReleaseEvery == 0))
      retire_members();
    // Members that used their allowance take a new box; whatever it reaches joins them.
    for (std::size_t k = 0; k < e_.state.size(); ++k)
      if (!e_.state.frozen[k]) reanchor_if_used(k);
    wake_around(kNoMember);
    if (e_.freeze.due(e_.stats.steps)) {
      e_.freeze.run(e_.state, e_.forces.stiffness, e_.model, e_.setup.fluid);
      own_.valid = false;  // the clusters are a function of the lists and the frozen flags
      settle_members();
      e_.stats.frozen = settled_;
      for (std::uint8_t f : e_.state.frozen) e_.stats.frozen += f;
    }
    if (e_.stats.steps % kReleaseEvery == 0) release_members();
  }
  if (members_changed_) {
    e_.extend_lists();  // the joiners' rows (a departure made the lists stale)
    fresh_step();
    members_changed_ = false;
  } else if (e_.carried) {
    fresh_step();  // the lists and the boxes (re-anchored, another pace) as they are now
  }
  // Lists that a rebuild or a joiner made link lagging clusters to others: those catch up.
  if (own_steps_ && lagging_ > 0) settle_lags(0.0);
  e_.stats.lagging = lagging_;
  e_.stats.members = e_.state.size();
  count_lanes();
}

// A member that used its allowance takes a new box (wake_around), whatever it then reaches joining.
void LocalStepper::reanchor_if_used(std::size_t k) {
  const std::uint32_t id = e_.state.origin[k];
  const double dx = e_.state.x[k] - member_track_[k].x;
  const double dy = e_.state.y[k] - member_track_[k].y;
  const double pace = kReanchor * (paced() ? e_.allowance[k] : 0.5 * e_.state.diameter[k]);
  if (dx * dx + dy * dy <= pace * pace) return;
  wake_.push_back(id);
  ++e_.stats.box_moves;
}

// At a step's end: the lists are then always fresh, so a checkpoint (which keeps whether they
// are stale, not why) resumes to the same step.
void LocalStepper::fresh_step() {
  // A grain picked up since the build would move at its own radius's pace until the next one:
  // its rows widen. (Rebuilding every list for it did so at every step at a million grains,
  // where some fine grain is picked up somewhere at each.)
  if (e_.carried) e_.widen_lists();
  if (e_.carried && e_.lists.stale && e_.state.size() > 0) {
    if (e_.resort_and_rebuild_lists()) index_members();
  }
  e_.integrator->refresh_step(e_.state);
}

void LocalStepper::move_deposit(std::uint32_t id, double x, double y) {
  if (e_.model.drag != DragLaw::di_felice) return;
  const std::size_t c = e_.voidage.cell(x, y);
  if (c == track_[id].deposit_cell) return;
  const double d = e_.sample.particles.diameter[id];
  const double volume = e_.sample.particles.weight[id] * e_.model.volume(d);
  e_.voidage.deposit(track_[id].deposit_cell, -volume);
  e_.voidage.deposit(c, volume);
  track_[id].deposit_cell = std::uint32_t(c);
}

void LocalStepper::write_free_grains(Particles& p) const {
  for (std::uint32_t id = 0; id < kind_.size(); ++id) {
    if (is_member(kind_[id])) continue;
    const FreeFlight::Point q =
        kind_[id] == GrainKind::coasting ? coasting_at(id, e_.time)
        : kind_[id] == GrainKind::retired
            ? retired_at(id, e_.time)
            : FreeFlight::Point{track_[id].flight.x, track_[id].flight.y, 0, 0};
    p.x[id] = q.x;
    p.y[id] = q.y;
    p.vx[id] = q.vx;
    p.vy[id] = q.vy;
    p.omega[id] = 0;
  }
}

std::size_t LocalStepper::bytes() const {
  auto cap = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  std::size_t lane_bytes = cap(lanes_);
  for (const Lane& l : lanes_)
    lane_bytes += l.syncs.bytes() + cap(l.near) + cap(l.failed) + cap(l.leaving);
  return cap(kind_) + cap(track_) + cap(member_) + cap(wake_) + boxes_.bytes() + cap(land_y_) +
         cap(bed_) + cap(ahead_slot_) + cap(blocker_) + cap(ahead_) + cap(widened_) +
         cap(leaving_) + release_.bytes() + clusters_.bytes() + own_.bytes() + cap(at_) +
         cap(member_at_) + lane_bytes;
}

}  // namespace sedem
