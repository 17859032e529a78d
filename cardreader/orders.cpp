#include "cardreader/orders.hpp"

#include <fmt/format.h>

namespace parsons::cardreader {

std::string_view axis_name(Axis axis) {
    static constexpr std::array<std::string_view, kAxisCount> names = {"table", "cross", "vertical",
                                                                       "swivel", "tilt"};
    return names.at(axis_index(axis));
}

std::optional<Axis> axis_named(std::string_view name) {
    for (Axis a : kAxes) {
        if (axis_name(a) == name) {
            return a;
        }
    }
    return std::nullopt;
}

std::string_view spindle_name(Spindle s) {
    switch (s) {
    case Spindle::forward:
        return "forward";
    case Spindle::reverse:
        return "reverse";
    case Spindle::off:
        break;
    }
    return "off";
}

std::string format_inches(Thousandths value) {
    return fmt::format("{}.{:03}", value / 1000, value % 1000);
}

std::string format_sequence(SequencePattern pattern) {
    std::string text;
    for (int k = 1; k <= kSequencePositions; ++k) {
        if ((pattern & (1u << (k - 1))) != 0) {
            text += static_cast<char>('0' + k);
        }
    }
    return text;
}

} // namespace parsons::cardreader
