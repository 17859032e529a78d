#include "axes/profile_relations.hpp"

#include "axes/profile_json.hpp"
#include "axes/screw_error_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <utility>

namespace parsons::axes {
namespace {

// The first axis for which `broken` holds, or nullptr.
template <typename F>
const AxisProfile* first_axis(const MachineProfile& p, F broken) {
    const auto it = std::find_if(p.axes.begin(), p.axes.end(), broken);
    return it == p.axes.end() ? nullptr : &*it;
}

bool travel_inverted(const AxisProfile& a) {
    return !(a.travel_min_in < a.travel_max_in);
}

bool soft_limits_inverted(const AxisProfile& a) {
    return a.soft_limits && !(a.soft_min_in < a.soft_max_in);
}

// The part's position must grow with the screw's (1 + the error's slope > 0), or a limit could
// be passed and found again further on: for each table, and for what the measuring chain makes
// of them together, whichever chain counts and whichever screw cam 160 corrects (lead screw 22,
// or shaft 74 under cam_160_on_instrument_shaft). The first table that falls, and where.
std::optional<std::pair<const char*, double>> falling_table(const AxisProfile& a) {
    const std::array<std::pair<const char*, ScrewErrorTable>, 6> tables = {{
        {"screw_error_in", ScrewErrorTable(a.screw_error_in)},
        {"lead_error_in", ScrewErrorTable(a.lead_error_in)},
        {"lead_error_in - cam_160_in",
         ScrewErrorTable::sum({{&a.lead_error_in, 1}, {&a.cam_160_in, -1}})},
        {"screw_error_in + instrument_error_in",
         ScrewErrorTable::sum({{&a.screw_error_in, 1}, {&a.instrument_error_in, 1}})},
        {"screw_error_in + instrument_error_in - cam_160_in",
         ScrewErrorTable::sum(
             {{&a.screw_error_in, 1}, {&a.instrument_error_in, 1}, {&a.cam_160_in, -1}})},
        {"screw_error_in + lead_error_in - cam_160_in",
         ScrewErrorTable::sum(
             {{&a.screw_error_in, 1}, {&a.lead_error_in, 1}, {&a.cam_160_in, -1}})},
    }};
    for (const auto& [what, table] : tables) {
        if (auto x = table.falls_after()) {
            return std::make_pair(what, *x);
        }
    }
    return std::nullopt;
}

// The press's detector pulses a second at its fastest (variation and a lasting change above 1).
double press_fastest_per_s(const PressProfile& press) {
    return press.strokes_per_min * 6.0 * press.pulses_per_degree * (1 + press.variation) *
           std::max(1.0, press.change_factor);
}

// The spindle motor's fastest: max_rpm, times a lasting change above 1 (counted only when
// change_at_s is set).
double spindle_factor(const SpindleSyncProfile& s) {
    return s.change_at_s ? std::max(1.0, s.change_factor) : 1.0;
}

std::string factor_words(double factor) {
    return factor > 1 ? fmt::format(" (x change_factor {:g})", factor) : "";
}

const ProfileRelation kRelations[] = {
    {"axes.*.travel_min_in < axes.*.travel_max_in",
     "the limit switches stand in order, a travel apart",
     [](const MachineProfile& p) { return first_axis(p, travel_inverted) == nullptr; },
     [](const MachineProfile& p) {
         return fmt::format("axes.{}: travel_min_in must be below travel_max_in",
                            first_axis(p, travel_inverted)->name);
     }},
    {"axes.*.soft_limits_in[0] < axes.*.soft_limits_in[1]", "the soft limits too, when set",
     [](const MachineProfile& p) { return first_axis(p, soft_limits_inverted) == nullptr; },
     [](const MachineProfile& p) {
         return fmt::format("axes.{}: soft_limits_in: the minimum must be below the maximum",
                            first_axis(p, soft_limits_inverted)->name);
     }},
    {"1 + the slope of each axis's error tables > 0",
     "the part moves on as the screw turns, for each table and for each sum of them the "
     "measuring chain uses, so no limit is passed and found again further on",
     [](const MachineProfile& p) {
         return first_axis(p, [](const AxisProfile& a) { return falling_table(a).has_value(); }) ==
                nullptr;
     },
     [](const MachineProfile& p) {
         const AxisProfile* a =
             first_axis(p, [](const AxisProfile& x) { return falling_table(x).has_value(); });
         const auto [what, x] = *falling_table(*a);
         return fmt::format("axes.{}: {}: the error falls faster than the screw advances after "
                            "{} in",
                            a->name, what, x);
     }},
    {"first_bank_s + relay_operate_s < second_bank_s",
     "the first bank's holding relays pick before the second bank senses the card",
     [](const MachineProfile& p) { return p.first_bank_s + p.relay_operate_s < p.second_bank_s; },
     [](const MachineProfile&) -> std::string {
         // Formatted, not one literal: a literal built in place is stored as immediates,
         // and lintian reads their 8-byte pieces as misspelt words.
         return fmt::format(
             "first_bank_s: {} must hold (the {})",
             "first_bank_s + relay_operate_s < second_bank_s",
             "first brush bank's relays pick before the second bank senses the card");
     }},
    {"second_bank_s + 3 stepping_switch_step_s <= reader_cycle_s",
     "every speed switch is set before the card cycle ends and the motors may run",
     [](const MachineProfile& p) {
         return p.second_bank_s + 3 * p.stepping_switch_step_s <= p.reader_cycle_s;
     },
     [](const MachineProfile&) -> std::string {
         return "reader_cycle_s: second_bank_s + 3 stepping_switch_step_s <= reader_cycle_s must "
                "hold (the speed switches step within one card cycle)";
     }},
    {"feed_gap_s < first_bank_s",
     "the gap between two cards passes the brushes before the first bank senses the card",
     [](const MachineProfile& p) { return p.feed_gap_s < p.first_bank_s; },
     [](const MachineProfile&) -> std::string {
         return "feed_gap_s: feed_gap_s < first_bank_s must hold (the gap between two cards "
                "passes the brushes before the first bank senses the card)";
     }},
    {"press.rod_in > press.stroke_in / 2", "the connecting rod is longer than the crank throw",
     [](const MachineProfile& p) { return p.press.rod_in > p.press.stroke_in / 2; },
     [](const MachineProfile& p) {
         return fmt::format("press.rod_in: the connecting rod ({} in) must be longer than the "
                            "crank throw, stroke_in / 2 ({} in)",
                            p.press.rod_in, p.press.stroke_in / 2);
     }},
    {"press.feeder_hold_lag_in = 0 or >= 0.001",
     "the feeder's interlock waits on a lag the counters' thousandth can take out",
     [](const MachineProfile& p) {
         return p.press.feeder_hold_lag_in == 0 || p.press.feeder_hold_lag_in >= 0.001;
     },
     [](const MachineProfile& p) {
         return fmt::format("press.feeder_hold_lag_in: {:g} in is under the counters' thousandth: "
                            "0 (no interlock) or at least 0.001 in",
                            p.press.feeder_hold_lag_in);
     }},
    {"press.pressing_from_deg < press.pressing_to_deg", "the pressing angles in order",
     [](const MachineProfile& p) { return p.press.pressing_from_deg < p.press.pressing_to_deg; },
     [](const MachineProfile& p) {
         return fmt::format("press.pressing_from_deg: must be below pressing_to_deg ({} is not "
                            "below {})",
                            p.press.pressing_from_deg, p.press.pressing_to_deg);
     }},
    {"press.strokes_per_min × 6 × press.pulses_per_degree × (1 + press.variation) × max(1, "
     "press.change_factor) <= max_stepping_rate_per_s",
     "with press_sync: detector 10's pulses at the press's fastest come no faster than the "
     "stepping switches of registers 14 and 11 follow",
     [](const MachineProfile& p) {
         return !p.press_sync || press_fastest_per_s(p.press) <= p.max_stepping_rate_per_s;
     },
     [](const MachineProfile& p) {
         const PressProfile& press = p.press;
         const double fastest = press_fastest_per_s(press);
         return fmt::format(
             "press.strokes_per_min: {} strokes a minute at press.pulses_per_degree {} give up to "
             "{:.0f} detector pulses a second (with variation and change_factor), faster than "
             "the stepping switches of registers 14 and 11 follow (max_stepping_rate_per_s "
             "{}): at most {:.2f} strokes a minute",
             press.strokes_per_min, press.pulses_per_degree, fastest, p.max_stepping_rate_per_s,
             press.strokes_per_min * p.max_stepping_rate_per_s / fastest);
     }},
    {"spindle.first_tool among spindle.heads[].tool", "the run starts with a head on the spindle",
     [](const MachineProfile& p) { return p.spindle.head(p.spindle.first_tool) != nullptr; },
     [](const MachineProfile& p) {
         std::string tools;
         for (const SpindleHead& h : p.spindle.heads) {
             tools += fmt::format("{}{}", tools.empty() ? "" : ", ", h.tool);
         }
         return fmt::format(
             "spindle.first_tool: tool {} is on no head (spindle.heads hold tools {})",
             p.spindle.first_tool, tools);
     }},
    {"spindle.max_rpm × max(1, spindle.change_factor) × spindle.encoder_pulses_per_rev / 60 <= "
     "max_stepping_rate_per_s",
     "with spindle_sync: encoder 32's edges at the motor's fastest come no faster than the "
     "stepping switches of interface 33 follow (change_factor counts only with change_at_s)",
     [](const MachineProfile& p) {
         const SpindleSyncProfile& s = p.spindle;
         return !p.spindle_sync ||
                s.max_rpm * spindle_factor(s) * s.encoder_pulses_per_rev / 60.0 <=
                    p.max_stepping_rate_per_s;
     },
     [](const MachineProfile& p) {
         const SpindleSyncProfile& s = p.spindle;
         const double factor = spindle_factor(s);
         const double edges_per_s = s.max_rpm * factor * s.encoder_pulses_per_rev / 60.0;
         const double most = p.max_stepping_rate_per_s * 60.0 / s.encoder_pulses_per_rev / factor;
         return fmt::format(
             "spindle.max_rpm: {} rev/min{} at spindle.encoder_pulses_per_rev {} give {:.1f} "
             "encoder pulses a second, faster than the stepping switches of spindle encoder "
             "interface 33 follow "
             "(max_stepping_rate_per_s {}): at most {:.2f} rev/min",
             s.max_rpm, factor_words(factor), s.encoder_pulses_per_rev, edges_per_s,
             p.max_stepping_rate_per_s, std::floor(most * 100) / 100);
     }},
    {"spindle.max_rpm × max(1, spindle.change_factor) / 60 × spindle.sample_s < 0.5",
     "with spindle_sync: motor 27 turns less than half a revolution between two samples, so "
     "the NC tells its sense from two readings of interface 33's counter",
     [](const MachineProfile& p) {
         const SpindleSyncProfile& s = p.spindle;
         return !p.spindle_sync || s.max_rpm * spindle_factor(s) / 60.0 * s.sample_s < 0.5;
     },
     [](const MachineProfile& p) {
         const SpindleSyncProfile& s = p.spindle;
         const double factor = spindle_factor(s);
         const double turns = s.max_rpm * factor / 60.0 * s.sample_s;
         return fmt::format(
             "spindle.sample_s: {:g} s at spindle.max_rpm {} rev/min{} turns motor 27 {:.3f} of a "
             "revolution "
             "between two samples of spindle encoder interface 33; from half a revolution on its "
             "counter cannot tell the sense: below {:.4f} s",
             s.sample_s, s.max_rpm, factor_words(factor), turns, 0.5 * 60.0 / (s.max_rpm * factor));
     }},
    {"contour.ramp_steps_per_s2 <= contour.acceleration_steps_per_s2",
     "with contouring: the interpolator's ramps change no motor's pulse rate faster than its "
     "rotor can follow (steps are lost only where the rate jumps: docs/contouring.md)",
     [](const MachineProfile& p) {
         return !p.contouring || p.contour.ramp_steps_per_s2 <= p.contour.acceleration_steps_per_s2;
     },
     [](const MachineProfile& p) {
         return fmt::format("contour.ramp_steps_per_s2: {:g} steps/s² is faster than the rotor "
                            "follows (contour.acceleration_steps_per_s2 {:g}): at most {:g}",
                            p.contour.ramp_steps_per_s2, p.contour.acceleration_steps_per_s2,
                            p.contour.acceleration_steps_per_s2);
     }},
};

} // namespace

std::span<const ProfileRelation> profile_relations() {
    return kRelations;
}

void check_profile_relations(const MachineProfile& p) {
    for (const ProfileRelation& r : kRelations) {
        if (!r.holds(p)) {
            throw ProfileError(r.message(p));
        }
    }
}

} // namespace parsons::axes
