#include "axes/profile_values.hpp"

#include "axes/profile_json.hpp"
#include "axes/profile_keys.hpp"

#include <fmt/format.h>

#include <cmath>

namespace parsons::axes::profile_values {

using nlohmann::json;

bool flag(const json& j, const std::string& key) {
    if (!j.is_boolean()) {
        throw ProfileError(fmt::format("{}: expected true or false", key));
    }
    return j.get<bool>();
}

double number(const json& j, std::string_view table_key, const std::string& where) {
    const KeyRange& r = profile_key_range(table_key);
    if (!j.is_number() || !in_range(r, j.get<double>())) {
        const std::string range = range_words(r);
        throw ProfileError(fmt::format("{}: must be a number{}{}, not {}", where,
                                       range == "any" ? "" : " ", range == "any" ? "" : range,
                                       j.dump()));
    }
    return j.get<double>();
}

std::int64_t whole(const json& j, std::string_view table_key, const std::string& where) {
    const KeyRange& r = profile_key_range(table_key);
    // 64 bits on every target (long is 32 on WebAssembly): a seed runs to 2^32 - 1. An unsigned
    // integer past 2^63 is refused by its sign bit or by its size, never wrapped into range.
    const bool ok = j.is_number_integer() &&
                    !(j.is_number_unsigned() &&
                      j.get<std::uint64_t>() > static_cast<std::uint64_t>(INT64_MAX)) &&
                    in_range(r, static_cast<double>(j.get<std::int64_t>()));
    if (!ok) {
        throw ProfileError(
            fmt::format("{}: must be a whole number {}, not {}", where, range_words(r), j.dump()));
    }
    return j.get<std::int64_t>();
}

} // namespace parsons::axes::profile_values
