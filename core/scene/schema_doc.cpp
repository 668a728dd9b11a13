#include "core/scene/schema_doc.h"

#include <sstream>

#include "core/scene/scene.h"

namespace sedem {
namespace {

std::string cell(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

std::string allowed(const Param& p) {
  std::string range = range_text(p);
  // The unit has a column of its own.
  if (!p.unit.empty() && range.size() > p.unit.size() + 1 &&
      range.compare(range.size() - p.unit.size() - 1, std::string::npos, " " + p.unit) == 0)
    range.resize(range.size() - p.unit.size() - 1);
  if (std::holds_alternative<std::vector<double>*>(p.target)) range = "list, each in " + range;
  return range;
}

}  // namespace

std::string schema_markdown(Scene& defaults) {
  const Schema schema = defaults.schema();
  std::ostringstream os;
  os << "| Key | Unit | Default | Allowed | Meaning |\n";
  os << "|---|---|---|---|---|\n";
  for (const auto& p : schema.params()) {
    os << "| `" << p.key << "` | " << cell(p.unit.empty() ? "-" : p.unit) << " | `"
       << cell(format_user_value(p)) << "` | " << cell(allowed(p)) << " | " << cell(p.doc)
       << " |\n";
  }
  for (const auto& [a, b] : schema.exclusives())
    os << "\n`" << a << "` and `" << b
       << "` are alternatives: give one of them a non-zero value; giving one (in the file or "
          "with `--set`) sets the other to 0.\n";
  return os.str();
}

}  // namespace sedem
