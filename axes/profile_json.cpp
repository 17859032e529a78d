#include "axes/profile_json.hpp"
#include "axes/profile_values.hpp"

#include "axes/json_text.hpp"
#include "axes/screw_error_table.hpp"
#include "axes/spindle_json.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace parsons::axes {
namespace {

using nlohmann::json;
using profile_values::flag;
using profile_values::number_in;
using profile_values::whole_in;

// A screw-error table a real screw can have: positions along a screw of a few feet, errors of
// thousandths left after compensating cam 160. Far beyond, the interpolation overflows.
constexpr double kScrewPositionLimitIn = 1000;
constexpr double kScrewErrorLimitIn = 1;

// Machine time is a double. Durations of a minute at most, speeds of 0.1 to 1000 in/min and
// accelerations of 0.001 in/s2 or more keep a deck of 9999 cards under 1e9 s, where it still
// resolves a microsecond; at 1e15 s it cannot tell one impulse from the next.
constexpr double kMaxDurationS = 60;
constexpr double kMinSpeedInPerMin = 0.1;
constexpr double kMaxSpeedInPerMin = 1000;
constexpr double kMinAccelerationInPerS2 = 0.001;
// Backlash in nut 78: a worn nut might have a few thousandths; a tenth of an inch is no nut.
constexpr double kMostBacklashIn = 0.1;

double positive(const json& j, const std::string& key) {
    if (!j.is_number()) {
        throw ProfileError(fmt::format("{}: expected a number", key));
    }
    const double v = j.get<double>();
    if (!(v > 0) || !std::isfinite(v)) {
        throw ProfileError(fmt::format("{}: must be a positive number, not {}", key, j.dump()));
    }
    return v;
}

double within(const json& j, const std::string& key, double least, double most) {
    const double v = positive(j, key);
    if (v < least || v > most) {
        throw ProfileError(
            fmt::format("{}: must lie between {} and {}, not {}", key, least, most, j.dump()));
    }
    return v;
}

double duration(const json& j, const std::string& key) {
    return within(j, key, 0, kMaxDurationS);
}

double finite(const json& j, const std::string& key) {
    if (!j.is_number() || !std::isfinite(j.get<double>())) {
        throw ProfileError(fmt::format("{}: expected a number", key));
    }
    return j.get<double>();
}

ErrorPoints error_points(const json& value, const std::string& k) {
    if (!value.is_array()) {
        throw ProfileError(fmt::format("{}: expected [[position, error], ...]", k));
    }
    ErrorPoints points;
    for (const auto& pair : value) {
        if (!pair.is_array() || pair.size() != 2) {
            throw ProfileError(fmt::format("{}: expected [[position, error], ...]", k));
        }
        const double x = finite(pair.at(0), k);
        const double e = finite(pair.at(1), k);
        if (!points.empty() && x <= points.back().first) {
            throw ProfileError(fmt::format("{}: positions must increase", k));
        }
        if (std::abs(x) > kScrewPositionLimitIn || std::abs(e) > kScrewErrorLimitIn) {
            throw ProfileError(fmt::format(
                "{}: [{}, {}]: positions must lie within +-{} in and errors within +-{} in", k, x,
                e, kScrewPositionLimitIn, kScrewErrorLimitIn));
        }
        points.emplace_back(x, e);
    }
    return points;
}

json points_json(const ErrorPoints& points) {
    json out = json::array();
    for (const auto& [x, e] : points) {
        out.push_back({x, e});
    }
    return out;
}

// --- The measuring chain of Fig. 3: lead screw 22, nut 78, instrument shaft 74, cam 160 ---
bool apply_chain_key(const std::string& key, const json& value, AxisProfile& a,
                     const std::string& k) {
    if (key == "lead_error_in") {
        a.lead_error_in = error_points(value, k);
    } else if (key == "instrument_error_in") {
        a.instrument_error_in = error_points(value, k);
    } else if (key == "cam_160_in") {
        a.cam_160_in = error_points(value, k);
    } else if (key == "backlash_in") {
        if (!value.is_number() || !(value.get<double>() >= 0) ||
            value.get<double>() > kMostBacklashIn) {
            throw ProfileError(fmt::format("{}: must be a number from 0 to {} in, not {}", k,
                                           kMostBacklashIn, value.dump()));
        }
        a.backlash_in = value.get<double>();
    } else {
        return false;
    }
    return true;
}

void chain_json(const AxisProfile& a, json& j) {
    j["lead_error_in"] = points_json(a.lead_error_in);
    j["backlash_in"] = a.backlash_in;
    j["instrument_error_in"] = points_json(a.instrument_error_in);
    j["cam_160_in"] = points_json(a.cam_160_in);
}

void apply_axis(const json& j, AxisProfile& a, const std::string& where) {
    if (!j.is_object()) {
        throw ProfileError(fmt::format("{}: expected an object", where));
    }
    for (const auto& [key, value] : j.items()) {
        const std::string k = where + "." + key;
        if (key == "speed_in_per_min") {
            if (!value.is_array() || value.size() != 3) {
                throw ProfileError(fmt::format("{}: expected three speeds [1, 2, 3]", k));
            }
            for (std::size_t i = 0; i < 3; ++i) {
                a.speed_in_per_min.at(i) = within(value.at(i), fmt::format("{}[{}]", k, i),
                                                  kMinSpeedInPerMin, kMaxSpeedInPerMin);
            }
        } else if (key == "acceleration_in_per_s2") {
            a.acceleration_in_per_s2 = within(value, k, kMinAccelerationInPerS2, HUGE_VAL);
        } else if (key == "braking_in_per_s2") {
            a.braking_in_per_s2 = within(value, k, kMinAccelerationInPerS2, HUGE_VAL);
        } else if (key == "travel_min_in") {
            a.travel_min_in = finite(value, k);
        } else if (key == "travel_max_in") {
            a.travel_max_in = finite(value, k);
        } else if (key == "soft_limits_in") {
            if (value.is_null()) {
                a.soft_limits = false;
            } else if (value.is_array() && value.size() == 2) {
                a.soft_limits = true;
                a.soft_min_in = finite(value.at(0), k + "[0]");
                a.soft_max_in = finite(value.at(1), k + "[1]");
            } else {
                throw ProfileError(fmt::format("{}: expected [min, max] in inches, or null", k));
            }
        } else if (key == "screw_lead_in_per_rev") {
            a.screw_lead_in_per_rev = positive(value, k);
        } else if (key == "pivot_to_screw_in") {
            a.pivot_to_screw_in = positive(value, k);
        } else if (key == "level_in") {
            a.level_in = finite(value, k);
        } else if (key == "screw_error_in") {
            a.screw_error_in = error_points(value, k);
        } else if (!apply_chain_key(key, value, a, k) && key != "name") {
            throw ProfileError(fmt::format("{}: unknown key", k));
        }
    }
    if (a.travel_min_in >= a.travel_max_in) {
        throw ProfileError(fmt::format("{}: travel_min_in must be below travel_max_in", where));
    }
    if (a.soft_limits && a.soft_min_in >= a.soft_max_in) {
        throw ProfileError(
            fmt::format("{}: soft_limits_in: the minimum must be below the maximum", where));
    }
    // The part's position must grow with the screw's (1 + the error's slope > 0), or a limit
    // could be passed and found again further on: for each table, and for what the measuring
    // chain makes of them together, whichever chain counts and whichever screw cam 160
    // corrects (lead screw 22, or shaft 74 under cam_160_on_instrument_shaft).
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
            throw ProfileError(fmt::format("{}: {}: the error falls faster than the screw "
                                           "advances after {} in",
                                           where, what, *x));
        }
    }
}

json axis_json(const AxisProfile& a) {
    const json errors = points_json(a.screw_error_in);
    json j{{"name", a.name},
           {"speed_in_per_min", a.speed_in_per_min},
           {"acceleration_in_per_s2", a.acceleration_in_per_s2},
           {"braking_in_per_s2", a.braking_in_per_s2},
           {"travel_min_in", a.travel_min_in},
           {"travel_max_in", a.travel_max_in},
           {"soft_limits_in", a.soft_limits ? json{a.soft_min_in, a.soft_max_in} : json(nullptr)},
           {"screw_lead_in_per_rev", a.screw_lead_in_per_rev},
           {"screw_error_in", errors},
           {"pivot_to_screw_in", a.pivot_to_screw_in},
           {"level_in", a.level_in}};
    chain_json(a, j);
    return j;
}

// ---- Readings of the patent and additions (MachineProfile's last group) ----

// "actions": {"tool_change_s": 8, ...}: each a duration.
void apply_actions(ActionTimes& a, const json& j) {
    if (!j.is_object()) {
        throw ProfileError("actions: expected an object of durations in seconds");
    }
    for (const auto& [key, value] : j.items()) {
        const std::string k = "actions." + key;
        double* field = key == "spindle_run_up_s"     ? &a.spindle_run_up_s
                        : key == "spindle_run_down_s" ? &a.spindle_run_down_s
                        : key == "coolant_valve_s"    ? &a.coolant_valve_s
                        : key == "tool_change_s"      ? &a.tool_change_s
                        : key == "dwell_s"            ? &a.dwell_s
                        : key == "lamp_s"             ? &a.lamp_s
                                                      : nullptr;
        if (field == nullptr) {
            throw ProfileError(fmt::format("{}: unknown key", k));
        }
        *field = duration(value, k);
    }
}

// "tools": [{"number": 1, "radius_in": 0.25}, ...]
std::vector<Tool> tools_from(const json& j) {
    if (!j.is_array()) {
        throw ProfileError("tools: expected [{\"number\": N, \"radius_in\": R}, ...]");
    }
    std::vector<Tool> tools;
    for (std::size_t i = 0; i < j.size(); ++i) {
        const std::string k = fmt::format("tools[{}]", i);
        const json& t = j.at(i);
        if (!t.is_object() || !t.contains("number") || !t.contains("radius_in") || t.size() != 2) {
            throw ProfileError(fmt::format("{}: expected {{\"number\": N, \"radius_in\": R}}", k));
        }
        const json& n = t.at("number");
        if (!n.is_number_integer() || n.get<std::int64_t>() < 1 || n.get<std::int64_t>() > 99) {
            throw ProfileError(fmt::format("{}.number: expected a tool number 1..99", k));
        }
        const int number = n.get<int>();
        for (const Tool& other : tools) {
            if (other.number == number) {
                throw ProfileError(fmt::format("{}.number: tool {} is listed twice", k, number));
            }
        }
        tools.push_back(Tool{number, positive(t.at("radius_in"), k + ".radius_in")});
    }
    return tools;
}

bool apply_reading(MachineProfile& p, const std::string& key, const json& value) {
    if (key == "incremental_equality_stops_at_any_speed") {
        p.incremental_equality_stops_at_any_speed = flag(value, key);
    } else if (key == "delay_258_waits_for_equality_to_leave") {
        p.delay_258_waits_for_equality_to_leave = flag(value, key);
    } else if (key == "lamps_only_on_trip") {
        p.lamps_only_on_trip = flag(value, key);
    } else if (key == "cam_160_on_instrument_shaft") {
        p.cam_160_on_instrument_shaft = flag(value, key);
    } else if (key == "refuse_double_punch") {
        p.refuse_double_punch = flag(value, key);
    } else if (key == "condition_cards") {
        p.condition_cards = flag(value, key);
    } else if (key == "actions") {
        apply_actions(p.actions, value);
    } else if (key == "tools") {
        p.tools = tools_from(value);
    } else if (key == "first_tool") {
        if (!value.is_number_integer() || value.get<std::int64_t>() < 1 ||
            value.get<std::int64_t>() > 99) {
            throw ProfileError("first_tool: expected a tool number 1..99");
        }
        p.first_tool = value.get<int>();
    } else {
        return false;
    }
    return true;
}

void put_readings(json& j, const MachineProfile& p) {
    j["incremental_equality_stops_at_any_speed"] = p.incremental_equality_stops_at_any_speed;
    j["delay_258_waits_for_equality_to_leave"] = p.delay_258_waits_for_equality_to_leave;
    j["lamps_only_on_trip"] = p.lamps_only_on_trip;
    j["cam_160_on_instrument_shaft"] = p.cam_160_on_instrument_shaft;
    j["refuse_double_punch"] = p.refuse_double_punch;
    j["condition_cards"] = p.condition_cards;
    j["actions"] = {{"spindle_run_up_s", p.actions.spindle_run_up_s},
                    {"spindle_run_down_s", p.actions.spindle_run_down_s},
                    {"coolant_valve_s", p.actions.coolant_valve_s},
                    {"tool_change_s", p.actions.tool_change_s},
                    {"dwell_s", p.actions.dwell_s},
                    {"lamp_s", p.actions.lamp_s}};
    json tools = json::array();
    for (const Tool& t : p.tools) {
        tools.push_back({{"number", t.number}, {"radius_in", t.radius_in}});
    }
    j["tools"] = tools;
    j["first_tool"] = p.first_tool;
}

// ---- Press synchronisation (EP 0436887; axes/press.hpp, docs/press-sync.md) ----

// The press's numbers: key, field, range (ends open or closed).
struct PressNumber {
    const char* key;
    double PressProfile::*field;
    double least;
    bool least_open;
    double most;
    bool most_open;
};
using profile_values::kNoEnd;
const std::array<PressNumber, 11> kPressNumbers = {{
    {"strokes_per_min", &PressProfile::strokes_per_min, 0.1, false, 120, false},
    {"start_angle_deg", &PressProfile::start_angle_deg, 0, false, 360, true},
    {"stroke_in", &PressProfile::stroke_in, 0, true, kNoEnd, false},
    {"rod_in", &PressProfile::rod_in, 0, true, kNoEnd, false},
    {"pressing_from_deg", &PressProfile::pressing_from_deg, 0, false, 360, false},
    {"pressing_to_deg", &PressProfile::pressing_to_deg, 0, false, 360, false},
    {"pressing_slowdown", &PressProfile::pressing_slowdown, 0, false, 0.9, false},
    {"drift_per_cycle", &PressProfile::drift_per_cycle, -0.1, false, 0.1, false},
    {"variation", &PressProfile::variation, 0, false, 0.5, false},
    {"change_angle_deg", &PressProfile::change_angle_deg, 0, false, 360, true},
    {"change_factor", &PressProfile::change_factor, 0, true, 4, false},
}};
// A stop or change this many revolutions on is beyond any run (and 360 x it stays exact).
constexpr std::int64_t kMostCycles = 1000000000;
// 360 x pulses_per_degree must fit the four decades of position register 14 (<= 9999).
constexpr std::int64_t kMostPulsesPerDegree = 27;

void apply_press_key(PressProfile& p, const std::string& key, const json& value,
                     const std::string& k) {
    for (const PressNumber& n : kPressNumbers) {
        if (key == n.key) {
            p.*n.field = number_in(value, k, n.least, n.least_open, n.most, n.most_open);
            return;
        }
    }
    if (key == "pulses_per_degree") {
        p.pulses_per_degree = static_cast<int>(whole_in(value, k, 1, kMostPulsesPerDegree));
    } else if (key == "reverse") {
        p.reverse = flag(value, k);
    } else if (key == "seed") {
        p.seed = static_cast<unsigned>(whole_in(value, k, 0, 4294967295LL));
    } else if (key == "change_cycle") {
        p.change_cycle = static_cast<int>(whole_in(value, k, 0, kMostCycles));
    } else if (key == "stop_cycle") {
        p.stop_cycle = static_cast<int>(whole_in(value, k, 0, kMostCycles));
    } else if (key == "stop_angle_deg") {
        p.stop_angle_deg = number_in(value, k, 0, false, 360, true);
    } else {
        throw ProfileError(fmt::format("{}: unknown key", k));
    }
}

void apply_press(PressProfile& p, const json& j) {
    if (!j.is_object()) {
        throw ProfileError("press: expected an object (the keys of docs/machine-profile.md)");
    }
    for (const auto& [key, value] : j.items()) {
        apply_press_key(p, key, value, "press." + key);
    }
    if (!(p.rod_in > p.stroke_in / 2)) {
        throw ProfileError(fmt::format("press.rod_in: the connecting rod ({} in) must be longer "
                                       "than the crank throw, stroke_in / 2 ({} in)",
                                       p.rod_in, p.stroke_in / 2));
    }
    if (!(p.pressing_from_deg < p.pressing_to_deg)) {
        throw ProfileError(fmt::format("press.pressing_from_deg: must be below pressing_to_deg "
                                       "({} is not below {})",
                                       p.pressing_from_deg, p.pressing_to_deg));
    }
}

json press_json(const PressProfile& p) {
    json j = json::object();
    for (const PressNumber& n : kPressNumbers) {
        j[n.key] = p.*n.field;
    }
    j["pulses_per_degree"] = p.pulses_per_degree;
    j["reverse"] = p.reverse;
    j["seed"] = p.seed;
    j["change_cycle"] = p.change_cycle;
    j["stop_cycle"] = p.stop_cycle;
    j["stop_angle_deg"] = p.stop_angle_deg;
    return j;
}

// "sync_drive": {"max_in_per_min": 5.4, "acceleration_in_per_s2": 0.5}
void apply_sync_drive(SyncDrive& d, const json& j) {
    if (!j.is_object()) {
        throw ProfileError("sync_drive: expected an object");
    }
    for (const auto& [key, value] : j.items()) {
        const std::string k = "sync_drive." + key;
        if (key == "max_in_per_min") {
            d.max_in_per_min = within(value, k, kMinSpeedInPerMin, kMaxSpeedInPerMin);
        } else if (key == "acceleration_in_per_s2") {
            d.acceleration_in_per_s2 = within(value, k, kMinAccelerationInPerS2, HUGE_VAL);
        } else if (key == "position_gain_per_s") {
            d.position_gain_per_s = within(value, k, 0, 100);
        } else {
            throw ProfileError(fmt::format("{}: unknown key", k));
        }
    }
}

// The longest processor 17 may wait for the crank: an hour (a press of 0.1 strokes a minute
// takes ten minutes a revolution).
constexpr double kMostSyncTimeoutS = 3600;

bool apply_press_sync(MachineProfile& p, const std::string& key, const json& value) {
    if (key == "press_sync") {
        p.press_sync = flag(value, key);
    } else if (key == "press") {
        apply_press(p.press, value);
    } else if (key == "sync_drive") {
        apply_sync_drive(p.sync_drive, value);
    } else if (key == "speed_sample_s") {
        // A reference block from a millisecond (the relays' own time) to a second.
        p.speed_sample_s = within(value, key, 0.001, 1.0);
    } else if (key == "sync_timeout_s") {
        p.sync_timeout_s = within(value, key, 0, kMostSyncTimeoutS);
    } else {
        return false;
    }
    return true;
}

void put_press_sync(json& j, const MachineProfile& p) {
    j["press_sync"] = p.press_sync;
    j["press"] = press_json(p.press);
    j["sync_drive"] = {{"max_in_per_min", p.sync_drive.max_in_per_min},
                       {"acceleration_in_per_s2", p.sync_drive.acceleration_in_per_s2},
                       {"position_gain_per_s", p.sync_drive.position_gain_per_s}};
    j["speed_sample_s"] = p.speed_sample_s;
    j["sync_timeout_s"] = p.sync_timeout_s;
}

} // namespace

MachineProfile profile_from_json(const std::string& json_text, MachineProfile p) {
    json j;
    try {
        j = json::parse(json_text);
    } catch (const json::parse_error& e) {
        throw ProfileError(fmt::format("not valid JSON at byte {}", e.byte));
    } catch (const json::out_of_range&) { // 1e400: valid JSON, but no double holds it
        throw ProfileError("a number too large to read (over 1.8e308)");
    }
    if (!j.is_object()) {
        throw ProfileError("the profile must be a JSON object");
    }
    // "base": a built-in profile to start from, whatever the caller passed (applied first).
    if (j.contains("base")) {
        const json& base = j.at("base");
        auto builtin = base.is_string() ? builtin_profile(base.get<std::string>()) : std::nullopt;
        if (!builtin) {
            throw ProfileError(fmt::format("base: expected \"parsons-1952\", \"parsons-safe\" or "
                                           "\"parsons-extended\", not {}",
                                           base.dump()));
        }
        p = *builtin;
    }
    for (const auto& [key, value] : j.items()) {
        if (key == "base") {
            continue;
        }
        if (key == "name") {
            if (!value.is_string()) {
                throw ProfileError("name: expected a string");
            }
            p.name = value.get<std::string>();
        } else if (key == "axes") {
            if (!value.is_object()) {
                throw ProfileError("axes: expected an object keyed by axis name");
            }
            for (const auto& [axis, settings] : value.items()) {
                // An init-capture: clang before 16 cannot capture a structured binding.
                auto it =
                    std::find_if(p.axes.begin(), p.axes.end(),
                                 [&name = axis](const AxisProfile& a) { return a.name == name; });
                if (it == p.axes.end()) {
                    throw ProfileError(fmt::format("axes.{}: unknown axis", axis));
                }
                apply_axis(settings, *it, "axes." + axis);
            }
        } else if (key == "reader_cycle_s") {
            p.reader_cycle_s = duration(value, key);
        } else if (key == "first_bank_s") {
            p.first_bank_s = duration(value, key);
        } else if (key == "second_bank_s") {
            p.second_bank_s = duration(value, key);
        } else if (key == "feed_gap_s") {
            p.feed_gap_s = duration(value, key);
        } else if (key == "ribbon_feed") {
            if (!value.is_boolean()) {
                throw ProfileError("ribbon_feed: expected true or false");
            }
            p.ribbon_feed = value.get<bool>();
        } else if (key == "relay_operate_s") {
            p.relay_operate_s = duration(value, key);
        } else if (key == "relay_release_s") {
            p.relay_release_s = duration(value, key);
        } else if (key == "stepping_switch_step_s") {
            p.stepping_switch_step_s = duration(value, key);
        } else if (key == "max_stepping_rate_per_s") {
            p.max_stepping_rate_per_s = positive(value, key);
        } else if (key == "delay_258_s") {
            p.delay_258_s = duration(value, key);
        } else if (key == "sequence_shaft_step_s") {
            p.sequence_shaft_step_s = duration(value, key);
        } else if (key == "count_hundredths_at_speed_1") {
            if (!value.is_boolean()) {
                throw ProfileError("count_hundredths_at_speed_1: expected true or false");
            }
            p.count_hundredths_at_speed_1 = value.get<bool>();
        } else if (key == "measuring_chain") {
            const std::string chain = value.is_string() ? value.get<std::string>() : "";
            if (chain == "instrument_shaft_74") {
                p.measuring_chain = MeasuringChain::instrument_shaft_74;
            } else if (chain == "screw_turns") {
                p.measuring_chain = MeasuringChain::screw_turns;
            } else {
                throw ProfileError("measuring_chain: expected \"instrument_shaft_74\" (the "
                                   "patent) or \"screw_turns\" (a departure)");
            }
        } else if (key == "separate_registers") {
            if (!value.is_boolean()) {
                throw ProfileError("separate_registers: expected true or false");
            }
            p.separate_registers = value.get<bool>();
        } else if (apply_reading(p, key, value) || apply_press_sync(p, key, value) ||
                   apply_spindle_sync(p, key, value)) {
            // an interpretation or an addition (above)
        } else {
            throw ProfileError(fmt::format("{}: unknown key", key));
        }
    }
    if (!(p.first_bank_s + p.relay_operate_s < p.second_bank_s &&
          p.second_bank_s + 3 * p.stepping_switch_step_s <= p.reader_cycle_s)) {
        throw ProfileError("first_bank_s + relay_operate_s < second_bank_s and second_bank_s + 3 "
                           "stepping_switch_step_s <= reader_cycle_s must hold (the two brush "
                           "banks sense the card, its relays pick and the speed switches step "
                           "within one card cycle)");
    }
    if (!(p.feed_gap_s < p.first_bank_s)) {
        throw ProfileError("feed_gap_s < first_bank_s must hold (the gap between two cards "
                           "passes the brushes before the first bank senses the card)");
    }
    if (p.press_sync) {
        // Position register 14 and speed register 11 are stepping switches: the press's
        // pulses, at its fastest, must come no faster than they step.
        const PressProfile& press = p.press;
        const double fastest = press.strokes_per_min * 6.0 * press.pulses_per_degree *
                               (1 + press.variation) * std::max(1.0, press.change_factor);
        if (fastest > p.max_stepping_rate_per_s) {
            throw ProfileError(fmt::format(
                "press.strokes_per_min: {} strokes a minute at {} pulses a degree give up to "
                "{:.0f} detector pulses a second (with variation and change_factor), faster than "
                "the stepping switches of registers 14 and 11 follow (max_stepping_rate_per_s "
                "{}): at most {:.2f} strokes a minute",
                press.strokes_per_min, press.pulses_per_degree, fastest, p.max_stepping_rate_per_s,
                press.strokes_per_min * p.max_stepping_rate_per_s / fastest));
        }
    }
    check_spindle_sync(p);
    return p;
}

std::string profile_to_json(const MachineProfile& p) {
    json axes = json::object();
    for (const AxisProfile& a : p.axes) {
        axes[a.name] = axis_json(a);
    }
    json j{{"name", p.name},
           {"reader_cycle_s", p.reader_cycle_s},
           {"first_bank_s", p.first_bank_s},
           {"second_bank_s", p.second_bank_s},
           {"feed_gap_s", p.feed_gap_s},
           {"ribbon_feed", p.ribbon_feed},
           {"relay_operate_s", p.relay_operate_s},
           {"relay_release_s", p.relay_release_s},
           {"stepping_switch_step_s", p.stepping_switch_step_s},
           {"max_stepping_rate_per_s", p.max_stepping_rate_per_s},
           {"delay_258_s", p.delay_258_s},
           {"sequence_shaft_step_s", p.sequence_shaft_step_s},
           {"separate_registers", p.separate_registers},
           {"count_hundredths_at_speed_1", p.count_hundredths_at_speed_1},
           {"measuring_chain", p.measuring_chain == MeasuringChain::screw_turns
                                   ? "screw_turns"
                                   : "instrument_shaft_74"},
           {"axes", axes}};
    put_readings(j, p);
    put_press_sync(j, p);
    put_spindle_sync(j, p);
    return json_text(j, 2) + "\n";
}

} // namespace parsons::axes
