#pragma once

#include <cstdint>

#include "core/model/cylinder.h"
#include "core/model/particles.h"
#include "core/sample/sample_config.h"

namespace sedem {

// n_mt: the cells per side of the placement matrix (Fig. 6). The paper takes the square
// root of the particle count, rounded up, so that there is a cell for every particle.
std::int64_t cells_per_side(const PlacementConfig& config, std::size_t particle_count);

// Share of the section's plane (B x H) the particles' discs cover.
double area_fraction(const Particles& particles, const Cylinder& cylinder);

// Places the particles by `config.method`: place_stratified or place_low_discrepancy.
// Sets x and y (diameters must be set). Same seed, same positions. Throws SceneError when a
// particle finds no room.
void place_particles(Particles& particles, const Cylinder& cylinder, const PlacementConfig& config,
                     std::uint64_t seed);

// Stratified random placement (Sect. 4.4, Fig. 6): the section is cut into n_mt x n_mt cells
// of the cylinder's aspect ratio, the particles are dealt out to the cells so that every cell
// holds floor(N / n_mt^2) or one more and any run of consecutive particles (a size class) is
// spread evenly over the rows, and each is put at a random point of its cell where it
// overlaps no other particle and lies inside the walls, above the bottom and below the free
// surface. Larger particles go first; one whose cell is full (a large particle may cover
// several cells) takes the nearest cell with room.
void place_stratified(Particles& particles, const Cylinder& cylinder, const PlacementConfig& config,
                      std::uint64_t seed);

// Low-discrepancy placement: particle i goes to point i of a seeded R2 sequence
// (quasi_random.h) mapped onto the span its centre may take inside the walls, above the
// bottom and below the surface. A run of consecutive particles (a size class, or all the
// sizes finer than a diameter, as build_sample orders them) is then spread evenly across the
// width as well as over the height, so the count of it in any circle or band is close to its
// expectation, not off by the square root of it as with random points. Larger particles go
// first; one whose point would overlap a placed particle lands at a random free point as
// near to it as there is room (dilute samples: none does).
void place_low_discrepancy(Particles& particles, const Cylinder& cylinder, std::uint64_t seed);

}  // namespace sedem
