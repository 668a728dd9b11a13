#include "core/engine/integrate/contact_projection.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <utility>

#include "core/engine/contact/walls.h"
#include "core/engine/threads_for.h"

namespace sedem {

namespace {

constexpr double kTolerance = 1e-3;
// Pairs and walls closer than this many smaller radii join the constraints even if they do not
// touch yet at the free positions: the sweeps may push them into contact.
constexpr double kSkin = 0.5;
// Below this many constraints a sweep runs on one thread: its two barriers cost more than the
// ~10 ns per constraint it shares, the more so on a loaded machine.
constexpr std::size_t kParallelFrom = std::size_t(1) << 15;

// The last step's forces in the order keep() stored them: the order collect meets them again
// while the lists stand (the same rows, the same partners). The next one is where the cursor
// is, a sequential read where the table's lookup is a cache miss; anything else (the lists
// rebuilt or re-sorted, a pair that held no force, another thread's rows) is looked up in the
// table, which holds the same entries: the same values either way.
class WarmCursor {
 public:
  WarmCursor(const std::vector<PairHistory::Entry>& order, const PairHistory& table, bool use)
      : next_(order.data()),
        end_(use ? order.data() + order.size() : order.data()),
        table_(table) {}
  double find(std::uint64_t key) {
    if (next_ < end_ && next_->key == key) return (next_++)->spring;
    const double force = table_.find(key);
    // Found out of order: a pair or a few that held a force and are not met again (a row this
    // run does not scan, a pair now beyond its lists) are skipped; a larger change waits for
    // the next step, whose order this step's forces set.
    if (force != 0) {
      const PairHistory::Entry* last = end_ - next_ > kLookAhead ? next_ + kLookAhead : end_;
      for (const PairHistory::Entry* e = next_; e < last; ++e)
        if (e->key == key) {
          next_ = e + 1;
          break;
        }
    }
    return force;
  }

 private:
  static constexpr std::ptrdiff_t kLookAhead = 8;
  const PairHistory::Entry* next_;
  const PairHistory::Entry* end_;
  const PairHistory& table_;
};

}  // namespace

void ContactProjection::configure(const ForceModel& model, int threads, int sweeps,
                                  std::size_t grains) {
  model_ = model;
  friction_ = model.contact && model.friction && model.mu > 0;  // ForceModel may be built by hand
  grains_ = grains;
  threads_ = std::max(1, threads);
  sweeps_ = std::max(1, sweeps);
  found_.resize(std::size_t(threads_));
}

std::size_t ContactProjection::bytes() const {
  std::size_t b = 0;
  for (const auto& f : found_) b += f.capacity() * sizeof(Constraint);
  b += constraints_.capacity() * sizeof(Constraint) + incidences_.capacity() * sizeof(Incidence);
  for (const auto* v :
       {&particle_, &count_, &first_, &slot_of_, &held_list_, &island_of_slot_,
        &island_of_constraint_, &active_constraints_, &active_slots_, &active_islands_})
    b += v->capacity() * 4;
  b += islands_.bytes();
  for (const auto* v : {&mobility_, &response_, &moved_x_, &moved_y_, &excess_, &island_worst_})
    b += v->capacity() * 8;
  b += converged_.capacity();
  for (const auto* v : {&spin_mobility_, &turned_}) b += v->capacity() * 8;
  b += held_.capacity() + kept_.capacity() * sizeof(PairHistory::Entry);
  for (const auto* v : {&kept_tangential_, &set_aside_, &set_aside_tangential_})
    b += v->capacity() * sizeof(PairHistory::Entry);
  b += moving_.capacity();
  return b + warm_.bytes() + warm_tangential_.bytes();
}

namespace {

void save_history(std::ostream& out, const PairHistory& history) {
  const auto entries = history.sorted_entries();
  const std::uint64_t count = entries.size();
  out.write(reinterpret_cast<const char*>(&count), 8);
  for (const auto& e : entries) {
    out.write(reinterpret_cast<const char*>(&e.key), 8);
    out.write(reinterpret_cast<const char*>(&e.spring), 8);
  }
}

void load_history(std::istream& in, PairHistory& history) {
  std::uint64_t count = 0;
  in.read(reinterpret_cast<char*>(&count), 8);
  std::vector<PairHistory::Entry> entries(count);
  for (auto& e : entries) {
    in.read(reinterpret_cast<char*>(&e.key), 8);
    in.read(reinterpret_cast<char*>(&e.spring), 8);
  }
  history.assign(&entries, 1);
}

}  // namespace

void ContactProjection::save(std::ostream& out) const {
  save_history(out, warm_);
  if (friction_) save_history(out, warm_tangential_);
}

void ContactProjection::load(std::istream& in) {
  load_history(in, warm_);
  if (friction_) load_history(in, warm_tangential_);
  kept_ = warm_.sorted_entries();
  if (friction_) kept_tangential_ = warm_tangential_.sorted_entries();
  held_.clear();  // rebuilt from warm_ at the next run
  held_list_.clear();
  particle_.clear();
}

// The constraints at the free positions, in the lists' row order of their first particle:
// walls, then pairs (in the grid's rows a same-level pair from its lower sample index, a
// cross-level pair from its finer side, which alone holds it in its list; in an appended row
// every pair, held there alone).
void ContactProjection::collect(const EngineState& s, const NeighbourGrid& grid,
                                const CandidateLists& lists,
                                const std::vector<std::uint32_t>* rows) {
  const std::size_t n = s.size();
  const double* x = s.x.data();
  const double* y = s.y.data();
  const double* d = s.diameter.data();
  const std::uint32_t* origin = s.origin.data();
  const std::uint8_t* frozen = s.frozen.data();
  const std::uint8_t* held = held_.data();
  const std::size_t ordered = lists.grid_rows;
  const std::uint32_t* start = lists.list_start().data();
  const std::uint32_t* list = lists.list().data();
  const Walls walls{model_.half_width};
  const bool warm = warm_.size() > 0;

  const std::size_t scanned = rows ? rows->size() : n;
  const int threads = threads_for(threads_, scanned);
  for (int t = threads; t < threads_; ++t) found_[std::size_t(t)].clear();
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    const std::size_t t = std::size_t(omp_get_thread_num());
    auto& found = found_[t];
    found.clear();
    // The first thread's rows come first, as they did at the last step; the others' start
    // somewhere in the order, which the table does not say: they look every force up.
    WarmCursor held_normal(kept_, warm_, t == 0);
    WarmCursor held_tangential(kept_tangential_, warm_tangential_, t == 0);
#pragma omp for schedule(static)
    for (std::size_t r = 0; r < scanned; ++r) {
      const std::size_t k = rows ? (*rows)[r] : r;
      const std::uint32_t i = lists.particle_of(k, grid);
      const bool alone = k >= ordered;  // an appended row: its pairs are held nowhere else
      const double ri = 0.5 * d[i];
      const std::uint32_t oi = origin[i];
      const std::uint8_t held_i = warm ? held[oi] : 0;
      if (!frozen[i]) {
        const Walls::Gaps gap = walls.gaps(x[i], y[i], ri);
        const double side = std::max(gap.left, gap.right), bottom = gap.bottom;
        const double side_force =
            held_i & partner_bit(kSide) ? held_normal.find(PairHistory::key(oi, kSide)) : 0.0;
        const double floor_force =
            held_i & partner_bit(kFloor) ? held_normal.find(PairHistory::key(oi, kFloor)) : 0.0;
        if (side > -kSkin * ri || side_force > 0)
          found.push_back({i, kSide, 0, 0, side_force, 0, 0, false});
        if (bottom > -kSkin * ri || floor_force > 0)
          found.push_back({i, kFloor, 0, 0, floor_force, 0, 0, false});
      }
      const int own = alone ? -1 : grid.level(i);
      for (std::uint32_t c = start[k], e = start[k + 1]; c < e; ++c) {
        const std::uint32_t j = list[c];
        if (frozen[i] && frozen[j]) continue;
        // A same-level pair is taken once: from its moving side if one is frozen (a frozen
        // particle's list may hold its coarser partners only), else from its lower sample index.
        if (!alone && grid.level(j) == own &&
            (frozen[i] != frozen[j] ? frozen[i] != 0 : origin[j] < oi))
          continue;
        const double dx = x[j] - x[i], dy = y[j] - y[i];
        const double dist2 = dx * dx + dy * dy;
        const double rj = 0.5 * d[j], reach = ri + rj, rmin = std::min(ri, rj);
        const double near = reach + kSkin * rmin;
        double force = 0, tangential = 0;
        if ((held_i & partner_bit(origin[j])) && (held[origin[j]] & partner_bit(oi))) {
          const auto key = PairHistory::key(oi, origin[j]);
          force = held_normal.find(key);
          // A tangential force is kept only with a normal one (keep): most pairs of held
          // grains touch neither, and look it up no more.
          if (friction_ && force > 0) tangential = held_tangential.find(key);
        }
        if (dist2 < near * near || force > 0)
          found.push_back({i, j, 0, 0, force, 0, 0, false, tangential, -tangential / model_.kt, 0});
      }
    }
  }
  constraints_.clear();
  for (const auto& f : found_) constraints_.insert(constraints_.end(), f.begin(), f.end());
}

// Slots for the particles the constraints involve, in order of first appearance, and each
// slot's constraints in constraint order.
void ContactProjection::index_participants(const EngineState& s, const std::vector<double>& drag,
                                           const std::vector<double>* lost, double dt) {
  const std::size_t n = s.size();
  if (slot_of_.size() != n) slot_of_.assign(n, kNone);
  particle_.clear();
  first_.clear();
  auto slot = [&](std::uint32_t p) {
    if (slot_of_[p] == kNone) {
      slot_of_[p] = std::uint32_t(particle_.size());
      particle_.push_back(p);
      first_.push_back(0);
    }
    ++first_[slot_of_[p]];
    return slot_of_[p];
  };
  for (Constraint& c : constraints_) {
    c.slot_a = slot(c.a);
    if (c.b < kSide) c.slot_b = slot(c.b);
  }
  // Counts to offsets; then each slot's incidences in constraint order.
  const std::size_t slots = particle_.size();
  std::uint32_t total = 0;
  for (std::size_t k = 0; k < slots; ++k) {
    const std::uint32_t c = first_[k];
    first_[k] = total;
    total += c;
  }
  first_.push_back(total);
  incidences_.resize(total);
  count_.assign(slots, 0);  // used as fill positions here, then as contact counts
  for (std::uint32_t k = 0; k < constraints_.size(); ++k) {
    const Constraint& c = constraints_[k];
    incidences_[first_[c.slot_a] + count_[c.slot_a]++] = {k, false};
    if (c.b < kSide) incidences_[first_[c.slot_b] + count_[c.slot_b]++] = {k, true};
  }
  std::fill(count_.begin(), count_.end(), 0u);
  mobility_.resize(slots);
  response_.resize(slots);
  moved_x_.assign(slots, 0.0);
  moved_y_.assign(slots, 0.0);
  for (std::size_t k = 0; k < slots; ++k) {
    const std::uint32_t p = particle_[k];
    const double mass = model_.mass(s.diameter[p]);
    const Mobility m = s.frozen[p]           ? Mobility{}
                       : lost && drag[p] > 0 ? mobility_of(drag[p], mass, dt, (*lost)[p])
                                             : mobility_of(drag[p], mass, dt);
    mobility_[k] = m.mobility;
    response_[k] = m.response;
  }
  if (!friction_) return;
  spin_mobility_.resize(slots);
  turned_.resize(slots);
  for (std::size_t k = 0; k < slots; ++k) {
    const std::uint32_t p = particle_[k];
    const double d = s.diameter[p], inertia = 0.1 * model_.mass(d) * d * d;
    spin_mobility_[k] = s.frozen[p] ? 0.0 : 0.5 * dt * dt / inertia;
    turned_[k] = s.frozen[p] ? 0.0 : s.omega[p] * dt;
  }
}

// Union-find over the slots, by the pairs' constraints; islands numbered in order of their first
// slot, so that they do not depend on the thread count.
void ContactProjection::find_islands() {
  const std::size_t slots = particle_.size();
  islands_.assign(slots);
  for (const Constraint& c : constraints_)
    if (c.b < kSide) islands_.unite(c.slot_a, c.slot_b);
  // Each root (the least slot of its island) is numbered before the rest of its island.
  islands_.flatten();
  island_of_slot_.resize(slots);
  std::uint32_t islands = 0;
  for (std::uint32_t k = 0; k < slots; ++k) {
    const std::uint32_t r = islands_.flat_root(k);
    island_of_slot_[k] = r == k ? islands++ : island_of_slot_[r];
  }
  island_of_constraint_.resize(constraints_.size());
  for (std::size_t k = 0; k < constraints_.size(); ++k)
    island_of_constraint_[k] = island_of_slot_[constraints_[k].slot_a];
  excess_.resize(constraints_.size());
  island_worst_.assign(islands, 0.0);
  converged_.assign(islands, 0);
}

// After a solving sweep: the islands whose constraints were all within kTolerance of their
// targets at its start are converged (the sweep moved them once more, as the last sweep of
// one island alone would).
bool ContactProjection::mark_converged() {
  bool all = true;
  auto mark = [&](std::size_t i) {
    if (island_worst_[i] < kTolerance) converged_[i] = 1;
    all = all && converged_[i];
  };
  if (narrowed_)
    for (std::uint32_t i : active_islands_) mark(i);
  else
    for (std::size_t i = 0; i < island_worst_.size(); ++i) mark(i);
  return all;
}

// A converged island stays as it is until the last sweep (which visits every constraint
// again), so leaving it out of the lists changes nothing but the time.
void ContactProjection::narrow() {
  auto keep_unconverged = [&](std::vector<std::uint32_t>& list, std::size_t all,
                              const std::uint32_t* island) {
    if (!narrowed_) {
      list.clear();
      for (std::uint32_t k = 0; k < all; ++k)
        if (!converged_[island ? island[k] : k]) list.push_back(k);
      return;
    }
    std::size_t kept = 0;
    for (std::uint32_t k : list)
      if (!converged_[island ? island[k] : k]) list[kept++] = k;
    list.resize(kept);
  };
  keep_unconverged(active_constraints_, constraints_.size(), island_of_constraint_.data());
  keep_unconverged(active_slots_, particle_.size(), island_of_slot_.data());
  keep_unconverged(active_islands_, converged_.size(), nullptr);
  narrowed_ = true;
}

double ContactProjection::friction_change(Constraint& c, const EngineState& s, double dx, double dy,
                                          double dist, double share_a, double share_b) {
  const std::size_t ka = c.slot_a, kb = c.slot_b;
  const double ra = 0.5 * s.diameter[c.a], rb = 0.5 * s.diameter[c.b];
  const double tx = -dy / dist, ty = dx / dist;
  const double slip = (s.x[c.a] - start_x_[c.a] - (s.x[c.b] - start_x_[c.b])) * tx +
                      (s.y[c.a] - start_y_[c.a] - (s.y[c.b] - start_y_[c.b])) * ty +
                      ra * turned_[ka] + rb * turned_[kb];
  const double g = c.spring + slip, compliance = 1.0 / model_.kt;
  const double spin = ra * ra * spin_mobility_[ka] * std::max<std::uint32_t>(count_[ka], 1) +
                      rb * rb * spin_mobility_[kb] * std::max<std::uint32_t>(count_[kb], 1);
  const double limit = model_.mu * c.lambda;
  const double wanted =
      c.lambda_t + (-g - c.lambda_t * compliance) / (share_a + share_b + spin + compliance);
  const double next = std::clamp(wanted, -limit, limit);
  const double change = next - c.lambda_t;
  c.lambda_t = next;
  return change;
}

void ContactProjection::sweep(EngineState& s, Mode mode) {
  double* x = s.x.data();
  double* y = s.y.data();
  const double* d = s.diameter.data();
  const Walls walls{model_.half_width};
  const double compliance = 1.0 / model_.kn;
  const bool starting = mode == Mode::start, solving = mode == Mode::solve;
  // The change of a force in this sweep (its value when only warming up).
  auto change = [&](double& force, double overlap, double denominator) {
    const double dl =
        solving ? std::max(-force, (overlap - force * compliance) / denominator) : 0.0;
    force += dl;
    return solving ? dl : force;
  };
  // Solving after narrow(), only the islands not yet converged (their lists, in order).
  const bool narrowed = solving && narrowed_;
  const std::uint32_t* only_constraints = narrowed ? active_constraints_.data() : nullptr;
  const std::uint32_t* only_slots = narrowed ? active_slots_.data() : nullptr;
  const std::size_t constraints = narrowed ? active_constraints_.size() : constraints_.size();
  const std::size_t slots = narrowed ? active_slots_.size() : particle_.size();
  const bool parallel = threads_ > 1 && constraints >= kParallelFrom;
  // Solving, the islands already converged stay as they are, and each of the others gets the
  // largest excess of its constraints: on one thread directly, on several through the
  // constraints' own (two threads may share an island).
  const std::uint8_t* done = solving ? converged_.data() : nullptr;
  const std::uint32_t* island = island_of_constraint_.data();
  const std::uint32_t* island_of_slot = island_of_slot_.data();
  double* excess = excess_.data();
  double* island_worst = island_worst_.data();
  if (narrowed)
    for (std::uint32_t i : active_islands_) island_worst[i] = 0;
  else if (solving)
    std::fill(island_worst_.begin(), island_worst_.end(), 0.0);
  auto note = [&](std::size_t k, double e) {
    if (parallel)
      excess[k] = e;
    else
      island_worst[island[k]] = std::max(island_worst[island[k]], e);
  };
#pragma omp parallel num_threads(threads_) if (parallel)
  {
#pragma omp for schedule(static)
    for (std::size_t i = 0; i < constraints; ++i) {
      const std::size_t k = only_constraints ? only_constraints[i] : i;
      Constraint& c = constraints_[k];
      c.mx = c.my = c.mt = 0;
      if (done && done[island[k]]) continue;
      if (solving && parallel) excess[k] = 0;
      const std::uint32_t a = c.a;
      const double ra = 0.5 * d[a];
      const double share_a = mobility_[c.slot_a] * std::max<std::uint32_t>(count_[c.slot_a], 1);
      if (c.b >= kSide) {
        double overlap = ra - y[a], direction = 0;
        if (c.b == kSide) {
          const Walls::Gaps gap = walls.gaps(x[a], y[a], ra);
          const double left = gap.left, right = gap.right;
          overlap = std::max(left, right);
          direction = left > right ? 1.0 : -1.0;
        }
        c.active = overlap > 0 || c.lambda > 0;
        if (starting || !c.active) continue;
        if (solving) note(k, (overlap - c.lambda * compliance) / ra);
        const double f = change(c.lambda, overlap, share_a + compliance);
        (c.b == kSide ? c.mx : c.my) = c.b == kSide ? direction * f : f;
        continue;
      }
      const std::uint32_t b = c.b;
      const double dx = x[b] - x[a], dy = y[b] - y[a];
      const double dist2 = dx * dx + dy * dy;
      const double rb = 0.5 * d[b], reach = ra + rb;
      c.active = (dist2 < reach * reach || c.lambda != 0) && dist2 != 0;
      if (starting || !c.active) continue;
      const double share_b = mobility_[c.slot_b] * std::max<std::uint32_t>(count_[c.slot_b], 1);
      const double dist = std::sqrt(dist2);
      if (solving) note(k, (reach - dist - c.lambda * compliance) / std::min(ra, rb));
      const double u = change(c.lambda, reach - dist, share_a + share_b + compliance) / dist;
      c.mx = -u * dx;
      c.my = -u * dy;
      if (friction_) {
        const double ft =
            solving ? friction_change(c, s, dx, dy, dist, share_a, share_b) : c.lambda_t;
        c.mt = ft;
        c.mx -= ft * dy / dist;
        c.my += ft * dx / dist;
      }
    }
#pragma omp for schedule(static)
    for (std::size_t i = 0; i < slots; ++i) {
      const std::size_t k = only_slots ? only_slots[i] : i;
      if (done && done[island_of_slot[k]]) continue;
      const double w = mobility_[k];
      double dx = 0, dy = 0, torque = 0;
      std::uint32_t count = 0;
      for (std::uint32_t e = first_[k]; e < first_[k + 1]; ++e) {
        const Incidence in = incidences_[e];
        const Constraint& c = constraints_[in.constraint];
        count += c.active;
        const double wk = in.is_b ? -w : w;
        dx += wk * c.mx;
        dy += wk * c.my;
        torque += c.mt;  // either side turns the same way, by its own radius
      }
      count_[k] = count;
      if (starting) continue;
      const std::uint32_t p = particle_[k];
      if (friction_) turned_[k] += spin_mobility_[k] * 0.5 * d[p] * torque;
      x[p] += dx;
      y[p] += dy;
      moved_x_[k] += dx;
      moved_y_[k] += dy;
    }
  }
  if (solving && parallel)
    for (std::size_t i = 0; i < constraints; ++i) {
      const std::size_t k = only_constraints ? only_constraints[i] : i;
      if (!done[island[k]]) island_worst[island[k]] = std::max(island_worst[island[k]], excess[k]);
    }
}

// Each grain of pair `key` (a wall: its grain only) gets the other's bit; a grain beyond the
// sample (a foreign checkpoint's key) none.
void ContactProjection::hold_both(std::uint64_t key) {
  const auto [a, b] = PairHistory::grains(key);
  for (const auto& [o, partner] : {std::pair(a, b), std::pair(b, a)}) {
    if (o >= held_.size()) continue;  // a wall, as a grain, is beyond every sample
    if (!held_[o]) held_list_.push_back(o);
    held_[o] |= partner_bit(partner);
  }
}

void ContactProjection::keep(const EngineState& s, const std::uint8_t* aside) {
  const std::uint32_t* origin = s.origin.data();
  // A pair with a grain set aside keeps its force unless a grain moving in this run is part of
  // it (then this run collected it, from its warm force, and decides it anew).
  set_aside_.clear();
  set_aside_tangential_.clear();
  if (aside) {
    moving_.resize(std::max(grains_, s.size()), 0);
    for (std::uint32_t p : particle_)
      if (!s.frozen[p]) moving_[origin[p]] = 1;
    auto kept_aside = [&](std::uint64_t key) {
      const auto [a, b] = PairHistory::grains(key);
      const bool wall = is_wall(b);
      return (aside[a] || (!wall && aside[b])) && !moving_[a] && (wall || !moving_[b]);
    };
    for (const PairHistory::Entry& e : kept_)
      if (kept_aside(e.key)) set_aside_.push_back(e);
    for (const PairHistory::Entry& e : kept_tangential_)
      if (kept_aside(e.key)) set_aside_tangential_.push_back(e);
    for (std::uint32_t p : particle_) moving_[origin[p]] = 0;
  }
  for (std::uint32_t o : held_list_) held_[o] = 0;
  held_list_.clear();
  kept_.clear();
  kept_tangential_.clear();
  for (const Constraint& c : constraints_) {
    if (c.lambda <= 0) continue;
    const std::uint32_t oa = origin[c.a], ob = c.b >= kSide ? c.b : origin[c.b];
    kept_.push_back({PairHistory::key(oa, ob), c.lambda});
    if (friction_ && c.b < kSide && c.lambda_t != 0)
      kept_tangential_.push_back({PairHistory::key(oa, ob), c.lambda_t});
  }
  kept_.insert(kept_.end(), set_aside_.begin(), set_aside_.end());
  for (const PairHistory::Entry& e : kept_) hold_both(e.key);
  kept_tangential_.insert(kept_tangential_.end(), set_aside_tangential_.begin(),
                          set_aside_tangential_.end());
  warm_.assign(&kept_, 1);
  if (friction_) warm_tangential_.assign(&kept_tangential_, 1);
}

void ContactProjection::append_touching(std::vector<std::uint32_t>& out) const {
  for (std::size_t k = 0; k < particle_.size(); ++k)
    if (count_[k] > 0) out.push_back(particle_[k]);
}

void ContactProjection::mark_touching(std::vector<double>& touching) const {
  std::fill(touching.begin(), touching.end(), 0.0);
  for (std::size_t k = 0; k < particle_.size(); ++k)
    if (count_[k] > 0) touching[particle_[k]] = 1.0;
}

ProjectionFacts ContactProjection::run(EngineState& s, const NeighbourGrid& grid,
                                       const CandidateLists& lists, const std::vector<double>& drag,
                                       double dt, const double* start_x, const double* start_y,
                                       const std::uint8_t* aside,
                                       const std::vector<std::uint32_t>* rows,
                                       const std::vector<double>* lost) {
  const std::size_t n = std::max(grains_, s.size());
  if (held_.size() != n) {  // first run, or after a checkpoint was loaded
    held_.assign(n, 0);
    held_list_.clear();
    for (const PairHistory::Entry& e : kept_) hold_both(e.key);  // kept_ is warm_'s entries
  }
  ProjectionFacts facts;
  collect(s, grid, lists, rows);
  index_participants(s, drag, lost, dt);
  if (friction_ && !(start_x && start_y))
    throw std::invalid_argument("contact projection: friction needs the step's start positions");
  start_x_ = start_x;
  start_y_ = start_y;
  sweep(s, Mode::start);
  for (std::uint32_t c : count_) facts.touching += c > 0;
  if (facts.touching == 0) {  // every particle stays at its free position
    if (warm_.size() > 0) keep(s, aside);
  } else {
    find_islands();
    bool warm = false;
    for (const Constraint& c : constraints_) warm = warm || c.lambda > 0;
    if (warm) sweep(s, Mode::warm);
    // Sweeps until every overlap is within kTolerance of the smaller radius of its compliant
    // target (checked at the positions each sweep starts from), at most sweeps_, each island
    // until its own are; then one more over all, whose forces are kept for the next step.
    narrowed_ = false;
    for (int k = 0; k < sweeps_; ++k) {
      sweep(s, Mode::solve);
      if (mark_converged()) break;
      narrow();
    }
    narrowed_ = false;
    std::fill(converged_.begin(), converged_.end(), 0);
    sweep(s, Mode::solve);
    keep(s, aside);
    const double* d = s.diameter.data();
    for (std::size_t k = 0; k < particle_.size(); ++k) {
      const std::uint32_t p = particle_[k];
      s.vx[p] += response_[k] * moved_x_[k];
      s.vy[p] += response_[k] * moved_y_[k];
      // The spin becomes the turn over the step divided by it (backward Euler). Taking the
      // torque as constant over the step (twice that change) made a rolling grain's spin
      // alternate between nought and twice its rate: the spin has no drag to damp it.
      if (friction_ && !s.frozen[p]) s.omega[p] = turned_[k] / dt;
    }
    const Walls walls{model_.half_width};
    // The overlaps left: the worst, and any deeper than a radius into a wall or than the
    // smaller diameter between two grains (a blow-up).
    for (const Constraint& c : constraints_) {
      const double ra = 0.5 * d[c.a];
      if (c.b >= kSide) {
        const double overlap = c.b == kSide ? walls.side_depth(s.x[c.a], ra) : ra - s.y[c.a];
        if (overlap > ra) facts.blowup.note(s.origin[c.a], "wall overlap", overlap);
        facts.max_overlap_ratio = std::max(facts.max_overlap_ratio, overlap / ra);
      } else {
        const double rb = 0.5 * d[c.b], rmin = std::min(ra, rb);
        const double dx = s.x[c.b] - s.x[c.a], dy = s.y[c.b] - s.y[c.a];
        // Not std::hypot: these overlaps are only reported, and its care for over- and
        // underflow, which no grain's coordinates need, costs a call per constraint.
        const double overlap = ra + rb - std::sqrt(dx * dx + dy * dy);
        if (overlap > 2 * rmin) facts.blowup.note(s.origin[c.a], "overlap", overlap);
        facts.max_overlap_ratio = std::max(facts.max_overlap_ratio, overlap / rmin);
      }
    }
  }
  for (std::uint32_t p : particle_) slot_of_[p] = kNone;
  return facts;
}

}  // namespace sedem
