// Machine state as JSON, exactly: every double to the last bit (17 significant digits, which
// nlohmann writes and reads back unchanged) and the infinities JSON has no number for ("inf",
// "-inf": a time that never comes, a switch that never stepped).
#pragma once

#include <nlohmann/json.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace parsons::axes {

class StateError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

inline nlohmann::json exact(double v) {
    if (std::isinf(v)) {
        return v > 0 ? "inf" : "-inf";
    }
    return v;
}

inline double exact(const nlohmann::json& j) {
    if (j.is_string()) {
        const auto s = j.get<std::string>();
        if (s == "inf" || s == "-inf") {
            return (s == "inf" ? 1 : -1) * std::numeric_limits<double>::infinity();
        }
    }
    if (!j.is_number()) {
        throw StateError("expected a number, \"inf\" or \"-inf\", found " + j.dump());
    }
    return j.get<double>();
}

// The member `key` of a state object, or a StateError naming it.
inline const nlohmann::json& member(const nlohmann::json& j, const char* key) {
    if (!j.is_object() || !j.contains(key)) {
        throw StateError(std::string("missing '") + key + "'");
    }
    return j.at(key);
}

template <typename T>
T read(const nlohmann::json& j, const char* key) {
    try {
        return member(j, key).get<T>();
    } catch (const nlohmann::json::exception&) {
        throw StateError(std::string("'") + key + "' has the wrong type");
    }
}

} // namespace parsons::axes
