#pragma once

#include <cstddef>
#include <map>
#include <string>

namespace sedem {

struct Scene;

// Where each key's value came from, for messages: "scene.toml:12" or "--set"; a key nobody
// gave is reported as "<source> (default)".
struct SceneOrigins {
  std::string source;
  std::map<std::string, std::string> at;

  std::string of(const std::string& key) const;
};

// The longest scene name accepted (it titles figures and frames).
inline constexpr std::size_t kMaxNameLength = 200;

// Checks that need more than one key (each key's own range is checked as it is read): the
// grading curve as a whole, the particle count, whether the particles fit in the section.
// Throws SceneError naming where, the key, its value and what is allowed.
void check_scene(const Scene& scene, const SceneOrigins& origins);

}  // namespace sedem
