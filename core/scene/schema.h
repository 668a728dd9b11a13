#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "core/model/shortened.h"

namespace sedem {

// Every scene key in one table: its dotted name, where its value lives, the unit the user
// writes it in, the factor to SI, its allowed range and a line of documentation. Loading a
// TOML file, `--set key=value`, the resolved scene in run.json and docs/scenes.md all walk
// this table, so a key is declared once, next to the struct that holds it.
struct Param {
  using Target = std::variant<bool*, std::int64_t*, double*, std::string*, std::vector<double>*>;

  std::string key;
  Target target;
  std::string unit;  // as written by the user: "um", "min", "g", "Pa*s"; empty if none
  double to_si = 1;  // SI value = user value * to_si (numbers and number lists)
  double min = -std::numeric_limits<double>::infinity();  // in user units, inclusive
  double max = std::numeric_limits<double>::infinity();
  bool min_exclusive = false;
  std::vector<std::string> choices;  // allowed strings (former names included); empty: any
  std::string doc;
  // Former names of choices, {former, current}: a scene or run record that says the former
  // still loads, and is written and read as the current one (current_choice).
  std::vector<std::pair<std::string, std::string>> aliases;
  // A choice of several: the value is a comma-separated list of choices ("png,pdf"), given
  // as that string or as a TOML list of strings.
  bool several = false;
};

class Schema {
 public:
  // Numeric keys: range in the user's unit; `to_si` converts to the stored SI value.
  Param& number(std::string key, double* target, std::string unit, double to_si, double min,
                double max, std::string doc);
  Param& integer(std::string key, std::int64_t* target, std::int64_t min, std::int64_t max,
                 std::string doc);
  Param& flag(std::string key, bool* target, std::string doc);
  Param& choice(std::string key, std::string* target, std::vector<std::string> choices,
                std::string doc);
  Param& text(std::string key, std::string* target, std::string doc);
  // Any of `choices`, at least one, stored as "a,b" in the order given.
  Param& choices(std::string key, std::string* target, std::vector<std::string> choices,
                 std::string doc);
  Param& list(std::string key, std::vector<double>* target, std::string unit, double to_si,
              double min, double max, std::string doc);

  // Two alternative keys (say, a count or a fraction): a scene gives at most one of them a
  // non-zero value, and the other is then 0 ("unused"). Giving one, in the file or in
  // `--set`, resets the other, so that an override can switch from one to the other.
  void exclusive(std::string a, std::string b);
  // A choice renamed: `former`, its old name, is still accepted for key's `current` choice.
  void alias(const std::string& key, std::string former, std::string current);
  const std::vector<std::pair<std::string, std::string>>& exclusives() const { return exclusives_; }

  const std::vector<Param>& params() const { return params_; }
  const Param* find(const std::string& key) const;
  // The declared key closest to `key` (edit distance), for "did you mean" messages.
  std::string nearest(const std::string& key) const;

 private:
  Param& add(Param p);
  std::vector<Param> params_;
  std::vector<std::pair<std::string, std::string>> exclusives_;
};

// The choice a value names: the current name of a former one (Param::aliases), else the value.
const std::string& current_choice(const Param& p, const std::string& value);

// A value as the user sees it (user units), for printing and run.json.
std::string format_user_value(const Param& p);

// A value in the unit the user writes it: "1e-06, 10] Pa*s" style ranges, "a, b" choices.
std::string range_text(const Param& p);

// Whether a key holds its "unused" value (0, false, empty), and setting it so.
bool is_unused(const Param& p);
void set_unused(const Param& p);

}  // namespace sedem
