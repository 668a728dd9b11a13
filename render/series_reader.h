#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/model/snapshot.h"

namespace sedem::render {

// A saved series that cannot be read back: missing, cut short, not well-formed XML, or not
// what sedem writes. The message names the file.
struct SeriesError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The (timestep, file) entries of a .pvd collection, in file order; files are relative to
// the .pvd's folder. Read with VTK's XML parser; throws SeriesError if the file cannot be
// read, is not well-formed, or an entry lacks a time or names a file outside the folder.
std::vector<std::pair<double, std::string>> read_pvd(const std::filesystem::path& pvd);

// A particle snapshot back from a .vtp written by write_particles_vtp: positions, velocity,
// diameter, weight, size_class, id, and the time from TimeValue. Throws SeriesError naming
// the file and what is wrong (missing, damaged, an array missing or cut short).
Snapshot read_particles_vtp(const std::filesystem::path& file);

}  // namespace sedem::render
