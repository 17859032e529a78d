// What one card orders the machine to do, once the brushes have sensed it: the spindle
// direction (column 165 of Fig. 8), the card number (for the card-number check, which the
// patent gives no numeral) and, for each of the five lead-screw axes, its motion, start speed,
// slow-downs, stop, check and sequence pattern (222). Numbers are kept as the card holds them:
// four decimal digits, thousandths of an inch.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace parsons::cardreader {

// The five lead-screw axes of Fig. 1, in card order.
enum class Axis : std::uint8_t { table, cross, vertical, swivel, tilt };
inline constexpr int kAxisCount = 5;
inline constexpr std::array<Axis, kAxisCount> kAxes = {Axis::table, Axis::cross, Axis::vertical,
                                                       Axis::swivel, Axis::tilt};

std::string_view axis_name(Axis axis);
std::optional<Axis> axis_named(std::string_view name);
inline std::size_t axis_index(Axis axis) {
    return static_cast<std::size_t>(axis);
}

// Reversing control 214: row 0 = forward (counters count up), row 1 = reverse (count down).
enum class Motion : std::uint8_t { forward, reverse };

// Spindle column 165: row 0 = forward, row 1 = reverse, blank = spindle off.
enum class Spindle : std::uint8_t { off, forward, reverse };

std::string_view spindle_name(Spindle s);

// A four-digit card number in thousandths of an inch: 0 .. 9999 (0.000 .. 9.999 in).
using Thousandths = std::uint16_t;
inline constexpr Thousandths kMaxThousandths = 9999;

// "8.785"
std::string format_inches(Thousandths value);

// Sequence pattern 222: bit k-1 set when position k (1..5) is punched.
using SequencePattern = std::uint8_t;
inline constexpr int kSequencePositions = 5;
// "12", "5", "" (digits of the punched positions, ascending)
std::string format_sequence(SequencePattern pattern);

struct AxisOrder {
    Motion motion = Motion::forward;
    int start_speed = 3; // 1 (fastest) .. 3 (slowest): speed switch 236 steps 1, 2 or 3 times
    std::array<std::optional<Thousandths>, 2> slow_down{}; // first, second slow-down (or none)
    Thousandths stop = 0;
    Thousandths check = 0;
    SequencePattern sequence = 0;

    bool operator==(const AxisOrder&) const = default;
};

struct CardOrders {
    int number = 0; // card number, 0000 .. 9999
    Spindle spindle = Spindle::off;
    std::array<AxisOrder, kAxisCount> axes{};

    const AxisOrder& axis(Axis a) const { return axes.at(axis_index(a)); }
    AxisOrder& axis(Axis a) { return axes.at(axis_index(a)); }
    bool operator==(const CardOrders&) const = default;
};

} // namespace parsons::cardreader
