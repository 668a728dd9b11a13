// Own steps (integrator.own_steps): clusters of members, each on steps of its own.
//
// Two members that no candidate list pairs cannot touch before the lists are rebuilt (the
// lists hold every pair their margins could close), so the moving members fall into clusters
// linked by their lists' pairs; frozen members link nothing (they move nobody). A cluster whose
// own fastest member allows twice the common step or more *lags*: it sits the common step out,
// its members keeping the state of its last step (at_: the time they are at),
// and takes one step of its own over its lag before that lag could pass its own step. Its
// members stay inside their boxes as on the common step (no step carries a member further than
// its own rule allows), so no coasting grain can meet them. Every cluster catches up at a
// reading (the instruments see every member at the members' time), at every kReleaseEvery-th
// step (the releases, the freezing and the contacts they read see the same), below
// kOwnStepsFrom moving members, and as soon as a list links it to members of another lag (a
// grain joined beside it, or the lists were rebuilt). docs/engine.md, "Clusters on steps of
// their own".

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "core/engine/schedule/local_stepper.h"

namespace sedem {

// The lists change by a build, or by rows appended for joiners and widenings (the others'
// rows stand): a build finds the clusters anew, appended rows join them further. A member
// frozen since still links its own: a larger cluster is safe.
void LocalStepper::find_clusters() {
  OwnSteps& o = own_;
  const EngineState& s = e_.state;
  const std::size_t n = s.size();
  const bool anew = !o.valid || o.builds != e_.stats.list_builds || o.members > n;
  if (anew || o.rows != e_.lists.rows() || o.members != n) {
    const std::vector<std::uint32_t>& start = e_.lists.list_start();
    const std::vector<std::uint32_t>& list = e_.lists.list();
    if (anew) {
      o.sets.assign(n);
      o.rates_valid = false;
      o.clean_rows = 0;
    } else {
      o.sets.grow(n);
    }
    o.row_member.resize(e_.lists.rows());
    for (std::size_t row = anew ? 0 : o.rows; row < e_.lists.rows(); ++row) {
      const std::uint32_t i = e_.lists.particle_of(row, e_.grid);
      std::uint32_t& member = o.row_member[row];
      member = kNoMember;
      if (i >= n) continue;
      if (s.frozen[i]) {  // its moving partners are linked by other rows, if at all
        for (std::uint32_t q = start[row]; q < start[row + 1]; ++q) {
          const std::uint32_t j = list[q];
          if (j >= n || s.frozen[j] || j == member) continue;
          member = member == kNoMember ? j : OwnSteps::kMixedRow;
        }
        continue;
      }
      member = i;
      for (std::uint32_t q = start[row]; q < start[row + 1]; ++q) {
        const std::uint32_t j = list[q];
        if (j < n && !s.frozen[j]) o.sets.unite(i, j);
      }
    }
    o.sets.flatten();
    if (o.rates_valid) {  // the joiners' rates
      o.moved.clear();
      for (std::size_t k = o.members; k < n; ++k) o.moved.push_back(std::uint32_t(k));
      e_.integrator->own_rates(s, &o.moved, o.rate);
    }
    o.valid = true;
    o.builds = e_.stats.list_builds;
    o.rows = e_.lists.rows();
    o.members = n;
  }
  if (!o.rates_valid) {
    e_.integrator->own_rates(s, nullptr, o.rate);
  } else {  // re-anchored since: another pace
    o.rerate.erase(
        std::remove_if(o.rerate.begin(), o.rerate.end(), [&](std::uint32_t k) { return k >= n; }),
        o.rerate.end());
    e_.integrator->own_rates(s, &o.rerate, o.rate);
  }
  o.rerate.clear();
  o.rates_valid = true;
  o.horizon.assign(n, 0.0);  // by root: the fastest member's rate, then its step
  o.most.assign(n, 0.0);
  o.least.assign(n, HUGE_VAL);
  lagging_ = 0;
  o.cluster_size.assign(n, 0);
  for (std::size_t k = 0; k < n; ++k) {
    if (s.frozen[k]) continue;
    const std::uint32_t root = o.sets.flat_root(std::uint32_t(k));
    ++o.cluster_size[root];
    o.horizon[root] = std::max(o.horizon[root], o.rate[k]);
    const double lag = lag_of(k);
    o.most[root] = std::max(o.most[root], lag);
    o.least[root] = std::min(o.least[root], lag);
    lagging_ += lag > 0;
  }
  for (std::size_t k = 0; k < n; ++k)
    if (o.least[k] != HUGE_VAL) o.horizon[k] = e_.integrator->step_at_rate(o.horizon[k]);
}

std::size_t LocalStepper::part_of_dt(double dt, int phase) {
  OwnSteps& o = own_;
  for (std::size_t p = 0; p < o.used; ++p)
    if (o.parts[p].dt == dt && o.parts[p].phase == phase) return p;
  if (o.parts.size() <= o.used) o.parts.emplace_back();
  OwnSteps::Part& part = o.parts[o.used];
  part.dt = dt;
  part.phase = phase;
  part.members.clear();
  return o.used++;
}

std::size_t LocalStepper::run_parts(double at) {
  OwnSteps& o = own_;
  EngineState& s = e_.state;
  const std::size_t n = s.size();
  if (o.used == 0) return 0;
  o.moving.clear();
  for (std::size_t k = 0; k < n; ++k)
    if (!s.frozen[k]) o.moving.push_back(std::uint32_t(k));
  o.aside.resize(std::max(e_.sample.particles.size(), n), 0);
  // Each member's part, and each part's rows (those holding a pair with one of its members: the
  // only ones its projection reads), in one pass over the lists; a member in two parts (one
  // catching up before the step, then taking it) has its rows found for each apart.
  o.part_of.assign(n, kNoMember);
  bool twice = false;
  for (std::size_t p = 0; p < o.used; ++p) {
    OwnSteps::Part& part = o.parts[p];
    if (!std::is_sorted(part.members.begin(), part.members.end()))  // the common part mostly is
      std::sort(part.members.begin(), part.members.end());
    part.rows.clear();
    for (std::uint32_t k : part.members) {
      twice = twice || o.part_of[k] != kNoMember;
      o.part_of[k] = std::uint32_t(p);
    }
  }
  const std::vector<std::uint32_t>& start = e_.lists.list_start();
  const std::vector<std::uint32_t>& list = e_.lists.list();
  auto find_rows = [&](std::size_t only_part) {
    for (std::size_t row = 0; row < e_.lists.rows(); ++row) {
      const std::uint32_t i = e_.lists.particle_of(row, e_.grid);
      if (i >= n) continue;
      auto take = [&](std::uint32_t k) {
        const std::uint32_t p = o.part_of[k];
        if (p == kNoMember || (only_part != kNoMember && p != only_part)) return;
        std::vector<std::uint32_t>& rows = o.parts[p].rows;
        if (rows.empty() || rows.back() != row) rows.push_back(std::uint32_t(row));
      };
      take(i);
      for (std::uint32_t q = start[row]; q < start[row + 1]; ++q)
        if (list[q] < n) take(list[q]);
    }
  };
  // Where every part holds whole clusters of the lists and frozen flags this run reads, a row's
  // pairs are those of one cluster, in its member's part or in none: only the rows of frozen
  // grains with partners in two clusters are read pair by pair.
  bool whole_clusters = !twice && o.valid && o.builds == e_.stats.list_builds &&
                        o.rows == e_.lists.rows() && o.members == n;
  if (whole_clusters) {
    o.tally.resize(n, 0);
    o.root_part.resize(n, kNoMember);
    for (std::size_t p = 0; p < o.used; ++p)
      for (std::uint32_t k : o.parts[p].members) {
        const std::uint32_t root = o.sets.flat_root(k);
        ++o.tally[root];
        whole_clusters =
            whole_clusters && (o.root_part[root] == kNoMember || o.root_part[root] == p);
        o.root_part[root] = std::uint32_t(p);
      }
    for (std::size_t p = 0; p < o.used; ++p)
      for (std::uint32_t k : o.parts[p].members) {
        const std::uint32_t root = o.sets.flat_root(k);
        whole_clusters =
            whole_clusters && (o.tally[root] == 0 || o.tally[root] == o.cluster_size[root]);
        o.tally[root] = 0;
        o.root_part[root] = kNoMember;
      }
  }
  if (whole_clusters) {
    for (std::size_t row = 0; row < o.rows; ++row) {
      const std::uint32_t member = o.row_member[row];
      if (member == OwnSteps::kMixedRow) {
        for (std::uint32_t q = start[row]; q < start[row + 1]; ++q) {
          const std::uint32_t p = list[q] < n ? o.part_of[list[q]] : kNoMember;
          if (p == kNoMember) continue;
          std::vector<std::uint32_t>& rows = o.parts[p].rows;
          if (rows.empty() || rows.back() != row) rows.push_back(std::uint32_t(row));
        }
      } else if (member != kNoMember && o.part_of[member] != kNoMember) {
        o.parts[o.part_of[member]].rows.push_back(std::uint32_t(row));
      }
    }
  } else if (!twice) {
    find_rows(kNoMember);
  }
  for (std::uint32_t k : o.moving) {
    s.frozen[k] = 1;
    o.aside[s.origin[k]] = 1;
  }
  Blowup blowup;
  std::size_t steps = 0;
  e_.integrator->begin_parts();
  for (int phase = 0; phase < 2; ++phase)
    for (std::size_t p = 0; p < o.used; ++p) {
      OwnSteps::Part& part = o.parts[p];
      if (part.phase != phase || part.members.empty()) continue;
      if (twice) {
        for (std::uint32_t k : part.members) o.part_of[k] = std::uint32_t(p);
        find_rows(p);
      }
      for (std::uint32_t k : part.members) {
        s.frozen[k] = 0;
        o.aside[s.origin[k]] = 0;
      }
      e_.integrator->advance_part(s, e_.forces, part.dt, part.members, part.rows, o.aside.data(),
                                  blowup);
      for (std::uint32_t k : part.members) {
        s.frozen[k] = 1;
        o.aside[s.origin[k]] = 1;
      }
      steps += part.members.size();
    }
  for (std::uint32_t k : o.moving) {
    s.frozen[k] = 0;
    o.aside[s.origin[k]] = 0;
  }
  // The rates the clusters' steps are chosen by: only those that moved changed.
  if (o.rates_valid)
    for (std::size_t p = 0; p < o.used; ++p)
      e_.integrator->own_rates(s, &o.parts[p].members, o.rate);
  e_.integrator->end_parts(s);
  o.used = 0;
  if (blowup.found) e_.throw_blowup(blowup, at);
  return steps;
}

std::size_t LocalStepper::advance_own(double dt, bool all, double at) {
  OwnSteps& o = own_;
  EngineState& s = e_.state;
  if (all && lagging_ == 0) {  // nothing lags, nothing may start to: one advance, no clusters
    o.lagging_roots.clear();
    o.lagging_stale = false;
    o.rates_valid = false;
    Blowup blowup;
    e_.integrator->advance(s, e_.forces, dt, blowup);
    if (blowup.found) e_.throw_blowup(blowup, at);
    std::size_t moving = 0;
    for (std::uint8_t f : s.frozen) moving += f == 0;
    return moving;
  }
  find_clusters();
  const std::size_t n = s.size();
  o.used = 0;
  o.catching.clear();
  bool mixed_any = false;
  std::size_t moving = 0;
  const std::size_t common = part_of_dt(dt, 1);
  for (std::size_t k = 0; k < n; ++k) {
    if (s.frozen[k]) continue;
    ++moving;
    const std::uint32_t root = o.sets.flat_root(std::uint32_t(k));
    const double lag = lag_of(k);
    if (o.least[root] < o.most[root]) {
      // A list links members of different lags (a grain joined beside a lagging cluster in this
      // step's rounds): those behind catch up first, then all take the common step, which they
      // lagged at their last look, so it is at most half their own step then.
      mixed_any = true;
      if (lag > 0) o.parts[part_of_dt(lag, 0)].members.push_back(std::uint32_t(k));
      set_at(k, kInSync);
      o.parts[common].members.push_back(std::uint32_t(k));
    } else if (lag == 0 && (all || !(o.horizon[root] >= 2 * dt))) {
      o.parts[common].members.push_back(std::uint32_t(k));
    } else {
      o.catching.emplace_back(lag + dt, std::uint32_t(k));
    }
  }
  if (!mixed_any && o.catching.empty()) {  // every member on the common step
    o.used = 0;
    o.lagging_roots.clear();
    o.lagging_stale = false;
    Blowup blowup;
    e_.integrator->advance(s, e_.forces, dt, blowup);
    o.rates_valid = false;
    if (blowup.found) e_.throw_blowup(blowup, at);
    return moving;
  }
  // The lagging ones sit the step out; those the next step would carry past their own step (if
  // it is as long as this one) catch up at its end, in this run, and so does every one where
  // all are to be at the members' time. (settle_lags brings the others the next step's own
  // length would carry past theirs to the members' time before it.)
  o.lagging_roots.clear();
  o.mark.assign(n, 0);
  for (const auto& [lag, k] : o.catching) {
    const std::uint32_t root = o.sets.flat_root(k);
    const double horizon = o.horizon[root];
    if (all || lag + dt > horizon) {
      o.parts[part_of_dt(lag, 1)].members.push_back(k);
      set_at(k, kInSync);
    } else {
      if (member_at_[k] < 0) set_at(k, e_.time);  // from the step's start
      if (!o.mark[root]) o.lagging_roots.push_back({member_at_[k], horizon});
      o.mark[root] = 1;
    }
  }
  o.lagging_stale = false;
  const std::size_t steps = run_parts(at);
  lagging_ = 0;
  for (std::size_t k = 0; k < n; ++k) lagging_ += member_at_[k] >= 0;
  return steps;
}

bool LocalStepper::settle_lags(double dt) {
  OwnSteps& o = own_;
  bool moved_any = false;
  std::vector<std::uint32_t>& moved = o.moved;
  while (lagging_ > 0) {
    if (e_.lists.stale && e_.state.size() > 0) {
      if (e_.resort_and_rebuild_lists()) index_members();
    }
    // The lists as the last look found them, or with rows appended that link no two lags: no
    // cluster holds two lags, and the lagging ones are those the members' step left.
    if (!links_two_lags()) {
      if (dt == 0) break;
      bool due = false;
      lag_cap_ = HUGE_VAL;
      for (const OwnSteps::Lagging& l : o.lagging_roots) {
        const double lag = e_.time - l.at;
        due = due || lag + dt > l.horizon;
        lag_cap_ = std::min(lag_cap_, l.horizon - lag);
      }
      if (!due) break;
    }
    find_clusters();
    o.used = 0;
    moved.clear();
    lag_cap_ = HUGE_VAL;
    const EngineState& s = e_.state;
    o.lagging_roots.clear();
    o.mark.assign(s.size(), 0);
    for (std::size_t k = 0; k < s.size(); ++k) {
      if (s.frozen[k]) continue;
      const double lag = lag_of(k);
      if (lag == 0) continue;
      const std::uint32_t root = o.sets.flat_root(std::uint32_t(k));
      if (o.least[root] < o.most[root] || lag + dt > o.horizon[root]) {
        o.parts[part_of_dt(lag, 0)].members.push_back(std::uint32_t(k));
        moved.push_back(std::uint32_t(k));
        set_at(k, kInSync);
      } else {
        lag_cap_ = std::min(lag_cap_, o.horizon[root] - lag);
        if (!o.mark[root]) o.lagging_roots.push_back({member_at_[k], o.horizon[root]});
        o.mark[root] = 1;
      }
    }
    o.lagging_stale = false;
    if (moved.empty()) break;
    e_.stats.particle_steps += double(run_parts(e_.time));
    lagging_ -= moved.size();
    moved_any = true;
    after_own_moves(moved);
  }
  if (lagging_ == 0) lag_cap_ = HUGE_VAL;
  if (moved_any) {
    e_.integrator->refresh_step(e_.state);
    members_changed_ = false;
  }
  return moved_any;
}

// Whether the lists link two members of different lags where the clusters were last found:
// in the rows appended since, if the lists were not built since.
bool LocalStepper::links_two_lags() {
  OwnSteps& o = own_;
  const EngineState& s = e_.state;
  const std::size_t n = s.size();
  if (!o.valid || o.builds != e_.stats.list_builds || o.members > n) return true;
  if (o.lagging_stale) return true;
  const std::vector<std::uint32_t>& start = e_.lists.list_start();
  const std::vector<std::uint32_t>& list = e_.lists.list();
  // Rows found clean stay so: a catch-up brings a whole cluster to one lag.
  for (std::size_t row = std::max(o.rows, o.clean_rows); row < e_.lists.rows(); ++row) {
    const std::uint32_t i = e_.lists.particle_of(row, e_.grid);
    if (i >= n || s.frozen[i]) continue;
    const double at = member_at_[i];
    for (std::uint32_t q = start[row]; q < start[row + 1]; ++q) {
      const std::uint32_t j = list[q];
      if (j < n && !s.frozen[j] && member_at_[j] != at) return true;
    }
  }
  o.clean_rows = e_.lists.rows();
  return false;
}

void LocalStepper::after_own_moves(const std::vector<std::uint32_t>& moved) {
  EngineState& s = e_.state;
  for (std::uint32_t k : moved) {
    if (e_.model.drag == DragLaw::di_felice) {
      const auto cell = std::uint32_t(e_.voidage.cell(s.x[k], s.y[k]));
      if (cell != member_track_[k].cell) {
        move_deposit(s.origin[k], s.x[k], s.y[k]);
        member_track_[k].cell = cell;
      }
    }
    reanchor_if_used(k);
  }
  e_.lists.stale = e_.lists.stale || e_.lists.moved_beyond_margin(s);
  wake_around(kNoMember);
  if (members_changed_) e_.extend_lists();
}

std::size_t LocalStepper::OwnSteps::bytes() const {
  auto cap = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  std::size_t b = sets.bytes() + cap(rate) + cap(horizon) + cap(most) + cap(least) + cap(part_of) +
                  cap(row_member) + cap(tally) + cap(root_part) + cap(cluster_size) + cap(moving) +
                  cap(aside) + cap(catching) + cap(moved) + cap(rerate) + cap(parts) +
                  cap(lagging_roots) + cap(mark);
  for (const Part& p : parts) b += cap(p.members) + cap(p.rows);
  return b;
}

}  // namespace sedem
