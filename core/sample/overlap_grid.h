#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/model/cylinder.h"
#include "core/model/particles.h"
#include "core/model/scene_error.h"

namespace sedem {

// The particles placed so far, binned by size band (diameters within a factor of two share
// a band), each band on a grid of its own: a query then scans a few bins per band whatever
// the ratio of the largest to the smallest size, and memory stays proportional to N.
class OverlapGrid {
 public:
  // Diameters must be set; positions are read as particles are inserted.
  OverlapGrid(const Particles& particles, const Cylinder& cylinder);

  // Whether a disc of radius r centred at (x, y) overlaps an inserted particle.
  bool overlaps(double x, double y, double r) const;
  // Adds particle i at its current (x, y).
  void insert(std::size_t i);

 private:
  static constexpr std::size_t kBands = 8;
  struct Band {
    double bin = 0, max_radius = 0;
    std::int64_t nx = 0, ny = 0;
    std::vector<std::int32_t> head;  // first particle of each bin, -1: none
  };

  std::size_t band_of(double d) const;

  const Particles& p_;
  double left_;
  double d_max_ = 0;
  std::vector<Band> bands_;
  std::vector<std::int32_t> next_;  // next particle in the same bin
};

// The error for a particle that finds no room: which one, and what to lower.
SceneError no_room_error(const Particles& particles, const Cylinder& cylinder,
                         std::size_t placed_before, std::size_t particle);

}  // namespace sedem
