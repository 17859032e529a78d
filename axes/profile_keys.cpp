// The table of every number a profile holds, and why each range is what it is:
//   durations (`..._s`) above 0, at most 60 s; speeds 0.1..1000 in/min; accelerations at least
//     0.001 in/s2: machine time is a double, and these keep a deck of 9999 cards under 1e9 s,
//     where it still resolves a microsecond (at 1e15 s it cannot tell one impulse from the next).
//   sync_timeout_s and spindle.transfer_timeout_s up to an hour (a press of 0.1 strokes a minute
//     takes ten minutes a revolution).
//   backlash_in 0..0.1 in: a worn nut has a few thousandths; a tenth of an inch is no nut.
//   error tables: positions within +-1000 in, errors within +-1 in (a real screw's; far beyond,
//     the interpolation overflows).
//   tool numbers 1..99: two columns of a card.
//   press.pulses_per_degree 1..27: 360 x it fits the four decades of position register 14.
//   press.change_cycle, stop_cycle up to 1e9 revolutions: beyond any run, and 360 x it is exact.
//   press.feeder_hold_lag_in 0 (none) or 0.001..1 in: under the counters' thousandth the press
//     would wait on a lag the counters cannot see go (a relation); an inch is no feeder's lag.
//   spindle.max_rpm 1..9999: a tap card's speed field has four digits.
//   spindle.encoder_pulses_per_rev 4..9999: phases A and B in quadrature give four edges for each
//     line of the disc at least; interface 33's counter holds a revolution in four decades.
//   spindle.change_at_s 0..1e9 s (or null): machine time still resolves a microsecond there.
#include "axes/profile_keys.hpp"

#include "axes/profile_relations.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace parsons::axes {
namespace {

using T = KeyType;
constexpr double kN = kNoEnd;
// Flags for an end that is open (above, below) or closed (at least, at most).
constexpr bool kOpen = true;
constexpr bool kShut = false;

constexpr KeyRange duration(std::string_view key, std::string_view meaning) {
    return {key, T::number, 0, kOpen, 60, kShut, "s", meaning};
}
constexpr KeyRange any(std::string_view key, std::string_view unit, std::string_view meaning) {
    return {key, T::number, -kN, kShut, kN, kShut, unit, meaning};
}
constexpr KeyRange positive(std::string_view key, std::string_view unit, std::string_view meaning) {
    return {key, T::number, 0, kOpen, kN, kShut, unit, meaning};
}
constexpr KeyRange tool(std::string_view key, std::string_view meaning) {
    return {key, T::whole, 1, kShut, 99, kShut, "", meaning};
}
// An error table's [position, error] pairs.
constexpr KeyRange table_position(std::string_view key) {
    return {key, T::number, -1000, kShut, 1000, kShut, "in", "A position of the error table"};
}
constexpr KeyRange table_error(std::string_view key) {
    return {key, T::number, -1, kShut, 1, kShut, "in", "The error table's error there"};
}

const KeyRange kKeys[] = {
    // The cabinet.
    duration("reader_cycle_s", "One card cycle of reader 134"),
    duration("first_bank_s", "When the first brush bank senses the card"),
    duration("second_bank_s", "When the second brush bank senses the speed columns"),
    duration("feed_gap_s", "The gap between two cards passing the brushes"),
    duration("relay_operate_s", "Operate time of a telephone-type relay"),
    duration("relay_release_s", "Release time of a relay"),
    duration("stepping_switch_step_s", "One step of a rotary stepping switch"),
    positive("max_stepping_rate_per_s", "/s",
             "The fastest impulse rate a counter stepping switch follows"),
    duration("delay_258_s", "Delay device 258's hold after an impulse"),
    duration("sequence_shaft_step_s", "Motor 278 moving stepping shaft 280 one position"),
    // Condition cards.
    duration("actions.spindle_run_up_s", "The spindle motor from rest to cutting speed"),
    duration("actions.spindle_run_down_s", "The spindle motor from cutting speed to rest"),
    duration("actions.coolant_valve_s", "The coolant valve's stroke"),
    duration("actions.tool_change_s", "The tool changer's whole cycle"),
    duration("actions.dwell_s", "How long a dwell holds the axis"),
    duration("actions.lamp_s", "An output lamp's relay operating"),
    tool("tools[].number", "A tool changer's tool number"),
    positive("tools[].radius_in", "in", "Its cutter radius"),
    tool("first_tool", "The tool in the spindle when the run starts"),
    // Press synchronisation.
    {"press.strokes_per_min", T::number, 0.1, kShut, 120, kShut, "rev/min",
     "Motor 22's nominal speed"},
    {"press.pulses_per_degree", T::whole, 1, kShut, 27, kShut, "/deg",
     "Detector 10's edges a degree of crank"},
    {"press.start_angle_deg", T::number, 0, kShut, 360, kOpen, "deg",
     "Where crank 21 stands when the run starts"},
    positive("press.stroke_in", "in", "Die 20's travel, twice the crank throw"),
    positive("press.rod_in", "in", "The connecting rod, pin to pin"),
    {"press.pressing_from_deg", T::number, 0, kShut, 360, kShut, "deg",
     "Where the die starts to work the metal"},
    {"press.pressing_to_deg", T::number, 0, kShut, 360, kShut, "deg",
     "Where the die stops working the metal"},
    {"press.pressing_slowdown", T::number, 0, kShut, 0.9, kShut, "",
     "The fraction of speed lost while pressing"},
    {"press.drift_per_cycle", T::number, -0.1, kShut, 0.1, kShut, "",
     "Each revolution's speed change over the one before"},
    {"press.variation", T::number, 0, kShut, 0.5, kShut, "",
     "Each revolution's random speed spread"},
    {"press.seed", T::whole, 0, kShut, 4294967295.0, kShut, "", "What the spread is drawn from"},
    {"press.change_cycle", T::whole, 0, kShut, 1e9, kShut, "",
     "The revolution of a lasting change of speed (0: none)"},
    {"press.change_angle_deg", T::number, 0, kShut, 360, kOpen, "deg",
     "The crank angle of the change"},
    {"press.change_factor", T::number, 0, kOpen, 4, kShut, "", "The speed after it, times"},
    {"press.stop_cycle", T::whole, 0, kShut, 1e9, kShut, "",
     "The revolution motor 22 stops at (0: never)"},
    {"press.stop_angle_deg", T::number, 0, kShut, 360, kOpen, "deg", "The crank angle it stops at"},
    {"press.feeder_hold_lag_in", T::number, 0, kShut, 1, kShut, "in",
     "The lag of a synchronised axis that holds the press (0: never)"},
    {"sync_drive.max_in_per_min", T::number, 0.1, kShut, 1000, kShut, "in/min",
     "The speed-following drive's fastest"},
    {"sync_drive.acceleration_in_per_s2", T::number, 0.001, kShut, kN, kShut, "in/s²",
     "Its rate limit, both ways"},
    {"sync_drive.position_gain_per_s", T::number, 0, kShut, 100, kShut, "/s",
     "Processor 63's position loop gain (0: off)"},
    {"speed_sample_s", T::number, 0.001, kShut, 1, kShut, "s",
     "The reference block of EP 0436887 Fig. 6"},
    {"sync_timeout_s", T::number, 0, kOpen, 3600, kShut, "s",
     "How long processor 17 waits for the crank"},
    // Spindle synchronisation.
    {"spindle.max_rpm", T::number, 1, kShut, 9999, kShut, "rev/min", "Motor 27's fastest speed"},
    positive("spindle.run_up_rpm_per_s", "rev/min/s", "How fast the motor gains speed"),
    positive("spindle.run_down_rpm_per_s", "rev/min/s", "How fast it loses speed"),
    {"spindle.encoder_pulses_per_rev", T::whole, 4, kShut, 9999, kShut, "/rev",
     "Encoder 32's edges a motor revolution"},
    {"spindle.sample_s", T::number, 0.001, kShut, 1, kShut, "s",
     "How often the NC reads interface 33"},
    {"spindle.feed_gain_per_s", T::number, 0, kShut, 1000, kShut, "/s",
     "Position correction of the synchronised feed (0: none)"},
    {"spindle.change_at_s", T::number, 0, kShut, 1e9, kShut, "s",
     "When a lasting change of the motor's speed comes (or null: none)"},
    {"spindle.change_factor", T::number, 0.1, kShut, 2, kShut, "", "The speed after it, times"},
    {"spindle.pc_scan_s", T::number, 0.001, kShut, 1, kShut, "s", "One scan of PC 130's ladder"},
    {"spindle.head_change_s", T::number, 0, kShut, 600, kShut, "s", "A head exchange by PC 130"},
    {"spindle.transfer_timeout_s", T::number, 0, kOpen, 3600, kShut, "s",
     "How long the NC waits for PC 130's ratio transfer"},
    {"spindle.chamfer_revs", T::number, 0, kShut, 20, kShut, "rev",
     "The tap's chamfer, tool revolutions"},
    tool("spindle.heads[].tool", "The tool number a tap card calls a head by"),
    {"spindle.heads[].ratio", T::number, 0, kOpen, 10, kShut, "",
     "Its ratio A: tool revolutions a motor revolution"},
    {"spindle.heads[].pitch_in", T::number, 0, kOpen, 1, kOpen, "in", "A tap's pitch"},
    {"spindle.heads[].radius_in", T::number, 0, kOpen, 2, kOpen, "in", "A cutter's radius"},
    tool("spindle.first_tool", "The head on the spindle when the run starts"),
    // Contouring.
    {"contour.steps_per_in", T::whole, 100, kShut, 10000, kShut, "/in",
     "Steps of a stepper axis to the inch"},
    {"contour.pull_in_steps_per_s", T::number, 0, kOpen, 100000, kShut, "/s",
     "A change of pulse rate the motor follows at once"},
    {"contour.acceleration_steps_per_s2", T::number, 1, kShut, 1e7, kShut, "/s²",
     "How fast the rotor can change its pulse rate"},
    {"contour.ramp_steps_per_s2", T::number, 1, kShut, 1e7, kShut, "/s²",
     "The interpolator's ramps, per axis at most"},
    {"contour.max_rate_change_steps_per_s", T::number, 0, kShut, 100000, kShut, "/s",
     "Claim 1's maximum difference of a motor's pulse rate"},
    {"contour.minimum_in_per_min", T::number, 0, kShut, 99.9, kShut, "in/min",
     "The speed a slowed junction is met at (claim 4: 0)"},
    // Each axis.
    {"axes.*.speed_in_per_min[]", T::number, 0.1, kShut, 1000, kShut, "in/min",
     "Speeds 1, 2, 3 of speed switch 236"},
    {"axes.*.acceleration_in_per_s2", T::number, 0.001, kShut, kN, kShut, "in/s²",
     "How fast the motor and its load change speed"},
    {"axes.*.braking_in_per_s2", T::number, 0.001, kShut, kN, kShut, "in/s²",
     "Deceleration while coasting to rest"},
    any("axes.*.travel_min_in", "in", "Where the lower limit switch cuts the power"),
    any("axes.*.travel_max_in", "in", "Where the upper limit switch cuts the power"),
    any("axes.*.soft_limits_in[0]", "in", "The soft limits' minimum (the pair or null)"),
    any("axes.*.soft_limits_in[1]", "in", "The soft limits' maximum"),
    positive("axes.*.screw_lead_in_per_rev", "in/rev", "Lead of the screw"),
    positive("axes.*.pivot_to_screw_in", "in", "Sine plate: pivot to screw"),
    any("axes.*.level_in", "in", "The screw position where the fixture stands level"),
    {"axes.*.backlash_in", T::number, 0, kShut, 0.1, kShut, "in", "Backlash in nut 78"},
    table_position("axes.*.screw_error_in[][0]"),
    table_error("axes.*.screw_error_in[][1]"),
    table_position("axes.*.lead_error_in[][0]"),
    table_error("axes.*.lead_error_in[][1]"),
    table_position("axes.*.instrument_error_in[][0]"),
    table_error("axes.*.instrument_error_in[][1]"),
    table_position("axes.*.cam_160_in[][0]"),
    table_error("axes.*.cam_160_in[][1]"),
};

// A bound as the docs and messages write it: 60, 0.001, 1000000000 (not 1e+09).
std::string bound(double v) {
    if (v == std::floor(v) && std::abs(v) < 1e15) {
        return fmt::format("{}", static_cast<std::int64_t>(v));
    }
    return fmt::format("{}", v);
}

} // namespace

std::span<const KeyRange> profile_key_ranges() {
    return kKeys;
}

const KeyRange& profile_key_range(std::string_view key) {
    for (const KeyRange& r : kKeys) {
        if (r.key == key) {
            return r;
        }
    }
    throw std::logic_error(fmt::format("profile key {} is not in axes/profile_keys.cpp", key));
}

bool in_range(const KeyRange& r, double v) {
    return std::isfinite(v) && (r.least_open ? v > r.least : v >= r.least) &&
           (r.most_open ? v < r.most : v <= r.most);
}

std::string range_words(const KeyRange& r) {
    const bool below = std::isfinite(r.least);
    const bool above = std::isfinite(r.most);
    if (r.type == KeyType::whole && !r.least_open && !r.most_open && below && above) {
        return fmt::format("from {} to {}", bound(r.least), bound(r.most));
    }
    std::string words;
    if (below) {
        words = fmt::format("{} {}", r.least_open ? "above" : "at least", bound(r.least));
    }
    if (above) {
        words += fmt::format("{}{} {}", words.empty() ? "" : " and ",
                             r.most_open ? "below" : "at most", bound(r.most));
    }
    return words.empty() ? "any" : words;
}

std::string profile_ranges_markdown() {
    std::string md = "| key | type | range | unit | what it is |\n|---|---|---|---|---|\n";
    for (const KeyRange& r : kKeys) {
        md += fmt::format("| `{}` | {} | {} | {} | {} |\n", r.key,
                          r.type == KeyType::whole ? "whole number" : "number", range_words(r),
                          r.unit.empty() ? "—" : r.unit, r.meaning);
    }
    md += "\nAnd between keys, checked once every key is read (each message starts with "
          "the key it names):\n\n";
    for (const ProfileRelation& rel : profile_relations()) {
        md += fmt::format("- `{}`: {}\n", rel.rule, rel.why);
    }
    return md;
}

} // namespace parsons::axes
