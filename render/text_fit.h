#pragma once

#include <string>
#include <vector>

namespace sedem::render {

// Text that must fit a width in pixels: titles over a panel, legend entries beside it. The
// names `sedem render` gives runs (several scene keys and values) are far longer than a
// sample's name, and text drawn past its box runs over the neighbouring panel.

// The width in logical pixels of `text` in the pictures' font at `size` pixels.
int text_width(const std::string& text, int size, bool bold = false);

struct FittedText {
  std::string text;
  int size = 0;
};

// `text` at the largest size from `largest` down to `smallest` that fits `width`; when even
// the smallest is too wide, its middle is replaced by "..." (the start and the end of a run's
// name are what tells it apart).
FittedText fit_text(const std::string& text, int width, int largest, int smallest = 8,
                    bool bold = false);

// `text` in lines no wider than `width`: broken after ", " where it can be (between the keys
// of a run's name), else after the last '.', '_' or ' ' that fits, else anywhere.
std::vector<std::string> wrap_text(const std::string& text, int width, int size);

}  // namespace sedem::render
