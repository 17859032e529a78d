// The documented range of every profile key the property test draws (tests/property_test.cpp).
//
// A small interface on purpose: the generator needs only each key's name, kind and bounds. For
// now they are read from the committed JSON schema (docs/schemas/profile.schema.json), the
// single statement of the ranges the loader is meant to agree with; when the loader's own table
// of ranges is in the tree, key_ranges() reads that instead and nothing else changes.
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace parsons::test {

struct KeyRange {
    enum class Kind { number, integer, boolean, choice };
    std::string key; // dotted as the loader names it: "spindle.max_rpm", "axes.table.backlash_in";
                     // an element of a fixed array as "axes.table.speed_in_per_min[1]"
    Kind kind = Kind::number;
    double min = 0;
    double max = 0;
    bool min_exclusive = false;
    bool max_exclusive = false;
    bool max_documented = true;       // false: the schema gives no maximum (one is assumed)
    std::vector<std::string> choices; // Kind::choice
};

// Every leaf of the schema with a range, a boolean or a choice: numbers without a documented
// maximum get an assumed one (kAssumedMax times the built-in profile's value, or 100),
// marked max_documented = false so the out-of-range draw leaves them alone.
std::vector<KeyRange> ranges_from_schema(const nlohmann::json& schema);

// The ranges the generator draws from (the schema, for now).
const std::vector<KeyRange>& key_ranges();

// The loader's name of a key: "axes.table.speed_in_per_min[1]" -> "axes.table.speed_in_per_min".
std::string loader_key(const std::string& key);

} // namespace parsons::test
