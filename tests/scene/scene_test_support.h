#pragma once

#include <string>
#include <vector>

#include "core/scene/scene_loader.h"

namespace sedem::test {

// The message of the SceneError a scene text raises (as file "bad.toml"), or "" if none.
inline std::string scene_error(const std::string& toml, std::vector<std::string> overrides = {}) {
  try {
    parse_scene(toml, "bad.toml", overrides);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

}  // namespace sedem::test
