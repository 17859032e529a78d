#include "axes/profile_json.hpp"

#include "axes/contour_json.hpp"
#include "axes/profile_values.hpp"

#include "axes/json_text.hpp"
#include "axes/profile_relations.hpp"
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
using profile_values::number;
using profile_values::whole;

// [[position, error], ...] of the table `table` ("lead_error_in") of an axis, at `k`.
ErrorPoints error_points(const json& value, const std::string& table, const std::string& k) {
    if (!value.is_array()) {
        throw ProfileError(fmt::format("{}: expected [[position, error], ...]", k));
    }
    ErrorPoints points;
    for (std::size_t i = 0; i < value.size(); ++i) {
        const json& pair = value.at(i);
        if (!pair.is_array() || pair.size() != 2) {
            throw ProfileError(fmt::format("{}: expected [[position, error], ...]", k));
        }
        const std::string at = fmt::format("{}[{}]", k, i);
        const double x = number(pair.at(0), "axes.*." + table + "[][0]", at + "[0]");
        const double e = number(pair.at(1), "axes.*." + table + "[][1]", at + "[1]");
        if (!points.empty() && x <= points.back().first) {
            throw ProfileError(fmt::format("{}: positions must increase", k));
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
        a.lead_error_in = error_points(value, key, k);
    } else if (key == "instrument_error_in") {
        a.instrument_error_in = error_points(value, key, k);
    } else if (key == "cam_160_in") {
        a.cam_160_in = error_points(value, key, k);
    } else if (key == "backlash_in") {
        a.backlash_in = number(value, "axes.*.backlash_in", k);
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
        const std::string row = "axes.*." + key; // the key's row in axes/profile_keys.cpp
        if (key == "speed_in_per_min") {
            if (!value.is_array() || value.size() != 3) {
                throw ProfileError(fmt::format("{}: expected three speeds [1, 2, 3]", k));
            }
            for (std::size_t i = 0; i < 3; ++i) {
                a.speed_in_per_min.at(i) =
                    number(value.at(i), row + "[]", fmt::format("{}[{}]", k, i));
            }
        } else if (key == "acceleration_in_per_s2") {
            a.acceleration_in_per_s2 = number(value, row, k);
        } else if (key == "braking_in_per_s2") {
            a.braking_in_per_s2 = number(value, row, k);
        } else if (key == "travel_min_in") {
            a.travel_min_in = number(value, row, k);
        } else if (key == "travel_max_in") {
            a.travel_max_in = number(value, row, k);
        } else if (key == "soft_limits_in") {
            if (value.is_null()) {
                a.soft_limits = false;
            } else if (value.is_array() && value.size() == 2) {
                a.soft_limits = true;
                a.soft_min_in = number(value.at(0), row + "[0]", k + "[0]");
                a.soft_max_in = number(value.at(1), row + "[1]", k + "[1]");
            } else {
                throw ProfileError(fmt::format("{}: expected [min, max] in inches, or null", k));
            }
        } else if (key == "screw_lead_in_per_rev") {
            a.screw_lead_in_per_rev = number(value, row, k);
        } else if (key == "pivot_to_screw_in") {
            a.pivot_to_screw_in = number(value, row, k);
        } else if (key == "level_in") {
            a.level_in = number(value, row, k);
        } else if (key == "screw_error_in") {
            a.screw_error_in = error_points(value, key, k);
        } else if (!apply_chain_key(key, value, a, k) && key != "name") {
            throw ProfileError(fmt::format("{}: unknown key", k));
        }
    }
    // The relations between an axis's keys are checked with the others, once every key is
    // read (axes/profile_relations.cpp).
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
        *field = number(value, k, k);
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
        const int number = static_cast<int>(whole(t.at("number"), "tools[].number", k + ".number"));
        for (const Tool& other : tools) {
            if (other.number == number) {
                throw ProfileError(fmt::format("{}.number: tool {} is listed twice", k, number));
            }
        }
        tools.push_back(Tool{number, profile_values::number(t.at("radius_in"), "tools[].radius_in",
                                                            k + ".radius_in")});
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
        p.first_tool = static_cast<int>(whole(value, key, key));
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

// The press's numbers: key and field (their ranges: "press.KEY" in axes/profile_keys.cpp).
struct PressNumber {
    const char* key;
    double PressProfile::*field;
};
const std::array<PressNumber, 12> kPressNumbers = {{
    {"strokes_per_min", &PressProfile::strokes_per_min},
    {"start_angle_deg", &PressProfile::start_angle_deg},
    {"stroke_in", &PressProfile::stroke_in},
    {"rod_in", &PressProfile::rod_in},
    {"pressing_from_deg", &PressProfile::pressing_from_deg},
    {"pressing_to_deg", &PressProfile::pressing_to_deg},
    {"pressing_slowdown", &PressProfile::pressing_slowdown},
    {"drift_per_cycle", &PressProfile::drift_per_cycle},
    {"variation", &PressProfile::variation},
    {"change_angle_deg", &PressProfile::change_angle_deg},
    {"change_factor", &PressProfile::change_factor},
    {"feeder_hold_lag_in", &PressProfile::feeder_hold_lag_in},
}};

void apply_press_key(PressProfile& p, const std::string& key, const json& value,
                     const std::string& k) {
    for (const PressNumber& n : kPressNumbers) {
        if (key == n.key) {
            p.*n.field = number(value, k, k);
            return;
        }
    }
    if (key == "pulses_per_degree") {
        p.pulses_per_degree = static_cast<int>(whole(value, k, k));
    } else if (key == "reverse") {
        p.reverse = flag(value, k);
    } else if (key == "seed") {
        p.seed = static_cast<unsigned>(whole(value, k, k));
    } else if (key == "change_cycle") {
        p.change_cycle = static_cast<int>(whole(value, k, k));
    } else if (key == "stop_cycle") {
        p.stop_cycle = static_cast<int>(whole(value, k, k));
    } else if (key == "stop_angle_deg") {
        p.stop_angle_deg = number(value, k, k);
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
            d.max_in_per_min = number(value, k, k);
        } else if (key == "acceleration_in_per_s2") {
            d.acceleration_in_per_s2 = number(value, k, k);
        } else if (key == "position_gain_per_s") {
            d.position_gain_per_s = number(value, k, k);
        } else {
            throw ProfileError(fmt::format("{}: unknown key", k));
        }
    }
}

bool apply_press_sync(MachineProfile& p, const std::string& key, const json& value) {
    if (key == "press_sync") {
        p.press_sync = flag(value, key);
    } else if (key == "press") {
        apply_press(p.press, value);
    } else if (key == "sync_drive") {
        apply_sync_drive(p.sync_drive, value);
    } else if (key == "speed_sample_s") {
        p.speed_sample_s = number(value, key, key);
    } else if (key == "sync_timeout_s") {
        p.sync_timeout_s = number(value, key, key);
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
            p.reader_cycle_s = number(value, key, key);
        } else if (key == "first_bank_s") {
            p.first_bank_s = number(value, key, key);
        } else if (key == "second_bank_s") {
            p.second_bank_s = number(value, key, key);
        } else if (key == "feed_gap_s") {
            p.feed_gap_s = number(value, key, key);
        } else if (key == "ribbon_feed") {
            if (!value.is_boolean()) {
                throw ProfileError("ribbon_feed: expected true or false");
            }
            p.ribbon_feed = value.get<bool>();
        } else if (key == "relay_operate_s") {
            p.relay_operate_s = number(value, key, key);
        } else if (key == "relay_release_s") {
            p.relay_release_s = number(value, key, key);
        } else if (key == "stepping_switch_step_s") {
            p.stepping_switch_step_s = number(value, key, key);
        } else if (key == "max_stepping_rate_per_s") {
            p.max_stepping_rate_per_s = number(value, key, key);
        } else if (key == "delay_258_s") {
            p.delay_258_s = number(value, key, key);
        } else if (key == "sequence_shaft_step_s") {
            p.sequence_shaft_step_s = number(value, key, key);
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
                   apply_spindle_sync(p, key, value) || apply_contouring(p, key, value)) {
            // an interpretation or an addition (above)
        } else {
            throw ProfileError(fmt::format("{}: unknown key", key));
        }
    }
    check_profile_relations(p);
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
    put_contouring(j, p);
    return json_text(j, 2) + "\n";
}

} // namespace parsons::axes
