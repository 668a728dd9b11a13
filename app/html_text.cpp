#include "app/html_text.h"

#include <cctype>
#include <cstring>

namespace sedem::app {

std::string html_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string url_path(std::string_view relative) {
  static const char* kHex = "0123456789ABCDEF";
  std::string out;
  for (const char c : relative) {
    const auto byte = static_cast<unsigned char>(c);
    if (std::isalnum(byte) || (c != 0 && std::strchr("-._~/=,+", c) != nullptr)) {
      out += c;
    } else {
      out += '%';
      out += kHex[byte >> 4];
      out += kHex[byte & 15];
    }
  }
  return out;
}

}  // namespace sedem::app
