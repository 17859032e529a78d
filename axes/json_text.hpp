// JSON as parsons writes it: nlohmann's text with every number in the shortest form that reads
// back to the same double. nlohmann's Grisu2 writes 17 digits for about one double in a thousand
// (336.91522200000003 for 336.915222, a report's microsecond); every JSON file parsons writes
// (report, events, --json documents, profiles, job files, saved states) goes through here, so a
// figure rounded to what it resolves (outputs/report/figures.hpp) is printed as people write it
// and a value kept to the last bit still reads back to that bit (docs/report.md).
#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace parsons::axes {

// j.dump(indent) with invalid UTF-8 replaced (U+FFFD) and each number shortened as above; an
// ordered_json keeps its keys in the order they were set.
std::string json_text(const nlohmann::json& j, int indent = -1);
std::string json_text(const nlohmann::ordered_json& j, int indent = -1);

// The same shortening on JSON text already written: each number token outside a string that
// has a shorter form reading back to the same double takes it; all else is copied as it is.
std::string shortest_numbers(std::string_view json);

} // namespace parsons::axes
