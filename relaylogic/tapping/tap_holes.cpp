// The holes of the tapping attachment (EP 0360190, spindle synchronisation; an addition):
// a hole's record in a saved state and how far it bottomed from its depth. Split from
// tapping_units.cpp (the house's 700-line limit).
#include "relaylogic/tapping/tapping_units.hpp"

#include "axes/state_json.hpp"

#include <algorithm>
#include <cmath>

namespace parsons::relaylogic {

using axes::exact;

double depth_miss_in(const HoleRecord& hole, int encoder_pulses_per_rev) {
    if (!hole.completed) {
        return 0;
    }
    const double edge_in =
        hole.pitch_ordered_in * hole.ratio_used / std::max(encoder_pulses_per_rev, 1);
    const double miss = hole.deepest_in - hole.depth_in;
    return std::abs(miss) > std::max(0.001, edge_in) + 1e-9 ? miss : 0.0;
}

namespace {

// The index wait's figures, only for a hole that waited (a saved state without them is one
// from before the addition, or of holes that did not wait).
void add_index_json(const HoleRecord& h, nlohmann::json& j) {
    if (h.index_wait) {
        j["index_wait"] = true;
        j["sync_s"] = exact(h.sync_s);
        j["sync_tool_revs"] = exact(h.sync_tool_revs);
    }
    if (h.retract != 1) { // the faster retract (an addition): only when ordered
        j["retract"] = h.retract;
    }
    if (h.peck_in > 0) { // rigid peck tapping (an addition): only when ordered
        j["peck_in"] = exact(h.peck_in);
        j["pecks"] = h.pecks;
    }
}

} // namespace

// A hole's record in a saved state: a resumed run reports the holes tapped before the card it
// resumes at, as an uninterrupted run does (found by the property test, tests/property_test.cpp).
nlohmann::json tap_hole_json(const HoleRecord& h) {
    nlohmann::json samples = nlohmann::json::array();
    for (const TapSample& s : h.samples) {
        samples.push_back({exact(s.t), exact(s.tool_revs), exact(s.feed_in)});
    }
    nlohmann::json j = {
        {"card", h.card},
        {"number", h.number},
        {"tool_called", h.tool_called},
        {"tool", h.tool},
        {"tap_pitch_in", h.tap_pitch_in ? exact(*h.tap_pitch_in) : nlohmann::json(nullptr)},
        {"head_ratio", exact(h.head_ratio)},
        {"ratio_used", exact(h.ratio_used)},
        {"pitch_ordered_in", exact(h.pitch_ordered_in)},
        {"rpm", h.rpm},
        {"axis", static_cast<int>(cardreader::axis_index(h.axis))},
        {"sense", h.sense},
        {"start_in", exact(h.start_in)},
        {"depth_in", exact(h.depth_in)},
        {"deepest_in", exact(h.deepest_in)},
        {"end_in", exact(h.end_in)},
        {"start_s", exact(h.start_s)},
        {"reverse_s", exact(h.reverse_s)},
        {"end_s", exact(h.end_s)},
        {"completed", h.completed},
        {"samples", samples}};
    add_index_json(h, j);
    return j;
}

HoleRecord tap_hole_from_json(const nlohmann::json& j) {
    HoleRecord h;
    h.card = j.at("card").get<std::int64_t>();
    h.number = j.at("number").get<int>();
    h.tool_called = j.at("tool_called").get<int>();
    h.tool = j.at("tool").get<int>();
    if (!j.at("tap_pitch_in").is_null()) {
        h.tap_pitch_in = exact(j.at("tap_pitch_in"));
    }
    h.head_ratio = exact(j.at("head_ratio"));
    h.ratio_used = exact(j.at("ratio_used"));
    h.pitch_ordered_in = exact(j.at("pitch_ordered_in"));
    h.rpm = j.at("rpm").get<int>();
    h.axis = cardreader::kAxes.at(static_cast<std::size_t>(
        std::clamp(j.at("axis").get<int>(), 0, static_cast<int>(cardreader::kAxisCount) - 1)));
    h.sense = j.at("sense").get<int>();
    h.start_in = exact(j.at("start_in"));
    h.depth_in = exact(j.at("depth_in"));
    h.deepest_in = exact(j.at("deepest_in"));
    h.end_in = exact(j.at("end_in"));
    h.start_s = exact(j.at("start_s"));
    h.reverse_s = exact(j.at("reverse_s"));
    h.end_s = exact(j.at("end_s"));
    h.completed = j.at("completed").get<bool>();
    for (const auto& s : j.at("samples")) {
        h.samples.push_back({exact(s.at(0)), exact(s.at(1)), exact(s.at(2))});
    }
    if (j.contains("index_wait")) {
        h.index_wait = j.at("index_wait").get<bool>();
        h.sync_s = exact(j.at("sync_s"));
        h.sync_tool_revs = exact(j.at("sync_tool_revs"));
    } else {
        h.sync_s = h.start_s;
    }
    h.retract = j.value("retract", 1);
    if (j.contains("peck_in")) {
        h.peck_in = exact(j.at("peck_in"));
        h.pecks = j.at("pecks").get<int>();
    }
    return h;
}

} // namespace parsons::relaylogic
