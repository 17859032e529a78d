#include "outputs/report/contouring_report.hpp"

#include "outputs/report/figures.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>

namespace parsons::cli {

using relaylogic::JunctionKind;

namespace {

const char* kind_key(JunctionKind k) {
    switch (k) {
    case JunctionKind::passed:
        return "passed";
    case JunctionKind::slowed_rate:
        return "slowed_rate";
    case JunctionKind::slowed_short:
        return "slowed_short";
    case JunctionKind::slowed_always:
        return "slowed_always";
    case JunctionKind::stopped:
        return "stopped";
    case JunctionKind::none:
        break;
    }
    return "none";
}

std::int64_t total(const std::array<std::int64_t, 3>& a) {
    return a[0] + a[1] + a[2];
}

} // namespace

nlohmann::json contouring_json(const relaylogic::ContouringResult& c) {
    using nlohmann::json;
    json junctions = json::array();
    for (const relaylogic::JunctionRecord& j : c.junctions) {
        junctions.push_back(
            json{{"first", j.first},
                 {"second", j.second},
                 {"decision", kind_key(j.kind)},
                 {"decided_seconds", j.decided_s < 0 ? json(nullptr) : json(time_s(j.decided_s))},
                 {"decided_along_in", decimals(j.decided_at_in, 4)},
                 {"rate_difference_steps_per_s", decimals(j.difference, 1)},
                 {"reached_seconds", time_s(j.at_s)},
                 {"speed_in_per_min", decimals(j.speed_in_per_min, 3)},
                 {"lost_steps", json{{"X", j.lost[0]}, {"Y", j.lost[1]}, {"Z", j.lost[2]}}}});
    }
    std::array<int, 6> count{};
    for (const relaylogic::JunctionRecord& j : c.junctions) {
        ++count.at(static_cast<std::size_t>(j.kind));
    }
    return json{{"junctions_policy", c.policy},
                {"segments", c.segments},
                {"decisions", json{{"passed", count[1]},
                                   {"slowed", count[2] + count[3] + count[4]},
                                   {"slowed_rate", count[2]},
                                   {"slowed_short", count[3]},
                                   {"slowed_always", count[4]},
                                   {"stopped", count[5]}}},
                {"lost_steps_total", total(c.lost)},
                {"junctions", junctions},
                {"lost_steps", json{{"X", c.lost[0]}, {"Y", c.lost[1]}, {"Z", c.lost[2]}}},
                {"offset_in", json{{"X", fine_length(c.offset_in[0])},
                                   {"Y", fine_length(c.offset_in[1])},
                                   {"Z", fine_length(c.offset_in[2])}}},
                {"largest_offset_in", fine_length(c.largest_offset_in)},
                {"motion_seconds", time_s(c.motion_s)},
                {"position_in", json{{"X", decimals(c.position_in[0], 4)},
                                     {"Y", decimals(c.position_in[1], 4)},
                                     {"Z", decimals(c.position_in[2], 4)}}}};
}

std::vector<std::string> contouring_lines(const relaylogic::ContouringResult& c) {
    std::array<int, 6> count{};
    for (const relaylogic::JunctionRecord& j : c.junctions) {
        ++count.at(static_cast<std::size_t>(j.kind));
    }
    const int slowed = count[2] + count[3] + count[4];
    std::vector<std::string> lines;
    lines.push_back(fmt::format(
        "  contouring     {} segment{} in {:.3f} s of motion (junctions \"{}\"): {} junction{} "
        "passed at speed, {} slowed ({} for a motor's rate change, {} before a short segment, {} "
        "as every junction), {} stopped for a card not yet read",
        c.segments, c.segments == 1 ? "" : "s", c.motion_s, c.policy, count[1],
        count[1] == 1 ? "" : "s", slowed, count[2], count[3], count[4], count[5]));
    lines.push_back(fmt::format(
        "  stepper axes   {} step{} lost (X {}, Y {}, Z {}): the path as cut left the programmed "
        "path by {:.4f} in at most and ends {:.4f} in from it",
        total(c.lost), total(c.lost) == 1 ? "" : "s", c.lost[0], c.lost[1], c.lost[2],
        c.largest_offset_in,
        std::sqrt(c.offset_in[0] * c.offset_in[0] + c.offset_in[1] * c.offset_in[1] +
                  c.offset_in[2] * c.offset_in[2])));
    return lines;
}

} // namespace parsons::cli
