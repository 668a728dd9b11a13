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

// Stratified random placement (Sect. 4.4, Fig. 6): the section is cut into n_mt x n_mt cells
// of the cylinder's aspect ratio, the particles are dealt out to the cells so that every cell
// holds floor(N / n_mt^2) or one more and any run of consecutive particles (a size class) is
// spread evenly over the rows, and each is put at a random point of its cell where it
// overlaps no other particle and lies inside the walls, above the bottom and below the free
// surface. Larger particles go first; one whose cell is full (a large particle may cover
// several cells) takes the nearest cell with room. Same seed, same positions.
// Sets x and y (diameters must be set). Throws SceneError when a particle finds no room.
void place_particles(Particles& particles, const Cylinder& cylinder, const PlacementConfig& config,
                     std::uint64_t seed);

}  // namespace sedem
