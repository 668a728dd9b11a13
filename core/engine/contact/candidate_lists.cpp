#include "core/engine/contact/candidate_lists.h"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "core/engine/threads_for.h"

namespace sedem {

void CandidateLists::configure(int threads) {
  threads_ = std::max(1, threads);
  local_lists_.resize(std::size_t(threads_));
}

void CandidateLists::rebuild(const EngineState& s, NeighbourGrid& grid, bool frozen_aware) {
  x0 = s.x;
  y0 = s.y;
  widenings.clear();  // the radii now are the build's
  rebuild_at_build_positions(s, grid, frozen_aware);
}

void CandidateLists::rebuild_at_build_positions(const EngineState& s, NeighbourGrid& grid,
                                                bool frozen_aware, std::size_t rows) {
  // A checkpoint's radii are those after its widenings: the build had the first ones' `from`.
  const std::vector<Widening> replay = std::move(widenings);
  widenings.clear();
  for (auto w = replay.rbegin(); w != replay.rend(); ++w) search[w->particle] = w->from;
  const std::size_t n = std::min(rows, s.size());
  grid.build(n, x0.data(), y0.data(), search.data());
  build(grid, n, x0.data(), y0.data(), search.data(), frozen_aware ? s.frozen.data() : nullptr);
  grid_rows = n;
  appended_to_ = n;
  row_particle_.clear();
  append_row_.clear();
  widened_.assign(n, 0);
  stale = false;
  double widest = 0;
  for (std::size_t i = 0; i < n; ++i) widest = std::max(widest, search[i]);
  appended_.reset(widest > 0 ? 2 * widest : 1);
  for (const Widening& w : replay) {
    extend_to(s, grid, w.appended_to);
    widen(grid, w.particle, w.to);
  }
  extend(s, grid);
}

void CandidateLists::extend_to(const EngineState& s, const NeighbourGrid& grid, std::size_t n) {
  if (stale) return;  // the next build takes them (lists not stale have been built)
  n = std::min(n, s.size());
  const double* bx = x0.data();
  const double* by = y0.data();
  const double* radius = search.data();
  for (std::size_t k = appended_to_; k < n; ++k) {
    auto take = [&](std::size_t m) {
      const double dx = bx[m] - bx[k], dy = by[m] - by[k], reach = radius[k] + radius[m];
      if (dx * dx + dy * dy < reach * reach) list_.push_back(std::uint32_t(m));
    };
    for_each_held_near(grid, k, radius[k], take);
    appended_.add(k, bx[k], by[k], radius[k]);
    append_row_.push_back(std::uint32_t(this->rows()));
    row_particle_.push_back(std::uint32_t(k));
    list_start_.push_back(std::uint32_t(list_.size()));
  }
  appended_to_ = std::max(appended_to_, n);
}

void CandidateLists::widen(const NeighbourGrid& grid, std::size_t k, double radius) {
  if (stale || k >= appended_to_ || !(radius > search[k])) return;
  const double before = search[k];
  widenings.push_back({std::uint32_t(k), std::uint32_t(appended_to_), before, radius});
  search[k] = radius;
  const double* bx = x0.data();
  const double* by = y0.data();
  const double* r = search.data();
  // The pairs held are those within the sum of their radii now (the build's, each append's and
  // each widening's own): k's new ones are those its old radius did not reach.
  auto take = [&](std::size_t m) {
    if (m == k) return;
    const double dx = bx[m] - bx[k], dy = by[m] - by[k];
    const double now = radius + r[m], then = before + r[m], squared = dx * dx + dy * dy;
    if (squared < now * now && !(squared < then * then)) list_.push_back(std::uint32_t(m));
  };
  for_each_held_near(grid, k, radius, take);
  if (k < grid_rows) widened_[k] = 1;
  appended_.add(k, bx[k], by[k], radius);
  row_particle_.push_back(std::uint32_t(k));
  list_start_.push_back(std::uint32_t(list_.size()));
}

bool CandidateLists::widenings_fit(std::size_t n) const {
  std::size_t appended = 0;
  for (const Widening& w : widenings) {
    if (w.particle >= n || w.appended_to > n || w.particle >= w.appended_to ||
        w.appended_to < appended || !std::isfinite(w.from) || !std::isfinite(w.to) ||
        !(w.from > 0) || !(w.to > w.from))
      return false;
    appended = w.appended_to;
  }
  return true;
}

void CandidateLists::build(const NeighbourGrid& grid, std::size_t n, const double* bx,
                           const double* by, const double* radius, const std::uint8_t* frozen) {
  const auto& order = grid.order();
  list_start_.resize(n + 1);
  list_start_[0] = 0;
  const int threads = threads_for(threads_, n);
  for (int t = threads; t < threads_; ++t) local_lists_[std::size_t(t)].clear();
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    auto& mine = local_lists_[std::size_t(omp_get_thread_num())];
    mine.clear();
#pragma omp for schedule(static)
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t i = order[k];
      std::uint32_t count = 0;
      grid.for_each_candidate(
          i, bx, by, radius,
          [&](std::uint32_t j) {
            const double dx = bx[j] - bx[i], dy = by[j] - by[i], reach = radius[i] + radius[j];
            if (dx * dx + dy * dy < reach * reach) {
              mine.push_back(j);
              ++count;
            }
          },
          frozen && frozen[i]);
      list_start_[k + 1] = count;
    }
  }
  for (std::size_t k = 0; k < n; ++k) list_start_[k + 1] += list_start_[k];
  list_.resize(list_start_[n]);
  // Static schedule: thread t handled the t-th contiguous block of k, so concatenating the
  // threads' lists in order gives the lists in k order.
  std::size_t at = 0;
  for (const auto& l : local_lists_) {
    std::copy(l.begin(), l.end(), list_.begin() + std::ptrdiff_t(at));
    at += l.size();
  }
}

// A pair's distance shrinks by at most the sum of both moves; the lists hold every pair within
// the interaction range plus margin (r_i + r_j), so they stay complete while
// move_i + move_j < margin (r_i + r_j) for every pair, i.e. while the two largest excesses
// e = move - margin r (1% kept in reserve) sum to less than zero. A small grain carried
// along by a large one thus uses the margin of its partners too, not its own margin alone.
// With margins per grain (local and carried steps) margin r_i is the margin grain i's search
// radius holds. With check_pairs, where the two largest excesses sum to zero or more the pairs
// that could are looked at: sample 5's first minute at 10^5 grains built the lists 7 600 times
// for the sum, and 2 of those times for a pair.
bool CandidateLists::moved_beyond_margin(const EngineState& s) {
  const std::size_t n = s.size();
  const double* x = s.x.data();
  const double* y = s.y.data();
  const double* d = s.diameter.data();
  const double share = 0.99 * 0.5 * margin;
  const bool own = margin_per_grain;
  const int threads = threads_for(threads_, n);
  std::vector<double>& top = top_excess_;
  top.assign(2 * std::size_t(threads), -HUGE_VAL);  // no allocation after the first step
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    double first = -HUGE_VAL, second = -HUGE_VAL;
#pragma omp for schedule(static)
    for (std::size_t i = 0; i < n; ++i) {
      const double dx = x[i] - x0[i], dy = y[i] - y0[i];
      const double excess =
          std::sqrt(dx * dx + dy * dy) - (own ? 0.99 * margin_of(i, d[i]) : share * d[i]);
      if (excess > second) {
        second = std::max(std::min(first, excess), second);
        first = std::max(first, excess);
      }
    }
    const std::size_t t = std::size_t(omp_get_thread_num());
    top[2 * t] = first;
    top[2 * t + 1] = second;
  }
  std::sort(top.begin(), top.end());
  if (!(n > 1 && top[top.size() - 1] + top[top.size() - 2] >= 0)) return false;
  if (!own || !check_pairs) return true;
  // The two largest excesses mostly belong to grains far apart: only a pair whose excesses sum
  // to zero or more and that is within its search radii now can have been left out and be in
  // reach (a pair farther apart is as safe as any the sum rule passes). One of its grains has
  // used up its own margin (a sum of two negative excesses is negative): few have, where most
  // barely use theirs. The other has an excess of at least minus the largest: where the
  // largest is large, that may be most of the members.
  const double first = top.back();
  near_.clear();
  past_.clear();
  double widest = 0;  // of those past their margin
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = x[i] - x0[i], dy = y[i] - y0[i];
    const double excess = std::sqrt(dx * dx + dy * dy) - 0.99 * margin_of(i, d[i]);
    if (excess < -first) continue;
    near_.push_back({std::uint32_t(i), excess, x[i]});
    if (excess < 0) continue;
    past_.push_back(near_.back());
    widest = std::max(widest, search[i]);
  }
  // Those past their margin, along x: each of near_ looks for them within its own search radius
  // and the widest of theirs (the two grains of a pair within its search radii are less than
  // the sum of those radii apart in x).
  std::sort(past_.begin(), past_.end(), [](const Near& a, const Near& b) {
    return a.x < b.x || (a.x == b.x && a.particle < b.particle);
  });
  for (const Near& b : near_) {
    const std::uint32_t j = b.particle;
    const double window = search[j] + widest;
    auto a = std::lower_bound(past_.begin(), past_.end(), b.x - window,
                              [](const Near& p, double at) { return p.x < at; });
    for (; a != past_.end() && a->x < b.x + window; ++a) {
      const std::uint32_t i = a->particle;
      if (i == j || a->excess + b.excess < 0) continue;
      const double dx = x[i] - x[j], dy = y[i] - y[j], reach = search[i] + search[j];
      if (dx * dx + dy * dy < reach * reach) return true;
    }
  }
  return false;
}

void CandidateLists::size_margins(const EngineState& s) {
  for (std::size_t k = 0; k < s.size(); ++k) {
    const double r = 0.5 * s.diameter[k];
    const double own = (search[k] - r * range) / r;  // radii
    const double dx = s.x[k] - x0[k], dy = s.y[k] - y0[k];
    const double used = std::sqrt(dx * dx + dy * dy) / (r * own);
    double next = own;
    if (used > kWidenAbove)
      next = std::min(kWidestMargin * margin, 2 * own);
    else if (used < kNarrowBelow)
      next = std::max(margin, 0.5 * own);
    search[k] = r * (range + next);
  }
}

std::size_t CandidateLists::bytes() const {
  std::size_t b = 0;
  for (const auto& l : local_lists_) b += l.capacity() * 4;
  b += (list_start_.capacity() + list_.capacity() + row_particle_.capacity() +
        append_row_.capacity()) *
       4;
  return b + widened_.capacity() + widenings.capacity() * sizeof(Widening) + appended_.bytes() +
         near_.capacity() * sizeof(Near);
}

}  // namespace sedem
