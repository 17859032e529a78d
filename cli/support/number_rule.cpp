#include "cli/support/number_rule.hpp"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace parsons::cli {
namespace {

constexpr std::string_view kExamples = "a decimal number such as 6, -0.5 or 1.5e-3";

std::string lower(std::string_view text) {
    std::string out;
    for (const char c : text) {
        out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return out;
}

// The length of the run of decimal digits at `at`.
std::size_t digits_at(std::string_view text, std::size_t at) {
    std::size_t n = 0;
    while (at + n < text.size() && std::isdigit(static_cast<unsigned char>(text[at + n])) != 0) {
        ++n;
    }
    return n;
}

// True when `text` is a decimal number of this kind: [+-] digits [. digits] [e [+-] digits],
// with at least one digit before the exponent (a real may be written .5 or 5.).
bool decimal_shape(std::string_view text, NumberKind kind) {
    std::size_t at = text.empty() || (text[0] != '+' && text[0] != '-') ? 0 : 1;
    std::size_t mantissa = digits_at(text, at);
    at += mantissa;
    if (kind == NumberKind::whole) {
        return mantissa > 0 && at == text.size();
    }
    if (at < text.size() && text[at] == '.') {
        const std::size_t fraction = digits_at(text, at + 1);
        mantissa += fraction;
        at += 1 + fraction;
    }
    if (mantissa == 0) {
        return false;
    }
    if (at < text.size() && (text[at] == 'e' || text[at] == 'E')) {
        ++at;
        if (at < text.size() && (text[at] == '+' || text[at] == '-')) {
            ++at;
        }
        const std::size_t exponent = digits_at(text, at);
        if (exponent == 0) {
            return false;
        }
        at += exponent;
    }
    return at == text.size();
}

std::optional<std::string> shape_problem(std::string_view text, NumberKind kind) {
    const std::string word = lower(text);
    const std::string_view unsigned_word = !word.empty() && (word[0] == '+' || word[0] == '-')
                                               ? std::string_view(word).substr(1)
                                               : std::string_view(word);
    if (unsigned_word == "nan" || unsigned_word.starts_with("nan(")) {
        return fmt::format("'{}' is not a number: give {}", text, kExamples);
    }
    if (unsigned_word == "inf" || unsigned_word == "infinity") {
        return fmt::format("'{}' is not finite: give {}", text, kExamples);
    }
    if (unsigned_word.size() > 1 && unsigned_word[0] == '0' &&
        (unsigned_word[1] == 'x' || unsigned_word[1] == 'b' || unsigned_word[1] == 'o')) {
        return fmt::format("'{}' is not decimal: numbers are written in decimal (hexadecimal, "
                           "octal and binary are not read)",
                           text);
    }
    if (kind == NumberKind::whole && decimal_shape(text, NumberKind::real)) {
        return fmt::format("'{}' is not a whole number: give digits only, e.g. 3", text);
    }
    return fmt::format("'{}' is not a number: give {}", text,
                       kind == NumberKind::whole ? "a whole number such as 3" : kExamples);
}

} // namespace

std::optional<std::string> number_problem(std::string_view text, NumberKind kind) {
    if (text.empty()) {
        return std::string("an empty value is not a number");
    }
    if (!decimal_shape(text, kind)) {
        return shape_problem(text, kind);
    }
    const std::string copy(text);
    errno = 0;
    if (kind == NumberKind::whole) {
        const long long v = std::strtoll(copy.c_str(), nullptr, 10);
        if (errno == ERANGE || v > std::numeric_limits<int>::max() ||
            v < std::numeric_limits<int>::min()) {
            return fmt::format("'{}' is too large: a whole number here is at most 2,147,483,647 "
                               "either side of zero",
                               text);
        }
        return std::nullopt;
    }
    const double v = std::strtod(copy.c_str(), nullptr);
    if (!std::isfinite(v)) {
        return fmt::format("'{}' is too large for any quantity (the largest is about 1.8e308)",
                           text);
    }
    return std::nullopt;
}

void apply_number_rule(CLI::App& app) {
    for (CLI::Option* option : app.get_options()) {
        // The type name CLI11 gave it, before any ':' and the checks' descriptions.
        const std::string full = option->get_type_name();
        const std::string type = full.substr(0, full.find(':'));
        NumberKind kind = NumberKind::real;
        if (type == "INT" || type == "UINT") {
            kind = NumberKind::whole;
        } else if (type != "FLOAT") {
            continue;
        }
        // A transform (CLI11's check() would not let it drop the zeros), run before the
        // option's own checks (bench's ranges), so the reason given is this rule's.
        option->transform(CLI::Validator(
            [kind](std::string& value) -> std::string {
                if (const auto problem = number_problem(value, kind)) {
                    return *problem;
                }
                if (kind == NumberKind::whole) { // 010 is ten: CLI11 would read it as octal
                    const std::size_t sign = value[0] == '+' || value[0] == '-' ? 1 : 0;
                    const std::size_t first = value.find_first_not_of('0', sign);
                    value = value.substr(0, sign) +
                            (first == std::string::npos ? "0" : value.substr(first));
                }
                return {};
            },
            ""));
    }
    for (CLI::App* sub : app.get_subcommands({})) {
        apply_number_rule(*sub);
    }
}

} // namespace parsons::cli
