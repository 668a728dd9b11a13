#include "core/scene/scene_loader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

#include <toml++/toml.h>

#include "core/scene/scene_checks.h"

namespace sedem {
namespace {

// "png, svg,png" as {"png", "svg"}: items trimmed, repeats dropped, order kept.
std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> items;
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    const auto b = item.find_first_not_of(" \t"), e = item.find_last_not_of(" \t");
    if (b == std::string::npos) continue;
    item = item.substr(b, e - b + 1);
    if (std::find(items.begin(), items.end(), item) == items.end()) items.push_back(item);
  }
  return items;
}

// A TOML list of strings as one comma-separated string; nothing if it is anything else.
std::optional<std::string> joined_strings(const toml::node& node) {
  const auto* arr = node.as_array();
  if (!arr) return std::nullopt;
  std::string out;
  for (const auto& item : *arr) {
    auto s = item.value_exact<std::string>();
    if (!s) return std::nullopt;
    out += (out.empty() ? "" : ",") + *s;
  }
  return out;
}

std::string where(const std::string& source, const toml::node& node) {
  const auto& region = node.source();
  std::ostringstream os;
  os << source;
  if (region.begin.line > 0 && source != "--set") os << ':' << region.begin.line;
  return os.str();
}

std::string node_text(const toml::node& node) {
  std::ostringstream os;
  if (const auto* arr = node.as_array()) {
    os << '[';
    for (std::size_t i = 0; i < arr->size(); ++i) os << (i ? ", " : "") << node_text(*arr->get(i));
    os << ']';
    return os.str();
  }
  node.visit([&](const auto& v) {
    if constexpr (toml::is_string<decltype(v)>)
      os << '"' << v.get() << '"';
    else
      os << v;
  });
  return os.str();
}

void check_range(const Param& p, double v, const std::string& at, const std::string& shown) {
  bool low = p.min_exclusive ? !(v > p.min) : !(v >= p.min);
  if (low || !(v <= p.max))
    throw SceneError(at + ": " + p.key + " = " + shown +
                     " is out of range; allowed: " + range_text(p));
}

std::optional<double> as_number(const toml::node& n) {
  if (auto f = n.value_exact<double>()) return *f;
  if (auto i = n.value_exact<std::int64_t>()) return double(*i);
  return std::nullopt;
}

void assign(const Param& p, const toml::node& node, const std::string& at) {
  const std::string shown = shortened(node_text(node));
  auto wrong_type = [&](const std::string& want) {
    return SceneError(at + ": " + p.key + " = " + shown + " must be " + want);
  };
  std::visit(
      [&](auto* target) {
        using T = std::remove_pointer_t<decltype(target)>;
        if constexpr (std::is_same_v<T, bool>) {
          auto b = node.value_exact<bool>();
          if (!b) throw wrong_type("true or false");
          *target = *b;
        } else if constexpr (std::is_same_v<T, std::int64_t>) {
          auto i = node.value_exact<std::int64_t>();
          if (!i) throw wrong_type("a whole number");
          check_range(p, double(*i), at, shown);
          *target = *i;
        } else if constexpr (std::is_same_v<T, double>) {
          auto v = as_number(node);
          if (!v) throw wrong_type("a number");
          check_range(p, *v, at, shown);
          *target = *v * p.to_si;
        } else if constexpr (std::is_same_v<T, std::string>) {
          std::optional<std::string> s = node.value_exact<std::string>();
          if (p.several && !s) s = joined_strings(node);
          if (!s) throw wrong_type(p.several ? "a string or a list of strings" : "a string");
          const auto items = p.several ? split_list(*s) : std::vector<std::string>{*s};
          if (items.empty()) throw wrong_type("at least one of: " + range_text(p));
          for (const auto& item : items)
            if (!p.choices.empty() &&
                std::find(p.choices.begin(), p.choices.end(), item) == p.choices.end())
              throw SceneError(at + ": " + p.key + " = " + shown +
                               (p.several ? ": '" + shortened(item) + "'" : "") +
                               " is not one of: " + range_text(p));
          std::string value;
          for (const auto& item : items) value += (value.empty() ? "" : ",") + item;
          *target = value;
        } else {
          const auto* arr = node.as_array();
          if (!arr) throw wrong_type("a list of numbers");
          std::vector<double> values;
          for (const auto& item : *arr) {
            auto v = as_number(item);
            if (!v) throw wrong_type("a list of numbers");
            check_range(p, *v, at, node_text(item) + " (in " + shown + ")");
            values.push_back(*v * p.to_si);
          }
          *target = std::move(values);
        }
      },
      p.target);
}

// The keys one layer of input (the file, or the --set list) gave, and where.
using Layer = std::map<std::string, std::string>;

void apply_table(const Schema& schema, const toml::table& table, const std::string& prefix,
                 const std::string& source, Layer& layer) {
  for (const auto& [k, node] : table) {
    const std::string key =
        prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (const auto* sub = node.as_table()) {
      apply_table(schema, *sub, key, source, layer);
      continue;
    }
    const Param* p = schema.find(key);
    if (!p)
      throw SceneError(where(source, node) + ": unknown key '" + key + "'; did you mean '" +
                       schema.nearest(key) + "'?");
    assign(*p, node, where(source, node));
    layer[key] = where(source, node);
  }
}

void apply_override(const Schema& schema, const std::string& assignment, Layer& layer) {
  auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw SceneError("--set " + assignment + ": expected key=value");
  std::string key = assignment.substr(0, eq);
  std::string value = assignment.substr(eq + 1);
  const Param* p = schema.find(key);
  if (!p)
    throw SceneError("--set: unknown key '" + key + "'; did you mean '" + schema.nearest(key) +
                     "'?");
  // A value is read as TOML; a bare word that is not valid TOML is taken as a string, so
  // that --set integrator.method=explicit needs no quotes.
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + value);
  } catch (const toml::parse_error&) {
    parsed = toml::table{{"v", value}};
  }
  assign(*p, *parsed.get("v"), "--set");
  layer[key] = "--set";
}

// Of two exclusive keys, the one a layer gives replaces the other; a layer may not give both.
void settle_exclusives(const Schema& schema, const Layer& layer) {
  for (const auto& [a, b] : schema.exclusives()) {
    const Param& pa = *schema.find(a);
    const Param& pb = *schema.find(b);
    const bool gave_a = layer.count(a) && !is_unused(pa);
    const bool gave_b = layer.count(b) && !is_unused(pb);
    if (gave_a && gave_b)
      throw SceneError(layer.at(b) + ": " + b + " = " + format_user_value(pb) + " and " +
                       layer.at(a) + ": " + a + " = " + format_user_value(pa) +
                       " are alternatives; give only one of them");
    if (gave_a) set_unused(pb);
    if (gave_b) set_unused(pa);
  }
}

// The shortest text of si / to_si in the user's unit that a scene reads back to si bit for bit
// (12.3 µm comes back as "12.3", not as 12.299999999999999): a run of the resolved scene is
// the run of the scene it was resolved from. A quotient of the division that no decimal
// multiplies back to si exactly (none known) keeps 17 digits, within an ulp.
std::string exact_number(double si, double to_si) {
  // to_chars and from_chars, not printf and strtod: no locale can make the point a comma.
  auto parse = [](const std::string& t) {
    double x = 0;
    std::from_chars(t.data(), t.data() + t.size(), x);
    return x;
  };
  auto digits = [](double x, int n) {
    char buffer[40];
    const auto end =
        std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::general, n).ptr;
    return std::string(buffer, end);
  };
  // The shortest form of a double ("20", not "2e+01").
  auto shortest = [](double x) {
    char buffer[40];
    return std::string(buffer, std::to_chars(buffer, buffer + sizeof buffer, x).ptr);
  };
  const double user = si / to_si;
  for (int n = 1; n <= 17; ++n)
    if (const double x = parse(digits(user, n)); x * to_si == si) return shortest(x);
  // The division may land an ulp or two from the one double that multiplies back exactly.
  for (const double toward : {-HUGE_VAL, HUGE_VAL}) {
    double near = user;
    for (int step = 0; step < 2; ++step) {
      near = std::nextafter(near, toward);
      if (near * to_si == si) return shortest(near);
    }
  }
  return shortest(user);
}

// A TOML basic string: quotes, backslashes and control characters escaped.
std::string toml_string(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\u%04x", unsigned(static_cast<unsigned char>(c)));
      out += escape;
    } else {
      out += c;
    }
  }
  return out + '"';
}

// A key's value as resolved_toml writes it: numbers exact, strings escaped.
std::string exact_user_value(const Param& p) {
  if (const auto* v = std::get_if<double*>(&p.target)) return exact_number(**v, p.to_si);
  if (const auto* v = std::get_if<std::vector<double>*>(&p.target)) {
    std::string list = "[";
    for (std::size_t i = 0; i < (*v)->size(); ++i) {
      if (i) list += ", ";
      list += exact_number((**v)[i], p.to_si);
    }
    return list + ']';
  }
  if (const auto* v = std::get_if<std::string*>(&p.target))
    return toml_string(current_choice(p, **v));
  return format_user_value(p);
}

}  // namespace

Scene parse_scene(std::string_view text, const std::string& source_name,
                  const std::vector<std::string>& overrides) {
  Scene scene;
  Schema schema = scene.schema();
  toml::table table;
  try {
    table = toml::parse(text, source_name);
  } catch (const toml::parse_error& e) {
    std::ostringstream os;
    os << source_name << ':' << e.source().begin.line << ": " << e.description();
    throw SceneError(os.str());
  }
  SceneOrigins origins{source_name, {}};
  Layer from_file, from_set;
  apply_table(schema, table, "", source_name, from_file);
  settle_exclusives(schema, from_file);
  for (const auto& o : overrides) apply_override(schema, o, from_set);
  settle_exclusives(schema, from_set);
  origins.at = from_file;
  for (const auto& [key, at] : from_set) origins.at[key] = at;
  check_scene(scene, origins);
  return scene;
}

Scene load_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (ec || !std::filesystem::exists(status))
    throw SceneError(file.string() + ": cannot open the scene file: no such file");
  // A folder, a device (/dev/zero) or a pipe is no scene; a scene is a small text file.
  if (!std::filesystem::is_regular_file(status))
    throw SceneError(file.string() +
                     ": not a scene file (a folder or a device, not a regular "
                     "file)");
  const auto size = std::filesystem::file_size(file, ec);
  if (ec || size > kMaxSceneFileBytes)
    throw SceneError(file.string() + ": the scene file is " + std::to_string(size) +
                     " bytes long; a scene is at most " + std::to_string(kMaxSceneFileBytes) +
                     " bytes");
  std::ifstream in(file);
  if (!in) throw SceneError(file.string() + ": cannot open the scene file");
  std::string text(kMaxSceneFileBytes + 1, '\0');
  in.read(text.data(), std::streamsize(text.size()));
  text.resize(std::size_t(in.gcount()));
  if (text.size() > kMaxSceneFileBytes)
    throw SceneError(file.string() + ": the scene file is longer than " +
                     std::to_string(kMaxSceneFileBytes) + " bytes");
  Scene scene = parse_scene(text, file.string(), overrides);
  return scene;
}

std::string resolved_toml(Scene& scene) {
  Schema schema = scene.schema();
  std::ostringstream os;
  for (const auto& p : schema.params()) {
    os << p.key << " = " << exact_user_value(p);
    if (!p.unit.empty()) os << "  # " << p.unit;
    os << '\n';
  }
  return os.str();
}

}  // namespace sedem
