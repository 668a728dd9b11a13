#pragma once

#include <filesystem>
#include <string>

#include "core/engine/engine.h"
#include "core/model/cylinder.h"

namespace sedem::render {

// A picture of the settling column at one time: the section's outline and every simulated
// particle as a dot coloured by diameter, with the time in the title.
void render_column_png(const Snapshot& snapshot, const Cylinder& cylinder, const std::string& title,
                       int width, int height, const std::filesystem::path& file);

}  // namespace sedem::render
