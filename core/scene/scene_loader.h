#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "core/model/scene_error.h"
#include "core/scene/scene.h"

namespace sedem {

// The largest scene file read (a scene is a few kilobytes of text).
inline constexpr std::size_t kMaxSceneFileBytes = 1 << 20;

// Reads a TOML scene, then applies `overrides` ("key=value", as given to --set), then checks
// the values against each other. Throws SceneError.
Scene load_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});
Scene parse_scene(std::string_view toml, const std::string& source_name,
                  const std::vector<std::string>& overrides = {});

// The resolved scene as TOML, every key with its value in user units: a scene file of its own
// that loads back to the same scene bit for bit (each number the shortest text that does), so
// that a run of it is the run of the scene and overrides it was resolved from (the scenes
// `sedem batch --emit` writes for each task).
std::string resolved_toml(Scene& scene);

}  // namespace sedem
