#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace sedem::app {

// Typed reads of a JSON object's keys for files sedem wrote and a user (or a disk) may have
// damaged: nlohmann's own errors ("type must be string, but is number") name no key, and its
// get<int>() of 1e308 converts without a word. Each throws std::invalid_argument naming
// `where` (the key's path, e.g. "runs[3].seed"), what was expected and, shortened, what is
// there.

// The key's value as given (missing: an error).
const nlohmann::json& json_key(const nlohmann::json& object, const std::string& key,
                               const std::string& where);
std::string json_string(const nlohmann::json& value, const std::string& where);
// A whole number in [low, high]; 2.5, 1e308, "3" and true are refused.
std::int64_t json_integer(const nlohmann::json& value, const std::string& where, std::int64_t low,
                          std::int64_t high);
// json_integer, or nothing for null.
std::optional<std::int64_t> json_optional_integer(const nlohmann::json& value,
                                                  const std::string& where, std::int64_t low,
                                                  std::int64_t high);
std::vector<std::string> json_strings(const nlohmann::json& value, const std::string& where);

// A value as a message quotes it: its JSON, at most about 40 characters, invalid UTF-8 replaced.
std::string json_quoted(const nlohmann::json& value);

}  // namespace sedem::app
