#include "app/json_fields.h"

#include <stdexcept>

namespace sedem::app {

namespace {

[[noreturn]] void refuse(const std::string& where, const std::string& expected,
                         const nlohmann::json& found) {
  throw std::invalid_argument(where + ": expected " + expected + ", found " + json_quoted(found));
}

}  // namespace

std::string json_quoted(const nlohmann::json& value) {
  // dump() throws on invalid UTF-8 by default: a damaged file's bytes must not.
  std::string text = value.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  constexpr std::size_t kLongest = 40;
  if (text.size() > kLongest) text = text.substr(0, kLongest) + "...";
  return text;
}

const nlohmann::json& json_key(const nlohmann::json& object, const std::string& key,
                               const std::string& where) {
  if (!object.is_object()) refuse(where, "an object holding \"" + key + "\"", object);
  const auto it = object.find(key);
  if (it == object.end())
    throw std::invalid_argument((where.empty() ? "" : where + ".") + key + ": missing");
  return *it;
}

std::string json_string(const nlohmann::json& value, const std::string& where) {
  if (!value.is_string()) refuse(where, "a string", value);
  return value.get<std::string>();
}

std::int64_t json_integer(const nlohmann::json& value, const std::string& where, std::int64_t low,
                          std::int64_t high) {
  // Appended, not "[" + ...: GCC 12 warns (-Wrestrict) on a literal added to a temporary.
  std::string expected = "a whole number in [";
  expected += std::to_string(low);
  expected += ", ";
  expected += std::to_string(high);
  expected += "]";
  // nlohmann keeps integers above the int64 range as unsigned, and larger ones as doubles.
  if (!value.is_number_integer()) refuse(where, expected, value);
  if (value.is_number_unsigned() && value.get<std::uint64_t>() > static_cast<std::uint64_t>(high))
    refuse(where, expected, value);
  const std::int64_t n = value.get<std::int64_t>();
  if (n < low || n > high) refuse(where, expected, value);
  return n;
}

std::optional<std::int64_t> json_optional_integer(const nlohmann::json& value,
                                                  const std::string& where, std::int64_t low,
                                                  std::int64_t high) {
  if (value.is_null()) return std::nullopt;
  return json_integer(value, where, low, high);
}

std::vector<std::string> json_strings(const nlohmann::json& value, const std::string& where) {
  if (!value.is_array()) refuse(where, "a list of strings", value);
  std::vector<std::string> out;
  for (std::size_t i = 0; i < value.size(); ++i)
    out.push_back(json_string(value[i], where + "[" + std::to_string(i) + "]"));
  return out;
}

}  // namespace sedem::app
