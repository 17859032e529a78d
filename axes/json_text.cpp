#include "axes/json_text.hpp"

#include <cstdio>
#include <cstdlib>

namespace parsons::axes {

namespace {

bool number_char(char c) {
    return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.' || c == 'e' || c == 'E';
}

std::size_t significant_digits(std::string_view token) {
    std::size_t digits = 0;
    bool leading = true;
    for (char c : token) {
        if (c == 'e' || c == 'E') {
            break;
        }
        if (c < '0' || c > '9') {
            continue;
        }
        leading = leading && c == '0';
        digits += leading ? 0 : 1;
    }
    return digits;
}

// The shortest "%.{p}g" text that reads back to the token's double, or the token itself when
// none is shorter. Only a token of 16 or more significant digits can have one: a double's
// 15-digit decimal always reads back to itself. (snprintf and strtod rather than
// std::to_chars: the WebAssembly build's libc++ has no floating-point to_chars.)
std::string shortest(std::string_view token) {
    const std::string text(token);
    if (text.find_first_of(".eE") == std::string::npos || significant_digits(text) < 16) {
        return text;
    }
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size()) {
        return text;
    }
    for (int precision = 1; precision <= 17; ++precision) {
        char buffer[40];
        const int n = std::snprintf(buffer, sizeof buffer, "%.*g", precision, value);
        if (n <= 0 || n >= static_cast<int>(sizeof buffer) ||
            std::strtod(buffer, nullptr) != value) {
            continue;
        }
        std::string candidate(buffer, static_cast<std::size_t>(n));
        if (candidate.find_first_of(".e") == std::string::npos) {
            candidate += ".0"; // still a fraction to a reader that keeps integers apart
        }
        return candidate.size() < text.size() ? candidate : text;
    }
    return text;
}

} // namespace

std::string shortest_numbers(std::string_view json) {
    std::string out;
    out.reserve(json.size());
    bool in_string = false;
    for (std::size_t i = 0; i < json.size(); ++i) {
        const char c = json[i];
        if (in_string) {
            out += c;
            if (c == '\\' && i + 1 < json.size()) {
                out += json[++i];
            } else if (c == '"') {
                in_string = false;
            }
            continue;
        }
        if (c == '"') {
            in_string = true;
            out += c;
            continue;
        }
        if (c == '-' || (c >= '0' && c <= '9')) {
            std::size_t end = i;
            while (end < json.size() && number_char(json[end])) {
                ++end;
            }
            out += shortest(json.substr(i, end - i));
            i = end - 1;
            continue;
        }
        out += c;
    }
    return out;
}

std::string json_text(const nlohmann::json& j, int indent) {
    return shortest_numbers(j.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace));
}

std::string json_text(const nlohmann::ordered_json& j, int indent) {
    return shortest_numbers(
        j.dump(indent, ' ', false, nlohmann::ordered_json::error_handler_t::replace));
}

} // namespace parsons::axes
