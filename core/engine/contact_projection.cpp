#include "core/engine/contact_projection.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <istream>
#include <ostream>

namespace sedem {

void ContactProjection::configure(const ForceModel& model, int threads, int sweeps) {
  model_ = model;
  threads_ = std::max(1, threads);
  sweeps_ = std::max(1, sweeps);
  reactions_.resize(std::size_t(threads_));
  worst_.resize(std::size_t(threads_));
  kept_.resize(std::size_t(threads_));
  touching_.resize(std::size_t(threads_));
}

std::size_t ContactProjection::bytes() const {
  std::size_t b = 0;
  for (const auto* v :
       {&moved_x_, &moved_y_, &dx_, &dy_, &pair_force_, &side_force_, &floor_force_})
    b += v->capacity() * 8;
  b += (count_.capacity() + next_count_.capacity()) * 4;
  for (const auto& r : reactions_) b += r.capacity() * sizeof(Reaction);
  for (const auto& r : kept_) b += r.capacity() * sizeof(PairHistory::Entry);
  return b + warm_.bytes();
}

void ContactProjection::save(std::ostream& out) const {
  const auto entries = warm_.sorted_entries();
  const std::uint64_t count = entries.size();
  out.write(reinterpret_cast<const char*>(&count), 8);
  for (const auto& e : entries) {
    out.write(reinterpret_cast<const char*>(&e.key), 8);
    out.write(reinterpret_cast<const char*>(&e.spring), 8);
  }
}

void ContactProjection::load(std::istream& in) {
  std::uint64_t count = 0;
  in.read(reinterpret_cast<char*>(&count), 8);
  std::vector<PairHistory::Entry> entries(count);
  for (auto& e : entries) {
    in.read(reinterpret_cast<char*>(&e.key), 8);
    in.read(reinterpret_cast<char*>(&e.spring), 8);
  }
  warm_.assign(&entries, 1);
}

namespace {

constexpr double kTolerance = 1e-3;
constexpr std::uint32_t kWall = 0xFFFFFFFE, kFloor = 0xFFFFFFFF;  // partners in warm_

}  // namespace

std::size_t ContactProjection::sweep(const EngineState& s, const NeighbourGrid& grid,
                                     const ForcePass& pass, const std::vector<double>& mobility,
                                     Mode mode) {
  const std::size_t n = s.size();
  const double* x = s.x.data();
  const double* y = s.y.data();
  const double* d = s.diameter.data();
  const std::uint32_t* origin = s.origin.data();
  const std::uint8_t* frozen = s.frozen.data();
  const auto& order = grid.order();
  const auto& start = pass.list_start();
  const auto& list = pass.list();
  const double hw = model_.half_width, compliance = 1.0 / model_.kn;
  const bool starting = mode == Mode::start, solving = mode == Mode::solve || mode == Mode::last;
  const bool keep = mode == Mode::last, warm = starting && warm_.size() > 0;
  // The change of a force in this pass, and its new value.
  auto change = [&](double& force, double overlap, double denominator) {
    const double dl =
        solving ? std::max(-force, (overlap - force * compliance) / denominator) : 0.0;
    force += dl;
    return mode == Mode::warm ? force : dl;
  };

#pragma omp parallel num_threads(threads_) if (threads_ > 1)
  {
    const std::size_t t = std::size_t(omp_get_thread_num());
    auto& reactions = reactions_[t];
    auto& kept = kept_[t];
    reactions.clear();
    if (keep) kept.clear();
    std::size_t touching = 0;
    double worst = 0;
#pragma omp for schedule(static)
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t i = order[k];
      const double ri = 0.5 * d[i];
      const double wi = frozen[i] ? 0.0 : mobility[i];
      const double share_i = wi * std::max<std::uint32_t>(count_[i], 1);
      double dxi = 0, dyi = 0;
      std::uint32_t count = 0;
      if (!frozen[i]) {
        const double left = -hw - (x[i] - ri), right = x[i] + ri - hw, bottom = ri - y[i];
        if (starting) {
          side_force_[i] = warm ? warm_.find(PairHistory::key(origin[i], kWall)) : 0.0;
          floor_force_[i] = warm ? warm_.find(PairHistory::key(origin[i], kFloor)) : 0.0;
        }
        const double side = std::max(left, right);
        if (side > 0 || side_force_[i] > 0) {
          ++count;
          if (!starting) {
            worst = std::max(worst, (side - side_force_[i] * compliance) / ri);
            const double f = change(side_force_[i], side, share_i + compliance);
            dxi += (left > right ? wi : -wi) * f;
          }
          if (keep && side_force_[i] > 0)
            kept.push_back({PairHistory::key(origin[i], kWall), side_force_[i]});
        }
        if (bottom > 0 || floor_force_[i] > 0) {
          ++count;
          if (!starting) {
            worst = std::max(worst, (bottom - floor_force_[i] * compliance) / ri);
            dyi += wi * change(floor_force_[i], bottom, share_i + compliance);
          }
          if (keep && floor_force_[i] > 0)
            kept.push_back({PairHistory::key(origin[i], kFloor), floor_force_[i]});
        }
      }
      const int own = grid.level(i);
      for (std::uint32_t c = start[k], e = start[k + 1]; c < e; ++c) {
        const std::uint32_t j = list[c];
        if (frozen[i] && frozen[j]) continue;
        const double dx = x[j] - x[i], dy = y[j] - y[i];
        const double dist2 = dx * dx + dy * dy;
        const double reach = ri + 0.5 * d[j];
        if (starting)
          pair_force_[c] = warm ? warm_.find(PairHistory::key(origin[i], origin[j])) : 0.0;
        if ((dist2 >= reach * reach && pair_force_[c] == 0) || dist2 == 0) continue;
        ++count;
        const bool cross = grid.level(j) != own;
        if (!starting) {
          const double wj = frozen[j] ? 0.0 : mobility[j];
          const double share_j = wj * std::max<std::uint32_t>(count_[j], 1);
          const double dist = std::sqrt(dist2);
          worst = std::max(worst,
                           (reach - dist - pair_force_[c] * compliance) / std::min(ri, 0.5 * d[j]));
          // Same-level pairs are solved from both sides with bitwise equal inputs (the sum of
          // the shares commutes) and opposite (dx, dy): exactly opposite moves.
          const double f = change(pair_force_[c], reach - dist, share_i + share_j + compliance);
          const double u = f / dist;
          dxi -= wi * u * dx;
          dyi -= wi * u * dy;
          if (cross && !frozen[j]) reactions.push_back({j, wj * u * dx, wj * u * dy, 1});
          if (keep && pair_force_[c] > 0 && (cross || origin[i] < origin[j]))
            kept.push_back({PairHistory::key(origin[i], origin[j]), pair_force_[c]});
        } else if (cross && !frozen[j]) {
          reactions.push_back({j, 0, 0, 1});
        }
      }
      dx_[i] = dxi;
      dy_[i] = dyi;
      next_count_[i] = count;
      touching += count > 0;
    }
    touching_[t] = touching;
    worst_[t] = worst;
  }
  residual_ = 0;
  for (double w : worst_) residual_ = std::max(residual_, w);
  std::size_t touching = 0;
  for (int t = 0; t < threads_; ++t) {
    for (const Reaction& r : reactions_[std::size_t(t)]) {
      touching += next_count_[r.j] == 0;
      dx_[r.j] += r.dx;
      dy_[r.j] += r.dy;
      next_count_[r.j] += r.count;
    }
    touching += touching_[std::size_t(t)];
  }
  std::swap(count_, next_count_);
  if (keep) warm_.assign(kept_.data(), kept_.size());
  return touching;
}

std::size_t ContactProjection::run(EngineState& s, const NeighbourGrid& grid, const ForcePass& pass,
                                   const std::vector<double>& mobility,
                                   const std::vector<double>& response) {
  const std::size_t n = s.size();
  dx_.resize(n);
  dy_.resize(n);
  // No zeroing: the first pass sets every force it later reads, and the counts.
  side_force_.resize(n);
  floor_force_.resize(n);
  pair_force_.resize(pass.list().size());
  count_.resize(n);
  next_count_.resize(n);
  // A first pass counts each particle's contacts at the free positions.
  const std::size_t touching = sweep(s, grid, pass, mobility, Mode::start);
  if (touching == 0) {  // every particle stays at its free position
    if (warm_.size() > 0) warm_.assign(nullptr, 0);
    return 0;
  }
  moved_x_.assign(n, 0.0);
  moved_y_.assign(n, 0.0);
  double* x = s.x.data();
  double* y = s.y.data();
  auto move = [&] {
#pragma omp parallel for num_threads(threads_) if (threads_ > 1) schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      x[i] += dx_[i];
      y[i] += dy_[i];
      // The correction summed apart: x - x_free would lose it to round-off on x.
      moved_x_[i] += dx_[i];
      moved_y_[i] += dy_[i];
    }
  };
  if (warm_.size() > 0) {
    sweep(s, grid, pass, mobility, Mode::warm);
    move();
  }
  // Sweeps until every overlap is within kTolerance of the smaller radius of its compliant
  // target (checked at the positions each sweep starts from), at most sweeps_.
  for (int k = 0; k < sweeps_; ++k) {
    sweep(s, grid, pass, mobility, Mode::solve);
    move();
    if (residual_ < kTolerance) break;
  }
  // A last sweep keeps the forces for the next step (and corrects what is left).
  sweep(s, grid, pass, mobility, Mode::last);
  move();
#pragma omp parallel for num_threads(threads_) if (threads_ > 1) schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    s.vx[i] += response[i] * moved_x_[i];
    s.vy[i] += response[i] * moved_y_[i];
  }
  return touching;
}

}  // namespace sedem
