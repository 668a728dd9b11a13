#pragma once

#include <string>

namespace sedem {

struct Scene;

// The table of every scene key as Markdown (key, unit, default, allowed values, meaning),
// from the Schema: docs/scenes.md embeds it between the markers below, and a test checks
// that the two agree, so the documentation cannot drift from the code.
std::string schema_markdown(Scene& defaults);

inline constexpr const char* kKeysBeginMarker = "<!-- keys:begin (generated; do not edit) -->";
inline constexpr const char* kKeysEndMarker = "<!-- keys:end -->";

}  // namespace sedem
