// Spindle synchronisation's profile keys (axes/spindle_json.hpp; docs/machine-profile.md,
// "Spindle synchronisation"). The ranges, and why:
//   max_rpm 1..9999: a tap card's speed field has four digits.
//   run_up_rpm_per_s, run_down_rpm_per_s above 0: any motor changes speed at some rate.
//   encoder_pulses_per_rev 4..9999: phases A and B in quadrature give four edges for each line
//     of the disc at least; interface 33's counter holds a revolution in four decades. Not
//     bound to a multiple of 4: the Gray code of the count needs none.
//   sample_s 0.001..1, pc_scan_s 0.001..1: a millisecond to a second, the NC's and a PC's
//     cycles; feed_gain_per_s 0..1000 (0: no position correction).
//   change_at_s null or 0..1e9 s (machine time still resolves a microsecond), change_factor
//     0.1..2: a sag or a surge of the supply, not a stop.
//   heads: 1..20, tools 1..99 each once, ratio above 0 and at most 10, a tap's pitch above 0
//     and below 1 in, a cutter's radius above 0 and below 2 in (exactly one of the two).
//   head_change_s 0..600, transfer_timeout_s above 0 and at most 3600, chamfer_revs 0..20.
#include "axes/spindle_json.hpp"

#include "axes/profile_json.hpp"
#include "axes/profile_values.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace parsons::axes {
namespace {

using nlohmann::json;
using profile_values::flag;
using profile_values::number_in;
using profile_values::whole_in;

using profile_values::kNoEnd;

// The spindle's numbers: key, field, range (ends open or closed).
struct SpindleNumber {
    const char* key;
    double SpindleSyncProfile::*field;
    double least;
    bool least_open;
    double most;
    bool most_open;
};
const std::array<SpindleNumber, 10> kSpindleNumbers = {{
    {"max_rpm", &SpindleSyncProfile::max_rpm, 1, false, 9999, false},
    {"run_up_rpm_per_s", &SpindleSyncProfile::run_up_rpm_per_s, 0, true, kNoEnd, false},
    {"run_down_rpm_per_s", &SpindleSyncProfile::run_down_rpm_per_s, 0, true, kNoEnd, false},
    {"sample_s", &SpindleSyncProfile::sample_s, 0.001, false, 1, false},
    {"feed_gain_per_s", &SpindleSyncProfile::feed_gain_per_s, 0, false, 1000, false},
    {"change_factor", &SpindleSyncProfile::change_factor, 0.1, false, 2, false},
    {"pc_scan_s", &SpindleSyncProfile::pc_scan_s, 0.001, false, 1, false},
    {"head_change_s", &SpindleSyncProfile::head_change_s, 0, false, 600, false},
    {"transfer_timeout_s", &SpindleSyncProfile::transfer_timeout_s, 0, true, 3600, false},
    {"chamfer_revs", &SpindleSyncProfile::chamfer_revs, 0, false, 20, false},
}};
constexpr std::int64_t kLeastPulsesPerRev = 4;
constexpr std::int64_t kMostPulsesPerRev = 9999;
constexpr double kLatestChangeS = 1e9;
constexpr std::size_t kMostHeads = 20;
constexpr double kMostRatio = 10;
constexpr double kMostPitchIn = 1;
constexpr double kMostRadiusIn = 2;

// heads[i]: {"tool": T, "ratio": A, "pitch_in": P} or {..., "radius_in": R}.
SpindleHead head_from(const json& h, const std::string& k) {
    if (!h.is_object()) {
        throw ProfileError(fmt::format("{}: expected {{\"tool\": T, \"ratio\": A, \"pitch_in\": P "
                                       "or \"radius_in\": R}}",
                                       k));
    }
    SpindleHead head;
    bool tool = false;
    bool ratio = false;
    for (const auto& [key, value] : h.items()) {
        const std::string hk = k + "." + key;
        if (key == "tool") {
            head.tool = static_cast<int>(whole_in(value, hk, 1, 99));
            tool = true;
        } else if (key == "ratio") {
            head.ratio = number_in(value, hk, 0, true, kMostRatio, false);
            ratio = true;
        } else if (key == "pitch_in") {
            head.pitch_in = number_in(value, hk, 0, true, kMostPitchIn, true);
        } else if (key == "radius_in") {
            head.radius_in = number_in(value, hk, 0, true, kMostRadiusIn, true);
        } else {
            throw ProfileError(fmt::format("{}: unknown key", hk));
        }
    }
    if (!tool || !ratio) {
        throw ProfileError(fmt::format("{}: needs \"tool\" and \"ratio\"", k));
    }
    if (head.pitch_in.has_value() == head.radius_in.has_value()) {
        throw ProfileError(fmt::format(
            "{}: needs exactly one of \"pitch_in\" (a tap) and \"radius_in\" (a cutter)", k));
    }
    return head;
}

std::vector<SpindleHead> heads_from(const json& j) {
    if (!j.is_array() || j.empty() || j.size() > kMostHeads) {
        throw ProfileError(fmt::format("spindle.heads: expected 1 to {} heads [{{\"tool\": T, "
                                       "\"ratio\": A, \"pitch_in\": P}}, ...]",
                                       kMostHeads));
    }
    std::vector<SpindleHead> heads;
    for (std::size_t i = 0; i < j.size(); ++i) {
        const std::string k = fmt::format("spindle.heads[{}]", i);
        const SpindleHead head = head_from(j.at(i), k);
        for (const SpindleHead& other : heads) {
            if (other.tool == head.tool) {
                throw ProfileError(fmt::format("{}.tool: tool {} is on two heads", k, head.tool));
            }
        }
        heads.push_back(head);
    }
    return heads;
}

void apply_spindle_key(SpindleSyncProfile& s, const std::string& key, const json& value,
                       const std::string& k) {
    for (const SpindleNumber& n : kSpindleNumbers) {
        if (key == n.key) {
            s.*n.field = number_in(value, k, n.least, n.least_open, n.most, n.most_open);
            return;
        }
    }
    if (key == "encoder_pulses_per_rev") {
        s.encoder_pulses_per_rev =
            static_cast<int>(whole_in(value, k, kLeastPulsesPerRev, kMostPulsesPerRev));
    } else if (key == "change_at_s") {
        s.change_at_s =
            value.is_null()
                ? std::nullopt
                : std::optional<double>(number_in(value, k, 0, false, kLatestChangeS, false));
    } else if (key == "heads") {
        s.heads = heads_from(value);
    } else if (key == "first_tool") {
        s.first_tool = static_cast<int>(whole_in(value, k, 1, 99));
    } else if (key == "ratio_source") {
        const std::string source = value.is_string() ? value.get<std::string>() : "";
        if (source == "transferred") {
            s.ratio_source = RatioSource::transferred;
        } else if (source == "stored") {
            s.ratio_source = RatioSource::stored;
        } else {
            throw ProfileError(fmt::format("{}: expected \"transferred\" (PC 130 sends it, the "
                                           "first embodiment) or \"stored\" (memory 12a holds "
                                           "every tool's, the second), not {}",
                                           k, value.dump()));
        }
    } else {
        throw ProfileError(fmt::format("{}: unknown key", k));
    }
}

void apply_spindle(SpindleSyncProfile& s, const json& j) {
    if (!j.is_object()) {
        throw ProfileError("spindle: expected an object (the keys of docs/machine-profile.md)");
    }
    for (const auto& [key, value] : j.items()) {
        apply_spindle_key(s, key, value, "spindle." + key);
    }
    if (s.head(s.first_tool) == nullptr) {
        std::string tools;
        for (const SpindleHead& h : s.heads) {
            tools += fmt::format("{}{}", tools.empty() ? "" : ", ", h.tool);
        }
        throw ProfileError(
            fmt::format("spindle.first_tool: tool {} is on no head (the heads hold tools {})",
                        s.first_tool, tools));
    }
}

json head_json(const SpindleHead& h) {
    json j{{"tool", h.tool}, {"ratio", h.ratio}};
    if (h.pitch_in) {
        j["pitch_in"] = *h.pitch_in;
    }
    if (h.radius_in) {
        j["radius_in"] = *h.radius_in;
    }
    return j;
}

json spindle_json(const SpindleSyncProfile& s) {
    json j = json::object();
    for (const SpindleNumber& n : kSpindleNumbers) {
        j[n.key] = s.*n.field;
    }
    j["encoder_pulses_per_rev"] = s.encoder_pulses_per_rev;
    j["change_at_s"] = s.change_at_s ? json(*s.change_at_s) : json(nullptr);
    json heads = json::array();
    for (const SpindleHead& h : s.heads) {
        heads.push_back(head_json(h));
    }
    j["heads"] = heads;
    j["first_tool"] = s.first_tool;
    j["ratio_source"] = s.ratio_source == RatioSource::stored ? "stored" : "transferred";
    return j;
}

} // namespace

bool apply_spindle_sync(MachineProfile& p, const std::string& key, const json& value) {
    if (key == "spindle_sync") {
        p.spindle_sync = flag(value, key);
    } else if (key == "spindle") {
        apply_spindle(p.spindle, value);
    } else {
        return false;
    }
    return true;
}

void check_spindle_sync(const MachineProfile& p) {
    if (!p.spindle_sync) {
        return;
    }
    // Interface 33's counter is stepping switches: encoder 32's edges at the motor's fastest
    // speed (max_rpm, times a lasting change above 1, as the press's check counts its own) must
    // come no faster than they step.
    const SpindleSyncProfile& s = p.spindle;
    const double factor = s.change_at_s ? std::max(1.0, s.change_factor) : 1.0;
    const double edges_per_s = s.max_rpm * factor * s.encoder_pulses_per_rev / 60.0;
    if (edges_per_s > p.max_stepping_rate_per_s) {
        const double most = p.max_stepping_rate_per_s * 60.0 / s.encoder_pulses_per_rev / factor;
        throw ProfileError(fmt::format(
            "spindle.max_rpm: {} rev/min{} at {} edges a revolution give {:.1f} encoder pulses "
            "a second, faster than the stepping switches of spindle encoder interface 33 follow "
            "(max_stepping_rate_per_s {}): at most {:.2f} rev/min",
            s.max_rpm, factor > 1 ? fmt::format(" (x change_factor {:g})", factor) : "",
            s.encoder_pulses_per_rev, edges_per_s, p.max_stepping_rate_per_s,
            std::floor(most * 100) / 100));
    }
    // The NC tells the motor's sense from two readings of interface 33's counter a sample apart:
    // less than half a revolution between them, at the fastest.
    const double turns = s.max_rpm * factor / 60.0 * s.sample_s;
    if (turns >= 0.5) {
        throw ProfileError(fmt::format(
            "spindle.sample_s: {:g} s at {} rev/min{} turns motor 27 {:.3f} of a revolution "
            "between two samples of spindle encoder interface 33; from half a revolution on its "
            "counter cannot tell the sense: below {:.4f} s",
            s.sample_s, s.max_rpm, factor > 1 ? fmt::format(" (x change_factor {:g})", factor) : "",
            turns, 0.5 * 60.0 / (s.max_rpm * factor)));
    }
}

void put_spindle_sync(json& j, const MachineProfile& p) {
    j["spindle_sync"] = p.spindle_sync;
    j["spindle"] = spindle_json(p.spindle);
}

} // namespace parsons::axes
