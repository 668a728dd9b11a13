// What stepping each cluster of members on a step of its own would save: a report for the
// benchmark (EngineStats::own_step_share, largest_cluster) of the clusters as the one-step scheme
// leaves them (integrator.own_steps steps them: local_own_steps.cpp).

#include <algorithm>

#include "core/engine/schedule/local_stepper.h"

namespace sedem {

// Two members whose boxes do not overlap cannot touch before one of the boxes moves, so the
// members fall into clusters joined by overlapping boxes (frozen members' included), each of
// which could take the step its own fastest member allows. A member's rate is the step rule's
// (Integrator::own_rates: its speed over its pace radius; the share is a ratio of rates). The share
// is the members' particle-steps at those steps over the common step's: 1 saves nothing. The
// largest cluster's share of the moving members says whether the clusters percolate (1: one
// cluster).
void LocalStepper::look_at_clusters() {
  Clusters& c = clusters_;
  const std::size_t n = e_.state.size();
  c.sets.assign(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t id = e_.state.origin[k];
    boxes_.overlapping(
        boxes_.box(id), id, [&](std::uint32_t j) { c.sets.unite(std::uint32_t(k), member_[j]); },
        [&](std::uint32_t j) { return member_[j] != kNoMember; });
  }
  c.sets.flatten();
  e_.integrator->own_rates(e_.state, nullptr, c.rate);
  c.fastest.assign(n, 0.0);
  c.moving.assign(n, 0);
  double fastest = 0, moving = 0;
  for (std::size_t k = 0; k < n; ++k) {
    if (e_.state.frozen[k]) continue;
    const double rate = c.rate[k];
    const std::uint32_t root = c.sets.flat_root(std::uint32_t(k));
    c.fastest[root] = std::max(c.fastest[root], rate);
    c.moving[root] += 1;
    fastest = std::max(fastest, rate);
    moving += 1;
  }
  if (!(fastest > 0)) return;  // not known: no member moved
  double own = 0, largest = 0;
  for (std::size_t k = 0; k < n; ++k) {
    own += c.moving[k] * c.fastest[k];
    largest = std::max(largest, c.moving[k]);
  }
  e_.stats.own_step_share = own / (moving * fastest);
  e_.stats.largest_cluster = largest / moving;
}

}  // namespace sedem
