#include "axes/profile_values.hpp"

#include "axes/profile_json.hpp"

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

double number_in(const json& j, const std::string& key, double least, bool least_open, double most,
                 bool most_open) {
    const bool ok = j.is_number() && std::isfinite(j.get<double>()) &&
                    (least_open ? j.get<double>() > least : j.get<double>() >= least) &&
                    (most_open ? j.get<double>() < most : j.get<double>() <= most);
    if (!ok) {
        const std::string above = fmt::format("{} {}", least_open ? "above" : "at least", least);
        const std::string below =
            std::isinf(most) ? ""
                             : fmt::format(" and {} {}", most_open ? "below" : "at most", most);
        throw ProfileError(
            fmt::format("{}: must be a number {}{}, not {}", key, above, below, j.dump()));
    }
    return j.get<double>();
}

std::int64_t whole_in(const json& j, const std::string& key, std::int64_t least,
                      std::int64_t most) {
    // 64 bits on every target (long is 32 on WebAssembly): a seed runs to 2^32 - 1.
    if (!j.is_number_integer() || j.get<std::int64_t>() < least || j.get<std::int64_t>() > most) {
        throw ProfileError(fmt::format("{}: must be a whole number from {} to {}, not {}", key,
                                       least, most, j.dump()));
    }
    return j.get<std::int64_t>();
}

} // namespace parsons::axes::profile_values
