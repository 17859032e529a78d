#include "axes/contour_json.hpp"

#include "axes/profile_json.hpp"
#include "axes/profile_values.hpp"

#include <fmt/format.h>

#include <array>

namespace parsons::axes {
namespace {

using nlohmann::json;
using profile_values::flag;
using profile_values::number;
using profile_values::whole;

struct ContourNumber {
    const char* key;
    double ContourProfile::*field;
};
const std::array<ContourNumber, 5> kContourNumbers = {{
    {"pull_in_steps_per_s", &ContourProfile::pull_in_steps_per_s},
    {"acceleration_steps_per_s2", &ContourProfile::acceleration_steps_per_s2},
    {"ramp_steps_per_s2", &ContourProfile::ramp_steps_per_s2},
    {"max_rate_change_steps_per_s", &ContourProfile::max_rate_change_steps_per_s},
    {"minimum_in_per_min", &ContourProfile::minimum_in_per_min},
}};

void apply_contour_key(ContourProfile& c, const std::string& key, const json& value,
                       const std::string& k) {
    for (const ContourNumber& n : kContourNumbers) {
        if (key == n.key) {
            c.*n.field = number(value, k, k);
            return;
        }
    }
    if (key == "steps_per_in") {
        c.steps_per_in = static_cast<int>(whole(value, k, k));
    } else if (key == "short_segment_rule") {
        c.short_segment_rule = flag(value, k);
    } else if (key == "junctions") {
        const std::string policy = value.is_string() ? value.get<std::string>() : "";
        if (policy == "rule") {
            c.junctions = JunctionPolicy::rule;
        } else if (policy == "pass") {
            c.junctions = JunctionPolicy::pass;
        } else if (policy == "minimum") {
            c.junctions = JunctionPolicy::minimum;
        } else {
            throw ProfileError(fmt::format("{}: expected \"rule\" (claim 1: pass unless the "
                                           "motors' speeds differ by more than the maximum), "
                                           "\"pass\" (every junction at the nominal speed) or "
                                           "\"minimum\" (every junction slowed), not {}",
                                           k, value.dump()));
        }
    } else {
        throw ProfileError(fmt::format("{}: unknown key", k));
    }
}

} // namespace

const char* junction_policy_name(JunctionPolicy policy) {
    switch (policy) {
    case JunctionPolicy::pass:
        return "pass";
    case JunctionPolicy::minimum:
        return "minimum";
    case JunctionPolicy::rule:
        break;
    }
    return "rule";
}

bool apply_contouring(MachineProfile& p, const std::string& key, const json& value) {
    if (key == "contouring") {
        p.contouring = flag(value, key);
    } else if (key == "contour") {
        if (!value.is_object()) {
            throw ProfileError("contour: expected an object (the keys of docs/machine-profile.md)");
        }
        for (const auto& [k, v] : value.items()) {
            apply_contour_key(p.contour, k, v, "contour." + k);
        }
    } else {
        return false;
    }
    return true;
}

void put_contouring(json& j, const MachineProfile& p) {
    // A profile without contouring whose contour keys are the defaults names neither: its JSON
    // stays as it was before the attachment came (reading it back gives the same profile).
    const ContourProfile d;
    const ContourProfile& c0 = p.contour;
    const bool defaults =
        c0.steps_per_in == d.steps_per_in && c0.pull_in_steps_per_s == d.pull_in_steps_per_s &&
        c0.acceleration_steps_per_s2 == d.acceleration_steps_per_s2 &&
        c0.ramp_steps_per_s2 == d.ramp_steps_per_s2 &&
        c0.max_rate_change_steps_per_s == d.max_rate_change_steps_per_s &&
        c0.minimum_in_per_min == d.minimum_in_per_min && c0.junctions == d.junctions &&
        c0.short_segment_rule == d.short_segment_rule;
    if (!p.contouring && defaults) {
        return;
    }
    j["contouring"] = p.contouring;
    json c = json::object();
    c["steps_per_in"] = p.contour.steps_per_in;
    for (const ContourNumber& n : kContourNumbers) {
        c[n.key] = p.contour.*n.field;
    }
    c["junctions"] = junction_policy_name(p.contour.junctions);
    c["short_segment_rule"] = p.contour.short_segment_rule;
    j["contour"] = c;
}

} // namespace parsons::axes
