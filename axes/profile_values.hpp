// The checks every key of the machine profile's JSON makes of its value (profile_json.cpp and
// the additions' own key files, spindle_json.cpp): each error is a ProfileError that names the
// key and what it must be ("press.variation: must be a number at least 0 and at most 0.5, not
// 2").
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <limits>
#include <string>

namespace parsons::axes::profile_values {

// The most of a range that has no upper end.
inline constexpr double kNoEnd = std::numeric_limits<double>::infinity();

// true or false.
bool flag(const nlohmann::json& j, const std::string& key);
// A number within a range whose ends may be open (an infinite most: no upper end).
double number_in(const nlohmann::json& j, const std::string& key, double least, bool least_open,
                 double most, bool most_open);
// A whole number from least to most.
std::int64_t whole_in(const nlohmann::json& j, const std::string& key, std::int64_t least,
                      std::int64_t most);

} // namespace parsons::axes::profile_values
