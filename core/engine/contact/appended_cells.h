#pragma once

// The particles appended to the candidate lists since their last build, hashed by cell, so that
// the row of a newly appended particle need not look at every other one: at a million grains
// thousands join the members between two builds, and looking at each pair of them was 8 % of
// the run. Its answer is the pairwise scan's to the bit: candidates in increasing index. A grain
// of the grid's rows whose search radius widened since the build is added too (the grid's
// blocks are sized by the radii it was built with), so a particle may be added more than once.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sedem {

class AppendedCells {
 public:
  // Empties it, for particles hashed in square cells of side `cell` (any positive side is
  // correct; about a search diameter keeps a query to a few cells).
  void reset(double cell);
  // Adds particle m at (x, y) with search radius reach.
  void add(std::size_t m, double x, double y, double reach);
  // Calls visit(m), in increasing m and once each, for every particle added whose cell lies within
  // reach + the largest reach added of (x, y), and possibly for some farther ones (the caller
  // tests the distance).
  template <class Visit>
  void for_each_near(double x, double y, double reach, Visit&& visit);
  std::size_t bytes() const {
    return (head_.capacity() + next_.capacity() + id_.capacity() + found_.capacity()) * 4;
  }

 private:
  static constexpr std::uint32_t kNone = UINT32_MAX;
  static constexpr std::size_t kBuckets = std::size_t(1) << 13;
  std::int64_t cell_of(double v) const;
  static std::size_t bucket(std::int64_t cx, std::int64_t cy);
  void collect(double x, double y, double reach);

  double inverse_cell_ = 1, widest_ = 0;
  bool increasing_ = true;            // every particle added after a lower one, none twice
  std::vector<std::uint32_t> head_;   // per bucket: the last entry added to it
  std::vector<std::uint32_t> next_;   // per entry: the one added to its bucket before it
  std::vector<std::uint32_t> id_;     // per entry: its particle
  std::vector<std::uint32_t> found_;  // a query's candidates, sorted before they are visited
};

template <class Visit>
void AppendedCells::for_each_near(double x, double y, double reach, Visit&& visit) {
  collect(x, y, reach);
  for (const std::uint32_t m : found_) visit(std::size_t(m));
}

}  // namespace sedem
