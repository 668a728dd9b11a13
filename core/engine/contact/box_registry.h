#pragma once

// Space-time boxes of the local time stepping (schedule/local_stepper.h): every grain holds one
// axis-aligned box that it cannot leave before its next update — a coasting grain the box its
// exact trajectory sweeps over its window, a grain stepped with the others its position with
// an allowance of travel, a settled grain its own disc — each widened by its radius and a skin.
// While two boxes do not overlap their grains cannot touch. Boxes live in a uniform grid of
// cells, each box listed in every cell it covers, so a query costs the few cells a box spans
// however many grains there are; an update touches only the grain's own cells.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sedem {

struct Box {
  double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  bool overlaps(const Box& b) const { return x0 < b.x1 && b.x0 < x1 && y0 < b.y1 && b.y0 < y1; }
  Box merged(const Box& b) const {
    return {std::min(x0, b.x0), std::max(x1, b.x1), std::min(y0, b.y0), std::max(y1, b.y1)};
  }
};

class BoxRegistry {
 public:
  void configure(double cell, double half_width, double height, std::size_t grains);
  // Sets grain id's box (replacing the one it had) with a kind that queries report.
  void set(std::uint32_t id, const Box& box, std::uint8_t kind);
  void clear(std::uint32_t id);
  bool has(std::uint32_t id) const { return kind_[id] != kNone; }
  const Box& box(std::uint32_t id) const { return box_[id]; }
  std::uint8_t kind(std::uint32_t id) const { return kind_[id]; }
  // Calls f(id) once for every other grain whose box overlaps `b`, in no particular order.
  template <class F>
  void overlapping(const Box& b, std::uint32_t self, F&& f) const {
    overlapping(b, self, f, [](std::uint32_t) { return true; });
  }
  // The same for the grains `wanted(id)` accepts, asked before their boxes are read: a query
  // that looks for a few kinds skips the others' boxes (a cache miss each, at a million grains).
  template <class F, class Wanted>
  void overlapping(const Box& b, std::uint32_t self, F&& f, Wanted&& wanted) const {
    long c0, c1, r0, r1;
    span(b, c0, c1, r0, r1);
    for (long r = r0; r <= r1; ++r) {
      if (row_entries_[std::size_t(r)] == 0) continue;
      for (long c = c0; c <= c1; ++c)
        cells_[std::size_t(r * columns_ + c)].for_each([&](std::uint32_t id) {
          if (id == self || !wanted(id)) return;
          const Box& o = box_[id];
          if (!o.overlaps(b)) return;
          // Reported from one cell only: the one holding the corner of the intersection.
          const long cc = column(o.x0 > b.x0 ? o.x0 : b.x0), rr = row(o.y0 > b.y0 ? o.y0 : b.y0);
          if ((cc < c0 ? c0 : cc) == c && (rr < r0 ? r0 : rr) == r) f(id);
        });
    }
  }
  std::size_t bytes() const;
  static constexpr std::uint8_t kNone = 0xFF;

 private:
  // A cell's ids, the first kInline of them in the cell itself: a query reads the count and
  // those ids in one cache line, where a vector's header and its buffer were two misses (12 %
  // of a test's last hours at 10^5 grains). The rest go to `more`. The order is a vector's
  // (appended at the end, an erased id's place taken by the last), so queries report in it.
  struct alignas(64) Cell {
    static constexpr std::uint32_t kInline = 9;
    std::uint32_t n = 0;
    std::uint32_t local[kInline] = {};
    std::vector<std::uint32_t> more;

    std::uint32_t& at(std::uint32_t i) { return i < kInline ? local[i] : more[i - kInline]; }
    void push_back(std::uint32_t id) {
      if (n < kInline)
        local[n] = id;
      else
        more.push_back(id);
      ++n;
    }
    void erase(std::uint32_t id) {
      for (std::uint32_t i = 0; i < n; ++i)
        if (at(i) == id) {
          at(i) = at(n - 1);
          if (n > kInline) more.pop_back();
          --n;
          return;
        }
    }
    template <class F>
    void for_each(F&& f) const {
      const std::uint32_t here = n < kInline ? n : kInline;
      for (std::uint32_t i = 0; i < here; ++i) f(local[i]);
      for (std::uint32_t i = here; i < n; ++i) f(more[i - kInline]);
    }
  };
  static_assert(sizeof(Cell) == 64, "kInline is chosen to fill one cache line");

  long column(double x) const {
    const long c = long((x + half_width_) * inverse_cell_);
    return c < 0 ? 0 : (c >= columns_ ? columns_ - 1 : c);
  }
  long row(double y) const {
    const long r = long(y * inverse_cell_);
    return r < 0 ? 0 : (r >= rows_ ? rows_ - 1 : r);
  }
  void span(const Box& b, long& c0, long& c1, long& r0, long& r1) const {
    c0 = column(b.x0);
    c1 = column(b.x1);
    r0 = row(b.y0);
    r1 = row(b.y1);
  }
  void insert(std::uint32_t id);
  void erase(std::uint32_t id);

  double inverse_cell_ = 1, half_width_ = 0;
  long columns_ = 1, rows_ = 1;
  std::vector<Cell> cells_;
  // Entries in each row of cells: a query skips the rows that hold none without reading their
  // cells. Where the suspension passes, the free grains hold no box and the registry holds the
  // bed's and the members' only, at the bottom, while a sync's window query above read a cell
  // or two, each a cache miss: 27 % of a million grains' whole test.
  std::vector<std::uint32_t> row_entries_;
  std::vector<Box> box_;
  std::vector<std::uint8_t> kind_;
};

}  // namespace sedem
