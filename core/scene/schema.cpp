#include "core/scene/schema.h"
#include "core/scene/edit_distance.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace sedem {

Param& Schema::add(Param p) {
  if (find(p.key)) throw std::logic_error("scene key declared twice: " + p.key);
  params_.push_back(std::move(p));
  return params_.back();
}

Param& Schema::number(std::string key, double* target, std::string unit, double to_si, double min,
                      double max, std::string doc) {
  return add(Param{
      std::move(key), target, std::move(unit), to_si, min, max, false, {}, std::move(doc), {}});
}

Param& Schema::integer(std::string key, std::int64_t* target, std::int64_t min, std::int64_t max,
                       std::string doc) {
  return add(Param{
      std::move(key), target, "", 1, double(min), double(max), false, {}, std::move(doc), {}});
}

Param& Schema::flag(std::string key, bool* target, std::string doc) {
  return add(Param{std::move(key), target, "", 1, 0, 1, false, {}, std::move(doc), {}});
}

Param& Schema::choice(std::string key, std::string* target, std::vector<std::string> choices,
                      std::string doc) {
  return add(
      Param{std::move(key), target, "", 1, 0, 0, false, std::move(choices), std::move(doc), {}});
}

Param& Schema::choices(std::string key, std::string* target, std::vector<std::string> choices,
                       std::string doc) {
  Param& p = choice(std::move(key), target, std::move(choices), std::move(doc));
  p.several = true;
  return p;
}

Param& Schema::text(std::string key, std::string* target, std::string doc) {
  return add(Param{std::move(key), target, "", 1, 0, 0, false, {}, std::move(doc), {}});
}

Param& Schema::list(std::string key, std::vector<double>* target, std::string unit, double to_si,
                    double min, double max, std::string doc) {
  return add(Param{
      std::move(key), target, std::move(unit), to_si, min, max, false, {}, std::move(doc), {}});
}

void Schema::exclusive(std::string a, std::string b) {
  if (!find(a) || !find(b)) throw std::logic_error("exclusive keys must be declared first");
  exclusives_.emplace_back(std::move(a), std::move(b));
}

void Schema::alias(const std::string& key, std::string former, std::string current) {
  auto it =
      std::find_if(params_.begin(), params_.end(), [&](const Param& p) { return p.key == key; });
  if (it == params_.end() ||
      std::find(it->choices.begin(), it->choices.end(), current) == it->choices.end())
    throw std::logic_error("an alias needs a declared choice: " + key + " = " + current);
  it->choices.push_back(former);  // the loader accepts it as one of the choices
  it->aliases.emplace_back(std::move(former), std::move(current));
}

const std::string& current_choice(const Param& p, const std::string& value) {
  for (const auto& [former, current] : p.aliases)
    if (value == former) return current;
  return value;
}

const Param* Schema::find(const std::string& key) const {
  auto it =
      std::find_if(params_.begin(), params_.end(), [&](const Param& p) { return p.key == key; });
  return it == params_.end() ? nullptr : &*it;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string Schema::nearest(const std::string& key) const {
  std::string best;
  std::size_t best_d = std::string::npos;
  for (const auto& p : params_) {
    // Compare with the whole key and with its last component, so that a right name in the
    // wrong table ("viscosity" for "fluid.viscosity") is found too.
    std::size_t d = edit_distance(key, p.key);
    auto dot = p.key.rfind('.');
    if (dot != std::string::npos) d = std::min(d, edit_distance(key, p.key.substr(dot + 1)) + 1);
    if (d < best_d) best_d = d, best = p.key;
  }
  return best;
}

std::string format_user_value(const Param& p) {
  std::ostringstream os;
  os.precision(12);
  std::visit(
      [&](auto* v) {
        using T = std::remove_pointer_t<decltype(v)>;
        if constexpr (std::is_same_v<T, bool>) {
          os << (*v ? "true" : "false");
        } else if constexpr (std::is_same_v<T, double>) {
          os << *v / p.to_si;
        } else if constexpr (std::is_same_v<T, std::vector<double>>) {
          os << '[';
          for (std::size_t i = 0; i < v->size(); ++i) os << (i ? ", " : "") << (*v)[i] / p.to_si;
          os << ']';
        } else if constexpr (std::is_same_v<T, std::string>) {
          os << '"' << current_choice(p, *v) << '"';
        } else {
          os << *v;
        }
      },
      p.target);
  return os.str();
}

std::string range_text(const Param& p) {
  std::ostringstream os;
  if (!p.choices.empty()) {
    bool first = true;
    for (const auto& c : p.choices) {
      const bool former = std::any_of(p.aliases.begin(), p.aliases.end(),
                                      [&](const auto& a) { return a.first == c; });
      if (former) continue;  // still read, no longer offered
      os << (first ? "" : ", ") << c;
      first = false;
    }
    return os.str();
  }
  const bool numeric = std::visit(
      [](auto* v) {
        using T = std::remove_pointer_t<decltype(v)>;
        return std::is_same_v<T, double> || std::is_same_v<T, std::int64_t> ||
               std::is_same_v<T, std::vector<double>>;
      },
      p.target);
  if (std::holds_alternative<bool*>(p.target)) return "true, false";
  if (!numeric) return "any text";
  os << (p.min_exclusive ? "(" : "[") << p.min << ", " << p.max << "]";
  if (!p.unit.empty()) os << ' ' << p.unit;
  return os.str();
}

bool is_unused(const Param& p) {
  return std::visit(
      [](auto* v) {
        using T = std::remove_pointer_t<decltype(v)>;
        if constexpr (std::is_same_v<T, bool>)
          return !*v;
        else if constexpr (std::is_same_v<T, std::string> || std::is_same_v<T, std::vector<double>>)
          return v->empty();
        else
          return *v == 0;
      },
      p.target);
}

void set_unused(const Param& p) {
  std::visit([](auto* v) { *v = std::remove_pointer_t<decltype(v)>{}; }, p.target);
}

}  // namespace sedem
