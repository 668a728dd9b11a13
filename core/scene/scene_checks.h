#pragma once

#include <string>

namespace sedem {

struct Scene;

// Checks that need more than one key (each key's own range is checked as it is read).
// Throws SceneError naming the keys involved.
void check_scene(const Scene& scene, const std::string& source);

}  // namespace sedem
