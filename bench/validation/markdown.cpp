#include "bench/validation/markdown.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace sedem::validation {

std::string markdown_table(const std::vector<std::string>& header,
                           const std::vector<std::vector<std::string>>& rows) {
  auto line = [&](const std::vector<std::string>& cells) {
    std::string s = "|";
    for (std::size_t k = 0; k < header.size(); ++k)
      s += " " + (k < cells.size() ? cells[k] : std::string()) + " |";
    return s + "\n";
  };
  std::string out = line(header) + "|";
  for (std::size_t k = 0; k < header.size(); ++k) out += "---|";
  out += "\n";
  for (const auto& r : rows) out += line(r);
  return out;
}

std::string fixed(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  std::string s = buffer;
  if (s.front() == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

std::string significant(double value, int digits) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

std::string replace_generated(const std::string& document, const std::string& name,
                              const std::string& content) {
  const std::string begin = "<!-- generated:begin " + name + " -->";
  const std::string end = "<!-- generated:end -->";
  const auto b = document.find(begin);
  if (b == std::string::npos) throw std::invalid_argument("no marker " + begin);
  const auto from = b + begin.size();
  const auto e = document.find(end, from);
  if (e == std::string::npos) throw std::invalid_argument("no " + end + " after " + begin);
  std::string body = content;
  if (!body.empty() && body.back() != '\n') body += '\n';
  return document.substr(0, from) + "\n" + body + document.substr(e);
}

}  // namespace sedem::validation
