// Spindle synchronisation's profile keys (axes/spindle_json.hpp; docs/machine-profile.md,
// "Spindle synchronisation"). Each number's range, and why, is in axes/profile_keys.cpp
// ("spindle.KEY"); the relations (the encoder against the stepping switches, the sample against
// half a revolution, the first tool among the heads) in axes/profile_relations.cpp.
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
using profile_values::number;
using profile_values::whole;

// The spindle's numbers: key and field (their ranges: "spindle.KEY" in axes/profile_keys.cpp).
struct SpindleNumber {
    const char* key;
    double SpindleSyncProfile::*field;
};
const std::array<SpindleNumber, 10> kSpindleNumbers = {{
    {"max_rpm", &SpindleSyncProfile::max_rpm},
    {"run_up_rpm_per_s", &SpindleSyncProfile::run_up_rpm_per_s},
    {"run_down_rpm_per_s", &SpindleSyncProfile::run_down_rpm_per_s},
    {"sample_s", &SpindleSyncProfile::sample_s},
    {"feed_gain_per_s", &SpindleSyncProfile::feed_gain_per_s},
    {"change_factor", &SpindleSyncProfile::change_factor},
    {"pc_scan_s", &SpindleSyncProfile::pc_scan_s},
    {"head_change_s", &SpindleSyncProfile::head_change_s},
    {"transfer_timeout_s", &SpindleSyncProfile::transfer_timeout_s},
    {"chamfer_revs", &SpindleSyncProfile::chamfer_revs},
}};
constexpr std::size_t kMostHeads = 20;

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
            head.tool = static_cast<int>(whole(value, "spindle.heads[]." + key, hk));
            tool = true;
        } else if (key == "ratio") {
            head.ratio = number(value, "spindle.heads[]." + key, hk);
            ratio = true;
        } else if (key == "pitch_in") {
            head.pitch_in = number(value, "spindle.heads[]." + key, hk);
        } else if (key == "radius_in") {
            head.radius_in = number(value, "spindle.heads[]." + key, hk);
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
            s.*n.field = number(value, k, k);
            return;
        }
    }
    if (key == "encoder_pulses_per_rev") {
        s.encoder_pulses_per_rev = static_cast<int>(whole(value, k, k));
    } else if (key == "change_at_s") {
        s.change_at_s = value.is_null() ? std::nullopt : std::optional<double>(number(value, k, k));
    } else if (key == "heads") {
        s.heads = heads_from(value);
    } else if (key == "first_tool") {
        s.first_tool = static_cast<int>(whole(value, k, k));
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

void put_spindle_sync(json& j, const MachineProfile& p) {
    j["spindle_sync"] = p.spindle_sync;
    j["spindle"] = spindle_json(p.spindle);
}

} // namespace parsons::axes
