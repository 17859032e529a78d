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

// ---- Condition cards: an addition after EP 0640901 (Siemens), not in the patent.
// A condition card (column 76 punched in row 1, docs/card-layout.md) carries up to five
// condition records, each split by converter UMS into a condition (axis, position, sense of
// passing) and an action, both carrying the same event identifier (claim 3). It stands before
// the motion card it watches (claim 4).

// Which kind of card this is: column 76, the extension mark (blank on a 1952 card).
// Row 1 a condition card, row 2 a sync card (the press synchronisation of EP 0436887), row 3 a
// tap card (the spindle synchronisation of EP 0360190).
enum class CardKind : std::uint8_t { motion, condition, sync, tap, segment };

// The sense in which the axis must pass the position: its counters counting up (forward),
// down (reverse), or either.
enum class PassingSense : std::uint8_t { forward, reverse, either };

// What the tripping unit ALE starts when the monitoring unit PRG reports the event.
enum class ActionKind : std::uint8_t {
    spindle_forward = 1, // start (or run up) the spindle forward
    spindle_reverse = 2, // start (or run up) the spindle in reverse
    spindle_stop = 3,    // run the spindle down to rest
    coolant_on = 4,
    coolant_off = 5,
    tool_change = 6, // parameter: the tool to put in the spindle (1..99)
    dwell = 7,       // parameter: the axis to hold (1..5 = table .. tilt)
    lamp = 8,        // parameter: the output lamp to light (1..9)
};
inline constexpr int kActionKinds = 8;
inline constexpr int kConditionsPerCard = 5;

// How long a condition stays armed (column 14 of its slot; an addition beyond EP 0640901's
// claims, after Siemens' later synchronized actions WHENEVER/EVERY): once, the seed's condition,
// armed for the next motion card only (blank); every, armed for every motion card that follows
// until a cancel or the deck's end, firing at each motion card whose counter steps onto its
// position (digit 1); cancel, ending the every-condition of this identifier (digit 2: only the
// event is punched besides).
enum class ConditionMode : std::uint8_t { once, every, cancel };

struct ConditionOrder {
    int event = 0; // identifier 1..99 shared by condition and action (claim 3)
    Axis axis = Axis::table;
    Thousandths position = 0; // compared with the absolute counter, d.ddd
    PassingSense sense = PassingSense::either;
    ActionKind action = ActionKind::lamp;
    int parameter = 0; // 0..9999: tool number, held axis, lamp number (0 where unused)
    ConditionMode mode = ConditionMode::once; // an addition beyond the seed's claims (above)

    bool operator==(const ConditionOrder&) const = default;
};

// "tool-change", "spindle-forward", ...: the listing's and the messages' word for an action.
std::string_view action_name(ActionKind a);
std::optional<ActionKind> action_named(std::string_view name);
// "+", "-", "*"
std::string_view sense_symbol(PassingSense s);
std::string_view sense_name(PassingSense s); // "forward", "reverse", "either"
std::string_view mode_name(ConditionMode m); // "once", "every", "cancel"
// The parameter in words: "tool 2", "hold cross", "lamp 3"; "" for an action without one.
std::string parameter_text(ActionKind a, int parameter);
// The action with its parameter in words: "tool-change (tool 2)", "dwell (hold cross)",
// "lamp (lamp 3)", "coolant-on".
std::string action_text(ActionKind a, int parameter);
// What the parameter of an action means and which values it takes, or an error sentence.
std::optional<std::string> parameter_error(ActionKind a, int parameter);

// ---- Sync cards: an addition after EP 0436887 (Mitsubishi), not in the patent.
// A sync card (column 76 punched in row 2, docs/card-layout.md) carries the seed's
// synchronisation commands for the motion card that follows it: position synchronisation
// (its G101 with R: hold the card's motion until the press's crank 21 reaches the angle) and
// speed synchronisation (its G95 with F: an axis travels F per pulse of detector 10), or
// both; or, alone on its card, the seed's M99: the reader goes back to a card, so many times.
// Any card but a loop card may also order reset switch 16A (claim 5: register 14 "selectively
// resettable at a reference position"): register 14 clears as the card is read, so the crank's
// angle there is the reference every R after it counts from. A card that orders only the reset
// synchronises nothing and needs no motion card after it.
inline constexpr int kMaxTravelPerPulse = 99999; // 0.99999 in per pulse

struct SyncOrder {
    bool position_sync = false; // G101
    int angle_deg = 0;          // R: the crank angle 0..359 (whole degrees) to start at
    // G95: per axis, the travel per detector pulse in hundred-thousandths of an inch
    // (1..99999, read 0.ddddd in); none = this axis is not speed-synchronised.
    std::array<std::optional<int>, kAxisCount> travel_per_pulse{};
    bool loop = false;           // M99
    int loop_to = 0;             // the card number the reader goes back to
    int loop_count = 0;          // how many times it goes back (1..9999)
    bool register_reset = false; // switch 16A: register 14 clears as the card is read

    bool speed_sync() const {
        for (const auto& f : travel_per_pulse) {
            if (f) {
                return true;
            }
        }
        return false;
    }
    // Orders for the motion card after it (a card of the reset alone, or a loop, has none).
    bool synchronises() const { return position_sync || speed_sync(); }
    bool operator==(const SyncOrder&) const = default;
};

// "0.00417" (hundred-thousandths of an inch per pulse)
std::string format_travel_per_pulse(int hundred_thousandths);

// ---- Tap cards: an addition after EP 0360190 (Mitsubishi), not in the patent.
// A tap card (column 76 punched in row 3, docs/card-layout.md) calls for a tool (PC 130 puts
// its spindle head on, and the head's gear ratio reaches memory 12a) and taps one hole: motor 27
// runs forward at S, the axis feeds into the work in step with the tool (the ordered pitch per
// tool revolution, from the encoder's speed times the ratio, S x A) to the depth, and comes back
// out as the spindle reverses. It stands alone: no axis moves by the 1952 columns on it.
inline constexpr int kMaxPitch = 99999;  // 0.99999 in per tool revolution
inline constexpr int kMaxTapTool = 99;   // T: two digits on the card
inline constexpr int kMaxTapRpm = 9999;  // S: four digits on the card, rev/min
inline constexpr int kMaxTapRetract = 4; // the retract multiple k: one digit, 1..4
inline constexpr int kMaxTapPeck = 9999; // the peck depth Q: d.ddd in, four digits

struct TapOrder {
    int tool = 0;                    // T: the head to tap with (1..99)
    Axis axis = Axis::vertical;      // the feed shaft
    Motion motion = Motion::reverse; // the sense into the work (its counters' sense)
    Thousandths depth = 0;           // travel into the work and back, d.ddd in (1..9999)
    int pitch = 0;                   // per tool revolution, hundred-thousandths of an inch
    int rpm = 0;                     // S: motor 27's speed, revolutions a minute (1..9999)
    // An addition after rigid tapping (LinuxCNC G33.1, Fanuc G84): the feed waits for the index
    // of encoder 32 that puts the tool at the same angle every pass (column 19 punched 1).
    bool index_wait = false;
    // An addition after LinuxCNC G33.1's faster retract: the return stroke at k x S, the feed
    // still following the tool (column 20; 1..4, blank 1 = the same speed as going in).
    int retract = 1;
    // An addition after rigid peck tapping (LinuxCNC and Fanuc G84 with Q): in to Q, out to the
    // starting count, in to 2Q, ... to the depth, the feed following one helix throughout
    // (columns 21-24; d.ddd in, 0 = blank, one pass).
    Thousandths peck = 0;

    bool operator==(const TapOrder&) const = default;
};

// The passes into the hole a tap order makes: ceil(depth / Q) with a peck Q, else 1.
inline int tap_passes(const TapOrder& t) {
    return t.peck > 0 ? (t.depth + t.peck - 1) / t.peck : 1;
}

// "0.05000" (hundred-thousandths of an inch per tool revolution)
std::string format_pitch(int hundred_thousandths);

// ---- Segment cards: an addition after EP 0636958 (Black & Decker), not in the patent.
// A segment card (column 76 punched in row 4, docs/card-layout.md) gives one straight segment
// of a contouring path: its end point in X (the table), Y (the cross slide) and Z (the vertical
// slide), d.ddd in from the reference point, and the nominal speed F along it. The contouring
// attachment's interpolator runs the three stepper axes together along it (docs/contouring.md).
inline constexpr int kSegmentAxes = 3;      // X, Y, Z
inline constexpr int kMaxSegmentFeed = 999; // F: three digits, tenths of an inch a minute

struct SegmentOrder {
    std::array<Thousandths, kSegmentAxes> to{}; // the end point, X Y Z, thousandths of an inch
    int feed = 0; // F: the nominal speed along the segment, tenths of in/min (1..999)

    bool operator==(const SegmentOrder&) const = default;
};

// "12.0" (tenths of an inch a minute)
std::string format_feed(int tenths_in_per_min);

struct CardOrders {
    int number = 0; // card number, 0000 .. 9999
    Spindle spindle = Spindle::off;
    std::array<AxisOrder, kAxisCount> axes{};
    // A condition card (an addition): its records; the axes above are unused and left default.
    CardKind kind = CardKind::motion;
    int condition_count = 0;
    std::array<ConditionOrder, kConditionsPerCard> conditions{};
    // A sync card (an addition): its orders; the axes above are unused and left default.
    SyncOrder sync{};
    // A tap card (an addition): its order; the axes above are unused and left default.
    TapOrder tap{};
    // A segment card (an addition): its order; the axes above are unused and left default.
    SegmentOrder segment{};

    const AxisOrder& axis(Axis a) const { return axes.at(axis_index(a)); }
    AxisOrder& axis(Axis a) { return axes.at(axis_index(a)); }
    bool operator==(const CardOrders&) const = default;
};

} // namespace parsons::cardreader
