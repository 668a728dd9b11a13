#include "render/text_fit.h"

#include <algorithm>

#include <cmath>

#include "render/drawing/cairo_painter.h"

namespace sedem::render {
namespace {

// The first boundary between UTF-8 characters at or after byte `at`: text is only ever cut
// between whole characters (µ and ³ take two bytes).
std::size_t char_end(const std::string& text, std::size_t at) {
  while (at < text.size() && (static_cast<unsigned char>(text[at]) & 0xC0) == 0x80) ++at;
  return at;
}

}  // namespace

int text_width(const std::string& text, int size, bool bold) {
  return int(std::ceil(text_advance(text, size, bold)));
}

FittedText fit_text(const std::string& text, int width, int largest, int smallest, bool bold) {
  for (int size = largest; size >= smallest; --size)
    if (text_width(text, size, bold) <= width) return {text, size};
  // Keep as much of both ends as fits around "...".
  std::size_t keep = text.size();
  while (keep > 0) {
    --keep;
    const std::size_t head = char_end(text, (keep + 1) / 2);
    const std::size_t tail = char_end(text, text.size() - keep / 2);
    const std::string cut = text.substr(0, head) + "..." + text.substr(tail);
    if (text_width(cut, smallest, bold) <= width) return {cut, smallest};
  }
  return {"...", smallest};
}

std::vector<std::string> wrap_text(const std::string& text, int width, int size) {
  std::vector<std::string> lines;
  std::string rest = text;
  while (!rest.empty() && text_width(rest, size) > width) {
    // The longest prefix that fits, ending on a whole character.
    std::size_t fits = 0;
    for (std::size_t end = char_end(rest, 1); end <= rest.size(); end = char_end(rest, end + 1)) {
      if (text_width(rest.substr(0, end), size) > width) break;
      fits = end;
      if (end == rest.size()) break;
    }
    if (fits == 0) fits = char_end(rest, 1);  // not even one character fits: one per line
    std::size_t cut = rest.rfind(", ", fits > 1 ? fits - 1 : 0);
    if (cut != std::string::npos && cut > 0 && cut + 1 <= fits) {
      cut += 2;
    } else {
      const std::size_t soft = rest.find_last_of("._ ", fits - 1);
      cut = soft != std::string::npos && soft > 0 ? soft + 1 : fits;
    }
    std::string line = rest.substr(0, cut);
    while (!line.empty() && line.back() == ' ') line.pop_back();
    lines.push_back(line);
    rest.erase(0, cut);
  }
  if (!rest.empty() || lines.empty()) lines.push_back(rest);
  return lines;
}

}  // namespace sedem::render
