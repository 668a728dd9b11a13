#include <algorithm>
#include <cmath>
#include <istream>
#include <memory>
#include <ostream>
#include <vector>

#include "core/engine/integrate/contact_projection.h"
#include "core/engine/integrate/integration_pass.h"
#include "core/engine/integrate/integrator.h"
#include "core/engine/state/disjoint_sets.h"

namespace sedem {

namespace {

using integration::check;
using integration::integrate;
using integration::ThreadSums;

class ExponentialIntegrator final : public Integrator {
 public:
  ExponentialIntegrator(const IntegratorConfig& c, const IntegratorContext& x)
      : config_(c), ctx_(x) {
    ceiling_ = std::min(config_.max_step, config_.fast_step_factor * ctx_.min_response_time);
    const double d = 2 * ctx_.max_radius;
    settling_ = d > 0 ? ctx_.max_terminal_speed / (d * d) : 0;
    crossing_ = ctx_.model->contact || ctx_.model->drag == DragLaw::di_felice;
    // Before any velocity is known, the largest grain at its settling speed sets the step.
    step_ = limited(ctx_.max_radius > 0 ? ctx_.max_terminal_speed / ctx_.max_radius : 0);
    projection_.configure(*ctx_.model, ctx_.threads, ctx_.contact_sweeps, ctx_.grains);
    carried_ = ctx_.carried_steps && config_.carried_fraction > 0 && ctx_.sample_diameter &&
               ctx_.lists && crossing_;
    substeps_ = carried_ && config_.carried_substeps;
    if (carried_) {
      const std::vector<double>& d = *ctx_.sample_diameter;
      carrier_.resize(d.size());
      largest_.assign(d.size(), 0.0);
      carrying_.assign(d.size());
      touching_.assign(d.size(), 0);
      for (std::size_t i = 0; i < d.size(); ++i) carrier_[i] = 0.5 * d[i];
    }
  }
  const char* name() const override { return "exponential"; }
  double next_step(const PassFacts&) override { return step_; }

  void advance(EngineState& s, const ForceAccumulators& f, double dt, Blowup& blowup) override {
    parts_ = false;
    split_ = substeps_ && dt > 0 && !ctx_.lists->stale && find_fast_set(s, dt);
    if (split_)
      advance_split(s, f, dt, blowup);
    else
      facts_ = move(s, f, dt, blowup, nullptr, nullptr);
    // Carried steps: the local stepper chooses the next step once the members and the lists
    // are up to date (refresh_step).
    if (carried_)
      find_carriers(s);
    else
      step_ = choose_step(s);
  }

  void begin_parts() override {
    split_ = false;
    parts_ = true;
    touched_.clear();
    facts_ = ProjectionFacts{};
  }
  void advance_part(EngineState& s, const ForceAccumulators& f, double dt,
                    const std::vector<std::uint32_t>& only, const std::vector<std::uint32_t>& rows,
                    const std::uint8_t* aside, Blowup& blowup) override {
    const ProjectionFacts facts = move(s, f, dt, blowup, &only, aside, &rows);
    facts_.max_overlap_ratio = std::max(facts_.max_overlap_ratio, facts.max_overlap_ratio);
    projection_.append_touching(touched_);
  }
  void end_parts(const EngineState& s) override {
    std::sort(touched_.begin(), touched_.end());
    facts_.touching = std::size_t(std::unique(touched_.begin(), touched_.end()) - touched_.begin());
    touched_.resize(facts_.touching);
    step_ = choose_step(s);
  }
  void own_rates(const EngineState& s, const std::vector<std::uint32_t>* only,
                 std::vector<double>& rate) const override {
    const double* box = box_pace();
    rate.resize(s.size());
    const std::size_t count = only ? only->size() : s.size();
    for (std::size_t m = 0; m < count; ++m) {
      const std::size_t k = only ? (*only)[m] : m;
      if (s.frozen[k]) {
        rate[k] = 0;
        continue;
      }
      rate[k] = floored_speed(s, k) / pace_radius(s, k, box);
    }
  }
  double step_at_rate(double radii_per_s) const override { return limited(radii_per_s); }

  void refresh_step(const EngineState& s, std::size_t appended_from) override {
    if (appended_from == 0 || appended_from > s.size()) {
      step_ = choose_step(s);
    } else {  // a min of the bounds, which min(step, the joiners' bound) gives to the bit
      const StepLimit before = limit_;
      step_ = std::min(step_, choose_step(s, appended_from));
      limit_.pushed += before.pushed;
      limit_.unpushed_step = std::min(limit_.unpushed_step, before.unpushed_step);
    }
  }
  StepLimit step_limit() const override { return limit_; }
  const std::vector<double>* carrier_radii() const override {
    return carried_ ? &carrier_ : nullptr;
  }

  void contact_facts(PassFacts& facts) const override {
    facts.contacts = facts_.touching;
    facts.max_overlap_ratio = facts_.max_overlap_ratio;
    facts.min_contact_mass = 0;
  }
  void mark_touching(std::vector<double>& touching) const override {
    if (!split_ && !parts_) return projection_.mark_touching(touching);
    std::fill(touching.begin(), touching.end(), 0.0);
    for (std::uint32_t p : touched_) touching[p] = 1.0;
  }
  double travel_in_step(const EngineState& s, std::size_t k) const override {
    return floored_speed(s, k) * step_;
  }
  SubstepReport substeps() const override {
    return split_ ? SubstepReport{fast_.size(), taken_} : SubstepReport{};
  }

  void save(std::ostream& out) const override {
    out.write(reinterpret_cast<const char*>(&step_), 8);
    projection_.save(out);
  }
  void load(std::istream& in) override {
    in.read(reinterpret_cast<char*>(&step_), 8);
    projection_.load(in);
    limit_ = {};  // a report only: not kept, not known until the step is next chosen
    if (carried_) find_carriers(*ctx_.state);  // the state is loaded first
  }
  std::size_t bytes() const override {
    return projection_.bytes() + drag_memo_.capacity() * sizeof(DragMemo) +
           (drag_.capacity() + lost_.capacity() + start_x_.capacity() + start_y_.capacity() +
            carrier_.capacity()) *
               8 +
           carrying_.bytes() + carried_ids_.capacity() * 4 + touching_.capacity() +
           still_.capacity() + largest_.capacity() * 8 + in_fast_.capacity() + aside_.capacity() +
           (fast_.capacity() + others_.capacity() + touched_.capacity() + fast_rows_.capacity()) *
               4;
  }

 private:
  IntegratorConfig config_;
  IntegratorContext ctx_;
  std::vector<ThreadSums> sums_;
  ContactProjection projection_;
  std::vector<double> start_x_, start_y_;  // friction: the positions at the step's start
  // The free update and the contact projection over dt: of every particle not frozen, or of
  // those `only` lists (the others frozen by the caller, and by sample index `aside`, whose
  // pairs' forces the projection keeps). Notes the first blow-up it sees.
  ProjectionFacts move(EngineState& s, const ForceAccumulators& f, double dt, Blowup& blowup,
                       const std::vector<std::uint32_t>* only, const std::uint8_t* aside,
                       const std::vector<std::uint32_t>* rows = nullptr) {
    const ForceModel& m = *ctx_.model;
    const bool project = m.contact && !m.contact_forces && ctx_.grid && ctx_.lists;
    // Without the force pass a free particle feels only weight, buoyancy and drag.
    const bool pass_forces = needs_force_pass(m);
    if (project) {
      drag_.resize(s.size());
      lost_.resize(s.size());
    }
    const bool memo = m.drag == DragLaw::di_felice && m.voidage_excludes_self;
    if (memo) drag_memo_.resize(s.size());
    // Friction needs the tangential motion over the step: the positions before it.
    const bool friction = project && projection_.friction();
    if (friction) {
      start_x_.assign(s.x.begin(), s.x.end());
      start_y_.assign(s.y.begin(), s.y.end());
    }
    // Free update: the forces of the pass (no contact force when contacts are projected), the
    // lubrication's stiffness folded into the damping.
    const std::size_t count = only ? only->size() : s.size();
    const ThreadSums sums =
        integrate(ctx_.threads, count, sums_, [&](std::size_t k, ThreadSums& t) {
          const std::size_t i = only ? (*only)[k] : k;
          if (s.frozen[i]) return;
          const double d = s.diameter[i];
          const double mass = m.mass(d);
          const double vx = s.vx[i], vy = s.vy[i];
          double c = ctx_.drag.coefficient(d, s.weight[i], std::sqrt(vx * vx + vy * vy), s.x[i],
                                           s.y[i], memo ? &drag_memo_[i] : nullptr, s.origin[i]);
          if (pass_forces) c += f.lubrication_stiffness[i] * dt;
          const double fx = pass_forces ? f.fx[i] : 0.0;
          const double fy = pass_forces ? f.fy[i] : m.gravity_force(d);
          if (project) drag_[i] = c;
          if (c > 0) {
            const double rate = c / mass;
            const double lost = decay_lost(c, mass, dt);
            if (project) lost_[i] = lost;  // the projection's mobility needs it too
            const double decay = 1.0 + lost;
            const double relax = -lost / rate;      // integral of the decay over dt
            const double ux = fx / c, uy = fy / c;  // velocity the step tends to
            s.x[i] += ux * dt + (vx - ux) * relax;
            s.y[i] += uy * dt + (vy - uy) * relax;
            s.vx[i] = ux + (vx - ux) * decay;
            s.vy[i] = uy + (vy - uy) * decay;
          } else {
            const double ax = fx / mass, ay = fy / mass;
            s.x[i] += dt * (vx + 0.5 * dt * ax);
            s.y[i] += dt * (vy + 0.5 * dt * ay);
            s.vx[i] += dt * ax;
            s.vy[i] += dt * ay;
          }
          check(s, i, ctx_.runaway_speed, t.blowup);
        });
    if (sums.blowup.found && !blowup.found) blowup = sums.blowup;
    ProjectionFacts facts;
    if (project && dt > 0) {
      facts = projection_.run(s, *ctx_.grid, *ctx_.lists, drag_, dt,
                              friction ? start_x_.data() : nullptr,
                              friction ? start_y_.data() : nullptr, aside, rows, &lost_);
      if (facts.blowup.found && !blowup.found) blowup = facts.blowup;
      Blowup moved;
      for (std::uint32_t p : projection_.participants())
        if (!s.frozen[p]) check(s, p, ctx_.runaway_speed, moved);
      if (moved.found && !blowup.found) blowup = moved;
    }
    return facts;
  }

  // Carried sub-steps: the members the step dt would carry further than crossing_fraction of
  // their own radius (held against a coarser grain), and every member a listed pair could bring
  // within the projection's skin of them over dt, at the set's fastest closing speed (grown
  // until none is left): the fast set. No pair of the fast set and the others can then meet
  // within dt, so each takes its steps apart, every grain within its own radius's rule.
  bool find_fast_set(const EngineState& s, double dt) {
    const double c = config_.crossing_fraction;
    const std::size_t n = s.size();
    in_fast_.assign(n, 0);
    fast_.clear();
    others_.clear();
    closing_.resize(n);
    double fastest = 0;
    for (std::size_t k = 0; k < n; ++k) {
      closing_[k] = closing_speed(s, k);
      if (s.frozen[k] || floored_speed(s, k) * dt <= c * 0.5 * s.diameter[k]) continue;
      in_fast_[k] = 1;
      fast_.push_back(std::uint32_t(k));
      fastest = std::max(fastest, closing_[k]);
    }
    if (fast_.empty()) return false;
    const CandidateLists& lists = *ctx_.lists;
    const std::vector<std::uint32_t>& start = lists.list_start();
    const std::vector<std::uint32_t>& list = lists.list();
    const std::size_t listed = lists.rows();
    // The rows that hold a pair with a grain of the set, from the pass that added none: the
    // only ones its sub-steps' projection reads.
    for (bool grew = true; grew;) {
      grew = false;
      fast_rows_.clear();
      for (std::size_t k = 0; k < listed; ++k) {
        const std::uint32_t i = lists.particle_of(k, *ctx_.grid);
        if (i >= n) continue;
        bool fast_row = in_fast_[i];
        for (std::uint32_t q = start[k]; q < start[k + 1]; ++q) {
          const std::uint32_t j = list[q];
          if (j >= n) continue;
          fast_row = fast_row || in_fast_[j];
          if (in_fast_[i] == in_fast_[j]) continue;
          const std::uint32_t other = in_fast_[i] ? j : i;
          if (s.frozen[other]) continue;  // a partner of both, never moved
          const double ri = 0.5 * s.diameter[i], rj = 0.5 * s.diameter[j];
          const double near =
              (fastest + closing_[other]) * dt + ri + rj + kFastSkin * std::min(ri, rj);
          const double dx = s.x[i] - s.x[j], dy = s.y[i] - s.y[j];
          if (dx * dx + dy * dy >= near * near) continue;
          in_fast_[other] = 1;
          fast_.push_back(other);
          fastest = std::max(fastest, closing_[other]);
          grew = true;
        }
        if (fast_row) fast_rows_.push_back(std::uint32_t(k));
      }
    }
    for (std::size_t k = 0; k < n; ++k)
      if (!s.frozen[k] && !in_fast_[k]) others_.push_back(std::uint32_t(k));
    return true;
  }

  // The fast set over dt in sub-steps of its own radius's rule, the others held frozen; then the
  // others over dt in one, the fast set held frozen.
  void advance_split(EngineState& s, const ForceAccumulators& f, double dt, Blowup& blowup) {
    aside_.resize(std::max(ctx_.grains, s.size()), 0);
    auto set_aside = [&](const std::vector<std::uint32_t>& set, std::uint8_t on) {
      for (std::uint32_t k : set) {
        s.frozen[k] = on;
        aside_[s.origin[k]] = on;
      }
    };
    touched_.clear();
    facts_ = ProjectionFacts{};
    auto note = [&](const ProjectionFacts& facts) {  // its blow-ups are in `blowup` already
      facts_.max_overlap_ratio = std::max(facts_.max_overlap_ratio, facts.max_overlap_ratio);
    };
    set_aside(others_, 1);
    double left = dt;
    taken_ = 0;
    while (left > 0 && !blowup.found) {
      double radii_per_s = 0;
      for (std::uint32_t k : fast_)
        radii_per_s = std::max(radii_per_s, 2 * floored_speed(s, k) / s.diameter[k]);
      // Equal parts of what is left, so that none is a sliver (a step of a few ns turns the
      // projection's corrections into runaway speeds).
      const double parts = std::ceil(left / limited(radii_per_s));
      const double sub = parts <= 1 ? left : left / parts;
      if (!(sub > 0)) {
        blowup.note(s.origin[fast_.front()], "sub-step", sub);
        break;
      }
      note(move(s, f, sub, blowup, &fast_, aside_.data(), &fast_rows_));
      left = parts <= 1 ? 0 : left - sub;
      ++taken_;
    }
    projection_.append_touching(touched_);
    set_aside(others_, 0);
    if (!others_.empty()) {
      set_aside(fast_, 1);
      note(move(s, f, dt, blowup, &others_, aside_.data()));
      projection_.append_touching(touched_);
      set_aside(fast_, 0);
    }
    // A frozen grain touching grains of both sets is one particle in contact.
    std::sort(touched_.begin(), touched_.end());
    facts_.touching = std::size_t(std::unique(touched_.begin(), touched_.end()) - touched_.begin());
    touched_.resize(facts_.touching);
  }

  // The ceiling, or less where a grain moving at `radii_per_s` would cross too far.
  double limited(double radii_per_s) const {
    if (!crossing_ || radii_per_s <= 0) return ceiling_;
    return std::min(ceiling_, config_.crossing_fraction / radii_per_s);
  }
  // The fastest moving grain, in its radii per second. A free grain may reach its settling
  // speed within the next step; one in a contact constraint moves as the projection left it.
  double fastest(const EngineState& s, std::size_t from = 0) {
    if (!crossing_) {
      limit_ = {};
      return 0;
    }
    constrained_.resize(s.size());
    const bool marked = !ctx_.members_only;
    if (marked)
      for (std::uint32_t p : projection_.participants()) constrained_[p] = 1;
    // Local steps: a member's box may let it travel less than its own radius.
    const double* box = box_pace();
    const int threads = from == 0 ? ctx_.threads : 1;  // a few joiners: not worth a thread
    const ThreadSums sums =
        integrate(threads, s.size() - from, sums_, [&](std::size_t k, ThreadSums& t) {
          const std::size_t i = from + k;
          if (s.frozen[i]) return;
          const double d = s.diameter[i];
          const double v2 = s.vx[i] * s.vx[i] + s.vy[i] * s.vy[i];
          const double free_settling = settling_ * d * d;
          const double settling = constrained_[i] ? 0.0 : free_settling;
          const double speed = std::sqrt(std::max(v2, settling * settling));
          // speed / (d / 2) is 2 speed / d to the bit: one rounding of the same quotient.
          const double pace = pace_radius(s, i, box);
          t.max_radii_per_s = std::max(t.max_radii_per_s, speed / pace);
          const double pushed = free_settling * StepLimit::kPushedSpeedRatio;
          if (v2 > pushed * pushed)
            ++t.pushed;
          else
            t.max_unpushed_radii_per_s = std::max(t.max_unpushed_radii_per_s, speed / pace);
        });
    if (marked)
      for (std::uint32_t p : projection_.participants()) constrained_[p] = 0;
    limit_ = {sums.pushed, limited(sums.max_unpushed_radii_per_s)};
    return sums.max_radii_per_s;
  }

  // The step for particles from..end (and, with carried steps, the pairs in their rows).
  double choose_step(const EngineState& s, std::size_t from = 0) {
    const CandidateLists& lists = *ctx_.lists;
    if (carried_ && !lists.stale) {
      const double step = carried_step(s, from);
      limit_ = {0, 0};
      return step;
    }
    return limited(fastest(s, from));
  }

  // Carried steps: the moving grains held together by the forces the last step left (the
  // projection's held pairs), as sets (union-find), each grain given its set's largest radius.
  // A frozen grain carries nothing: a grain resting on the bed keeps its own pace.
  void find_carriers(const EngineState& s) {
    const std::vector<double>& d = *ctx_.sample_diameter;
    still_.resize(d.size(), 0);
    for (std::size_t k = 0; k < s.size(); ++k)
      if (s.frozen[k]) still_[s.origin[k]] = 1;
    for (std::uint32_t id : carried_ids_) {
      carrier_[id] = 0.5 * d[id];
      carrying_.make_single(id);
      touching_[id] = 0;
    }
    carried_ids_.clear();
    for (const PairHistory::Entry& e : projection_.held_pairs()) {
      const auto [a, b] = PairHistory::grains(e.key);
      if (ContactProjection::is_wall(b) || a >= d.size() || b >= d.size() || still_[a] || still_[b])
        continue;
      carried_ids_.push_back(a);
      carried_ids_.push_back(b);
      carrying_.unite(a, b);
    }
    for (std::uint32_t id : carried_ids_) {
      const std::uint32_t r = carrying_.root(id);
      largest_[r] = std::max(largest_[r], 0.5 * d[id]);
    }
    const double scale = config_.carried_fraction / config_.crossing_fraction;
    any_carried_ = false;
    for (std::uint32_t id : carried_ids_) {
      carrier_[id] = std::max(0.5 * d[id], scale * largest_[carrying_.root(id)]);
      any_carried_ = any_carried_ || carrier_[id] > 0.5 * d[id];
      touching_[id] = 1;
    }
    for (std::uint32_t id : carried_ids_) largest_[id] = 0;
    for (std::size_t k = 0; k < s.size(); ++k) still_[s.origin[k]] = 0;
  }

  // Carried steps: the longest step in which no moving grain travels more than
  // crossing_fraction of its pace radius (its carrier's radius, within its lists' margin and
  // its box's allowance), and no listed pair closes by more than its gap plus
  // crossing_fraction (r_i + r_j). Speeds count at least the settling speed, as fastest() does;
  // a pair's closing speed counts both (each may reach it within the step). Needs fresh lists.
  double carried_step(const EngineState& s, std::size_t from) {
    const CandidateLists& lists = *ctx_.lists;
    const double* box = box_pace();
    const double c = config_.crossing_fraction;
    const std::size_t n = s.size();
    double rate = 0;  // per second: the inverse of the longest step allowed
    closing_.resize(n);
    for (std::size_t k = from; k < n; ++k) {
      closing_[k] = closing_speed(s, k);
      if (s.frozen[k]) continue;
      // A grain that touches nothing keeps its own radius, which its lists' margin always
      // allows; its box may allow less.
      const std::uint32_t id = s.origin[k];
      double pace = 0.5 * s.diameter[k];
      if (touching_[id])
        pace = std::min(carrier_[id], lists.margin_of(k, s.diameter[k]) / lists.margin);
      if (box) pace = std::min(pace, box[k]);
      rate = std::max(rate, floored_speed(s, k) / (c * pace));
    }
    // With every grain at its own radius's pace no pair can close by more than the pair rule
    // allows: the grains' own bounds above are the one-rate scheme's.
    if (!any_carried_) return rate > 0 ? std::min(ceiling_, 1.0 / rate) : ceiling_;
    const std::vector<std::uint32_t>& start = lists.list_start();
    const std::vector<std::uint32_t>& list = lists.list();
    const std::size_t listed = lists.rows();
    // A pair closes at most at the sum of both speeds (floors included): most pairs are then
    // far enough apart not to bind, which their squared distance tells without a root. The
    // pairs of particles appended from `from` on are in the rows from theirs on.
    for (std::size_t k = lists.first_row_from(from); k < listed; ++k) {
      const std::uint32_t i = lists.particle_of(k, *ctx_.grid);
      if (i >= n) continue;
      for (std::uint32_t q = start[k]; q < start[k + 1]; ++q) {
        const std::uint32_t j = list[q];
        if (j >= n) continue;
        const double reach = 0.5 * (s.diameter[i] + s.diameter[j]);
        const double apart = (closing_[i] + closing_[j]) / rate - c * reach + reach;
        const double dx = s.x[i] - s.x[j], dy = s.y[i] - s.y[j];
        if (rate > 0 && (apart <= 0 || dx * dx + dy * dy >= apart * apart)) continue;
        rate = std::max(rate, pair_rate(s, i, j));
      }
    }
    return rate > 0 ? std::min(ceiling_, 1.0 / rate) : ceiling_;
  }

  // The inverse of the longest step in which particles i and j (state indices) close by at
  // most their gap plus crossing_fraction (r_i + r_j).
  double pair_rate(const EngineState& s, std::size_t i, std::size_t j) const {
    if (!carried_ || (s.frozen[i] && s.frozen[j])) return 0;
    const double ri = 0.5 * s.diameter[i], rj = 0.5 * s.diameter[j];
    const double dvx = s.vx[i] - s.vx[j], dvy = s.vy[i] - s.vy[j];
    const double dx = s.x[i] - s.x[j], dy = s.y[i] - s.y[j];
    const double closing = std::sqrt(dvx * dvx + dvy * dvy) + floor_of(s, i) + floor_of(s, j);
    const double gap = std::max(0.0, std::sqrt(dx * dx + dy * dy) - ri - rj);
    return closing / (gap + config_.crossing_fraction * (ri + rj));
  }
  // A moving grain's clear-water settling speed, which a free grain may reach within a step (0
  // for a frozen one), and its speed counted at least at that.
  double floor_of(const EngineState& s, std::size_t k) const {
    return s.frozen[k] ? 0.0 : settling_ * s.diameter[k] * s.diameter[k];
  }
  // The most a grain can add to a pair's closing speed within a step: its speed and its
  // settling speed, which it may gain (0 for a frozen one).
  double closing_speed(const EngineState& s, std::size_t k) const {
    return s.frozen[k] ? 0.0 : std::sqrt(s.vx[k] * s.vx[k] + s.vy[k] * s.vy[k]) + floor_of(s, k);
  }
  // Local steps: the members' pace radii by state index (nullptr: each moves at its own radius).
  const double* box_pace() const {
    return ctx_.allowance && !ctx_.allowance->empty() ? ctx_.allowance->data() : nullptr;
  }
  // The radius member k's step rule counts its travel in: its own, or less where its box allows
  // less.
  static double pace_radius(const EngineState& s, std::size_t k, const double* box) {
    const double r = 0.5 * s.diameter[k];
    return box ? std::min(r, box[k]) : r;
  }
  double floored_speed(const EngineState& s, std::size_t k) const {
    const double v2 = s.vx[k] * s.vx[k] + s.vy[k] * s.vy[k], floor = floor_of(s, k);
    return std::sqrt(std::max(v2, floor * floor));
  }

  bool carried_ = false;
  bool any_carried_ = false;  // some grain's pace is more than its own radius
  // Carried sub-steps (integrator.carried_substeps): whether the last advance split, its fast
  // set and the others (state indices), by sample index those set aside in a run, the
  // particles in contact after it, and the sub-steps it took.
  bool substeps_ = false, split_ = false;
  bool parts_ = false;  // the last step was taken in parts (own steps): touched_ holds its contacts
  static constexpr double kFastSkin = 0.5;  // the projection's skin, in smaller radii
  std::vector<std::uint8_t> in_fast_, aside_;
  std::vector<std::uint32_t> fast_, others_, touched_, fast_rows_;
  std::size_t taken_ = 0;
  std::vector<double> carrier_;  // by sample index: see carrier_radii()
  std::vector<double> largest_;  // find_carriers' scratch: each set's largest radius, at its root
  DisjointSets carrying_;        // find_carriers' sets, by sample index
  std::vector<std::uint32_t> carried_ids_;  // their members
  std::vector<double> closing_;         // carried_step's scratch: each particle's speed and floor
  std::vector<std::uint8_t> touching_;  // by sample index: in carried_ids_
  std::vector<std::uint8_t> still_;     // find_carriers' scratch, by sample index: frozen
  std::vector<double> drag_;            // per particle: its drag coefficient over this step
  std::vector<double> lost_;            // and its decay_lost, where the drag is not 0
  std::vector<DragMemo> drag_memo_;     // per particle: what its last drag found in its cell
  std::vector<std::uint8_t> constrained_;  // per particle, zero between steps
  ProjectionFacts facts_;
  double step_ = 0, ceiling_ = 0;
  StepLimit limit_;      // of step_
  double settling_ = 0;  // clear-water settling speed / d^2
  bool crossing_ = false;
};

}  // namespace

std::unique_ptr<Integrator> make_exponential_integrator(const IntegratorConfig& config,
                                                        const IntegratorContext& context) {
  return std::make_unique<ExponentialIntegrator>(config, context);
}

}  // namespace sedem
