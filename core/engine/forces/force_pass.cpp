#include "core/engine/forces/force_pass.h"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "core/engine/contact/walls.h"

namespace sedem {

void ForcePass::configure(const ForceModel& model, int threads) {
  model_ = model;
  threads_ = std::max(1, threads);
  reactions_.resize(std::size_t(threads_));
  springs_.resize(std::size_t(threads_));
  facts_.resize(std::size_t(threads_));
}

std::size_t ForcePass::bytes() const {
  std::size_t b = 0;
  for (const auto& r : reactions_) b += r.capacity() * sizeof(Reaction);
  for (const auto& e : springs_) b += e.capacity() * sizeof(PairHistory::Entry);
  return b;
}

namespace {
// A blow-up, not a contact: deeper than the smaller grain's diameter and than the larger grain's
// radius. A large grain may step half its radius into a fine one before the contact resolves.
inline bool too_deep(double overlap, double ri, double rj) {
  return overlap > std::max(2 * std::min(ri, rj), std::max(ri, rj));
}
}  // namespace

void ForcePass::run(const EngineState& s, const NeighbourGrid& grid, const CandidateLists& lists,
                    const PairHistory& old_springs, PairHistory& new_springs, double dt,
                    ForceAccumulators& out, PassFacts& facts) {
  const std::size_t n = s.size();
  const ForceModel& m = model_;
  const double* x = s.x.data();
  const double* y = s.y.data();
  const double* vx = s.vx.data();
  const double* vy = s.vy.data();
  const double* w = s.omega.data();
  const double* d = s.diameter.data();
  const std::uint32_t* origin = s.origin.data();
  const std::uint8_t* frozen = s.frozen.data();
  const auto& order = grid.order();
  const std::uint32_t* list_start = lists.list_start().data();
  const std::uint32_t* list = lists.list().data();
  const Walls walls{m.half_width};
  const double reach = m.lubrication_reach();
  const double pair_stiffness = 2 * (m.kn + (m.friction ? m.kt : 0.0));

#pragma omp parallel num_threads(threads_) if (threads_ > 1)
  {
    const std::size_t t = std::size_t(omp_get_thread_num());
    auto& reactions = reactions_[t];
    auto& springs = springs_[t];
    ThreadFacts& tf = facts_[t];
    reactions.clear();
    springs.clear();
    tf = ThreadFacts{};

#pragma omp for schedule(static)
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t i = order[k];
      const double ri = 0.5 * d[i];
      double fx = 0, fy = m.gravity_force(d[i]), tq = 0, stiff = 0, spin = 0, lub = 0;
      bool touching = false, close = false;
      double worst = 0;

      if (m.contact && !frozen[i]) {
        const Walls::Gaps gap = walls.gaps(x[i], y[i], ri);
        const double left = gap.left, right = gap.right, bottom = gap.bottom;
        const double kw = m.contact_forces ? m.kn : 0.0;
        if (left > 0)
          fx += kw * left, stiff += m.kn, worst = std::max(worst, left), touching = true;
        if (right > 0)
          fx -= kw * right, stiff += m.kn, worst = std::max(worst, right), touching = true;
        if (bottom > 0)
          fy += kw * bottom, stiff += m.kn, worst = std::max(worst, bottom), touching = true;
        if (worst > ri) tf.blowup.note(origin[i], "wall overlap", worst);
        close = std::max(left, std::max(right, bottom)) > -m.skin * ri;
        worst /= ri;
      }

      if (m.contact || m.lubrication) {
        const int own = grid.level(i);
        for (std::uint32_t c = list_start[k], e = list_start[k + 1]; c < e; ++c) {
          const std::uint32_t j = list[c];
          if (frozen[i] && frozen[j]) continue;
          const bool cross = grid.level(j) != own;  // found from this side only
          const double dx = x[j] - x[i], dy = y[j] - y[i];
          const double dist2 = dx * dx + dy * dy;
          const double rj = 0.5 * d[j];
          const double cutoff = (ri + rj) * (1 + m.skin) + reach * std::max(ri, rj);
          if (dist2 >= cutoff * cutoff || dist2 == 0) continue;
          const double dist = std::sqrt(dist2);
          const double nx = dx / dist, ny = dy / dist;  // from i to j
          const double overlap = ri + rj - dist;
          double jfx = 0, jfy = 0, jtq = 0, jstiff = 0, jspin = 0, jlub = 0;
          if (m.contact && overlap > -m.skin * (ri + rj)) close = true;

          if (m.contact && overlap > 0 && !m.contact_forces) {
            stiff += pair_stiffness;
            touching = true;
            worst = std::max(worst, overlap / std::min(ri, rj));
            if (too_deep(overlap, ri, rj)) tf.blowup.note(origin[i], "overlap", overlap);
            if (cross) jstiff += pair_stiffness;
          } else if (m.contact && overlap > 0) {
            const bool i_first = origin[i] < origin[j];
            const std::uint32_t a = i_first ? i : j, b = i_first ? j : i;
            const std::uint64_t key = PairHistory::key(origin[i], origin[j]);
            const double sa = i_first ? 1.0 : -1.0;  // n from a to b
            const double old = m.friction ? old_springs.find(key) : 0.0;
            const ContactResult c =
                contact_force(m, sa * nx, sa * ny, overlap, 0.5 * d[a], 0.5 * d[b], vx[a], vy[a],
                              w[a], vx[b], vy[b], w[b], old, dt);
            const double cfx = i_first ? c.fx : -c.fx, cfy = i_first ? c.fy : -c.fy;
            fx += cfx;
            fy += cfy;
            tq += i_first ? c.torque_a : c.torque_b;
            stiff += pair_stiffness;
            if (m.friction) spin += 2 * m.kt * ri * ri;
            touching = true;
            worst = std::max(worst, overlap / std::min(ri, rj));
            if (too_deep(overlap, ri, rj)) tf.blowup.note(origin[i], "overlap", overlap);
            if (cross) {
              jfx -= cfx;
              jfy -= cfy;
              jtq += i_first ? c.torque_b : c.torque_a;
              jstiff += pair_stiffness;
              if (m.friction) jspin += 2 * m.kt * rj * rj;
            }
            if (m.friction && (cross || i_first)) springs.push_back({key, c.spring});
          }

          if (m.lubrication) {
            const double gap = -overlap;
            if (gap < reach * ri) {
              const double f = lubrication_force(m, d[i], d[j], gap);
              fx -= f * nx;
              fy -= f * ny;
              stiff += 2 * f * m.lubrication_range / ri;
              lub += 2 * f * m.lubrication_range / ri;
            }
            if (cross && gap < reach * rj) {
              const double f = lubrication_force(m, d[j], d[i], gap);
              jfx += f * nx;
              jfy += f * ny;
              jstiff += 2 * f * m.lubrication_range / rj;
              jlub += 2 * f * m.lubrication_range / rj;
            }
          }
          if (cross && !frozen[j] && (jfx != 0 || jfy != 0 || jtq != 0 || jstiff != 0))
            reactions.push_back({j, jfx, jfy, jtq, jstiff, jspin, jlub});
        }
      }

      out.fx[i] = fx;
      out.fy[i] = fy;
      out.torque[i] = tq;
      out.stiffness[i] = stiff;
      out.spin_stiffness[i] = spin;
      out.lubrication_stiffness[i] = lub;
      if (touching) ++tf.contacts;
      if (touching || close) {
        const double mass = m.mass(d[i]);
        if (tf.min_contact_mass == 0 || mass < tf.min_contact_mass) tf.min_contact_mass = mass;
      }
      tf.max_overlap_ratio = std::max(tf.max_overlap_ratio, worst);
    }
  }

  // Partners' shares of the cross-level pairs, in thread order.
  facts = PassFacts{};
  for (int t = 0; t < threads_; ++t) {
    for (const Reaction& r : reactions_[std::size_t(t)]) {
      out.fx[r.j] += r.fx;
      out.fy[r.j] += r.fy;
      out.torque[r.j] += r.torque;
      if (out.stiffness[r.j] == 0 && r.stiffness > 0) ++facts.contacts;
      out.stiffness[r.j] += r.stiffness;
      out.spin_stiffness[r.j] += r.spin_stiffness;
      out.lubrication_stiffness[r.j] += r.lubrication_stiffness;
    }
    const ThreadFacts& tf = facts_[std::size_t(t)];
    facts.contacts += tf.contacts;
    if (tf.min_contact_mass > 0 &&
        (facts.min_contact_mass == 0 || tf.min_contact_mass < facts.min_contact_mass))
      facts.min_contact_mass = tf.min_contact_mass;
    facts.max_overlap_ratio = std::max(facts.max_overlap_ratio, tf.max_overlap_ratio);
    if (tf.blowup.found && !facts.blowup.found) facts.blowup = tf.blowup;
  }
  if (m.friction && m.contact && m.contact_forces)
    new_springs.assign(springs_.data(), springs_.size());
}

}  // namespace sedem
