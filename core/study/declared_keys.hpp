// A study section as a front end of a command: the keys its rows declare for studies
// (Setting::study_key), found below the section and read as the row's type and bounds.
#pragma once

#include "support/io/json_input.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sphkern {

// The section's own keys: the first token of each of the command's study keys, then `others`
// (keys the section reads that are no setting of the command).
std::vector<std::string> declared_study_keys(std::string_view command, std::vector<std::string> others = {});

// The value of the command's setting `key` below `section`, if the study gives it.
std::optional<JsonNode> declared_node(const JsonNode& section, std::string_view command, std::string_view key);

// That value as the row's number (a whole number where the row takes one), checked by the
// row's bounds and named by its pointer.
std::optional<double> declared_number(const JsonNode& section, std::string_view command, std::string_view key);

} // namespace sphkern
