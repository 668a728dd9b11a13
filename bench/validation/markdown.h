#pragma once

#include <string>
#include <vector>

namespace sedem::validation {

// A GitHub-flavoured markdown table; every row as long as the header.
std::string markdown_table(const std::vector<std::string>& header,
                           const std::vector<std::vector<std::string>>& rows);

// A number with `decimals` digits after the point ("-0.0" printed as "0.0").
std::string fixed(double value, int decimals);
// A number in the shortest of fixed or scientific notation with `digits` significant digits.
std::string significant(double value, int digits);

// Replaces what lies between "<!-- generated:begin NAME -->" and the next
// "<!-- generated:end -->" with `content`. Throws std::invalid_argument when the markers are
// missing, so a renamed section is noticed instead of silently not updated.
std::string replace_generated(const std::string& document, const std::string& name,
                              const std::string& content);

}  // namespace sedem::validation
