// The checks every key of the machine profile's JSON makes of its value (profile_json.cpp and
// the additions' own key files, spindle_json.cpp): a number is checked against its key's range
// in the one table of ranges (axes/profile_keys.hpp); each error is a ProfileError that names
// the key as the file spells it and what it must be ("press.variation: must be a number at
// least 0 and at most 0.5, not 2").
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <string_view>

namespace parsons::axes::profile_values {

// true or false.
bool flag(const nlohmann::json& j, const std::string& key);
// The number of the table's key `table_key` ("axes.*.backlash_in"), found at `where`
// ("axes.tilt.backlash_in"): a finite number within its range.
double number(const nlohmann::json& j, std::string_view table_key, const std::string& where);
// The whole number of a whole key of the table.
std::int64_t whole(const nlohmann::json& j, std::string_view table_key, const std::string& where);

} // namespace parsons::axes::profile_values
