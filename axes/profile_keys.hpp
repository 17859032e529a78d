// Every number a machine profile's JSON holds, with the range the machine model honours, stated
// once (axes/profile_keys.cpp). The loader checks each value against it (profile_json.cpp,
// spindle_json.cpp through profile_values.hpp); docs/machine-profile.md's table "Every number's
// range" is written from it, and tests/profile_keys_test.cpp holds docs/schemas/profile.schema.json
// and that table to exactly these ranges. The relations between keys are listed once too
// (axes/profile_relations.hpp).
//
// A key is spelled as the file nests it, with three wildcards: "axes.*.backlash_in" (every axis),
// "tools[].number" (every element of a list) and "axes.*.soft_limits_in[0]" (one place of a
// fixed pair). "press.strokes_per_min" is the key "strokes_per_min" of the object "press".
#pragma once

#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>

namespace parsons::axes {

// The end of a range that has none (a most of kNoEnd: no upper end; a least of -kNoEnd: none
// below). A value is always finite.
inline constexpr double kNoEnd = std::numeric_limits<double>::infinity();

enum class KeyType {
    number, // any JSON number within the range
    whole,  // a JSON integer within the range
};

struct KeyRange {
    std::string_view key;
    KeyType type;
    double least;
    bool least_open; // true: above `least`; false: at least
    double most;
    bool most_open; // true: below `most`; false: at most
    std::string_view unit;
    std::string_view meaning; // one line
};

// The whole table, in the order docs/machine-profile.md lists it.
std::span<const KeyRange> profile_key_ranges();
// The row of `key` (as the table spells it, wildcards included). A key not in the table is a
// programming error: std::logic_error.
const KeyRange& profile_key_range(std::string_view key);
// Whether v lies in the range (finite, within both ends).
bool in_range(const KeyRange& r, double v);
// The range in words, as the loader's messages and the docs table say it: "above 0 and at most
// 60", "from 1 to 99", "any number".
std::string range_words(const KeyRange& r);
// docs/machine-profile.md's generated section: a table of every key's range, then the list of
// relations (axes/profile_relations.hpp), in Markdown.
std::string profile_ranges_markdown();

} // namespace parsons::axes
