#pragma once

#include <cstddef>
#include <string>

namespace sedem {

// A value's text in a message: whole when short, else its first and last characters and its
// length, so that a list of ten thousand values does not bury the message it is part of.
inline std::string shortened(const std::string& text, std::size_t longest = 120) {
  if (text.size() <= longest) return text;
  const std::size_t tail = longest / 4, head = longest - tail;
  return text.substr(0, head) + " ... " + text.substr(text.size() - tail) + " (" +
         std::to_string(text.size()) + " characters)";
}

}  // namespace sedem
