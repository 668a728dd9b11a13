#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "core/engine/engine.h"

namespace sedem::render {

// The (timestep, file) entries of a .pvd collection, in file order; files are relative to
// the .pvd's folder. Throws std::runtime_error if the file cannot be read.
std::vector<std::pair<double, std::string>> read_pvd(const std::filesystem::path& pvd);

// A particle snapshot back from a .vtp written by write_particles_vtp: positions, velocity,
// diameter, weight, size_class, id, and the time from TimeValue. Throws std::runtime_error
// naming the file and the missing array.
Snapshot read_particles_vtp(const std::filesystem::path& file);

}  // namespace sedem::render
