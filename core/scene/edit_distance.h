#pragma once

#include <cstddef>
#include <string>

namespace sedem {

// Levenshtein distance between two strings (insertions, deletions, substitutions), for
// "did you mean" messages. Defined in schema.cpp.
std::size_t edit_distance(const std::string& a, const std::string& b);

}  // namespace sedem
