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

namespace {
constexpr std::array<std::string_view, kActionKinds> kActionNames = {
    "spindle-forward", "spindle-reverse", "spindle-stop", "coolant-on",
    "coolant-off",     "tool-change",     "dwell",        "lamp"};
} // namespace

std::string_view action_name(ActionKind a) {
    const auto i = static_cast<std::size_t>(a) - 1;
    return i < kActionNames.size() ? kActionNames.at(i) : std::string_view("unknown");
}

std::optional<ActionKind> action_named(std::string_view name) {
    for (std::size_t i = 0; i < kActionNames.size(); ++i) {
        if (kActionNames.at(i) == name) {
            return static_cast<ActionKind>(i + 1);
        }
    }
    return std::nullopt;
}

std::string_view sense_symbol(PassingSense s) {
    return s == PassingSense::forward ? "+" : s == PassingSense::reverse ? "-" : "*";
}

std::string_view mode_name(ConditionMode m) {
    return m == ConditionMode::every ? "every" : m == ConditionMode::cancel ? "cancel" : "once";
}

std::string_view sense_name(PassingSense s) {
    return s == PassingSense::forward   ? "forward"
           : s == PassingSense::reverse ? "reverse"
                                        : "either";
}

std::string parameter_text(ActionKind a, int parameter) {
    switch (a) {
    case ActionKind::tool_change:
        return fmt::format("tool {}", parameter);
    case ActionKind::dwell:
        return parameter >= 1 && parameter <= kAxisCount
                   ? fmt::format("hold {}",
                                 axis_name(kAxes.at(static_cast<std::size_t>(parameter - 1))))
                   : std::string();
    case ActionKind::lamp:
        return fmt::format("lamp {}", parameter);
    default:
        return {};
    }
}

std::string action_text(ActionKind a, int parameter) {
    const std::string what = parameter_text(a, parameter);
    return what.empty() ? std::string(action_name(a))
                        : fmt::format("{} ({})", action_name(a), what);
}

std::optional<std::string> parameter_error(ActionKind a, int parameter) {
    switch (a) {
    case ActionKind::tool_change:
        if (parameter < 1 || parameter > 99) {
            return fmt::format("tool-change needs the tool number 1..99, not {}", parameter);
        }
        return std::nullopt;
    case ActionKind::dwell:
        if (parameter < 1 || parameter > kAxisCount) {
            return fmt::format("dwell needs the axis to hold, 1..5 (table, cross, vertical, "
                               "swivel, tilt), not {}",
                               parameter);
        }
        return std::nullopt;
    case ActionKind::lamp:
        if (parameter < 1 || parameter > 9) {
            return fmt::format("lamp needs the lamp number 1..9, not {}", parameter);
        }
        return std::nullopt;
    default:
        if (parameter != 0) {
            return fmt::format("{} takes no parameter (leave it blank), not {}", action_name(a),
                               parameter);
        }
        return std::nullopt;
    }
}

std::string format_inches(Thousandths value) {
    return fmt::format("{}.{:03}", value / 1000, value % 1000);
}

std::string format_travel_per_pulse(int hundred_thousandths) {
    return fmt::format("{}.{:05}", hundred_thousandths / 100000, hundred_thousandths % 100000);
}

std::string format_pitch(int hundred_thousandths) {
    return format_travel_per_pulse(hundred_thousandths);
}

std::string format_feed(int tenths_in_per_min) {
    return fmt::format("{}.{}", tenths_in_per_min / 10, tenths_in_per_min % 10);
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
