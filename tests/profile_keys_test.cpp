// The profile loader is the guard (axes/profile_keys.hpp, axes/profile_relations.hpp): every
// number's range and every relation between keys is stated once, in the loader's own tables,
// and the JSON Schema (docs/schemas/profile.schema.json) and the docs (docs/machine-profile.md,
// "Every number's range") say exactly the same. PARSONS_UPDATE_GOLDEN=1 rewrites the docs'
// generated section from the tables.
#include "axes/machine_profile.hpp"
#include "axes/profile_json.hpp"
#include "axes/profile_keys.hpp"
#include "axes/profile_relations.hpp"

#include "tests/test_support.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace profile_keys_test {

using nlohmann::json;
using parsons::axes::KeyRange;
using parsons::axes::KeyType;
using parsons::axes::profile_from_json;
using parsons::axes::ProfileError;

// A key's value placed in a partial profile, and the key as the loader names it there.
struct Placed {
    json patch;
    std::string where;
};

// "axes.*.speed_in_per_min[]" -> {"axes": {"table": {"speed_in_per_min": [v, 1.8, 0.6]}}}.
Placed in_axis(const std::string& rest, const json& v) {
    const auto bracket = rest.find('[');
    const std::string name = rest.substr(0, bracket);
    const std::string tail = bracket == std::string::npos ? "" : rest.substr(bracket);
    json value = v;
    std::string at = name;
    if (tail == "[]") {
        value = json::array({v, 1.8, 0.6});
        at += "[0]";
    } else if (tail == "[][0]") {
        value = json::array({json::array({v, 0})});
        at += "[0][0]";
    } else if (tail == "[][1]") {
        value = json::array({json::array({0, v})});
        at += "[0][1]";
    } else if (tail == "[0]") {
        value = json::array({v, 10});
        at += "[0]";
    } else if (tail == "[1]") {
        value = json::array({-10, v});
        at += "[1]";
    }
    return {{{"axes", {{"table", {{name, value}}}}}}, "axes.table." + at};
}

Placed place(const std::string& key, const json& v) {
    if (key.rfind("axes.*.", 0) == 0) {
        return in_axis(key.substr(7), v);
    }
    if (key.rfind("tools[].", 0) == 0) {
        json tool{{"number", 1}, {"radius_in", 0.25}};
        tool[key.substr(8)] = v;
        return {{{"tools", json::array({tool})}}, "tools[0]." + key.substr(8)};
    }
    if (key.rfind("spindle.heads[].", 0) == 0) {
        const std::string field = key.substr(16);
        json head{{"tool", 1}, {"ratio", 0.25}};
        head[field == "radius_in" ? "radius_in" : "pitch_in"] = 0.05;
        head[field] = v;
        return {{{"spindle", {{"heads", json::array({head})}, {"first_tool", 1}}}},
                "spindle.heads[0]." + field};
    }
    const auto dot = key.find('.');
    if (dot != std::string::npos) {
        return {{{key.substr(0, dot), {{key.substr(dot + 1), v}}}}, key};
    }
    return {{{key, v}}, key};
}

// The loader's message for the key placed with v, or "" when it accepts it.
std::string loaded(const std::string& key, const json& v, std::string* where = nullptr) {
    const Placed p = place(key, v);
    if (where != nullptr) {
        *where = p.where;
    }
    try {
        profile_from_json(p.patch.dump(), parsons::axes::default_profile());
    } catch (const ProfileError& e) {
        return e.what();
    }
    return "";
}

json as_json(const KeyRange& r, double v) {
    return r.type == KeyType::whole ? json(static_cast<std::int64_t>(v)) : json(v);
}

// The next value past `v` toward `to`: a whole step for a whole key.
double step(const KeyRange& r, double v, double to) {
    return r.type == KeyType::whole ? v + (to > v ? 1 : -1) : std::nextafter(v, to);
}

// The schema node that describes a key of the table, through $ref and a nullable anyOf, with
// its JSON pointer.
struct SchemaNode {
    const json* node;
    std::string pointer;
};

SchemaNode resolved(const json& root, SchemaNode at) {
    for (;;) {
        if (at.node->contains("$ref")) {
            at.pointer = at.node->at("$ref").get<std::string>().substr(1);
            at.node = &root.at(json::json_pointer(at.pointer));
        } else if (at.node->contains("anyOf")) {
            const json& branches = at.node->at("anyOf");
            std::size_t i = 0;
            while (i < branches.size() && branches.at(i).value("type", "") == "null") {
                ++i;
            }
            REQUIRE(i < branches.size());
            at = {&branches.at(i), at.pointer + "/anyOf/" + std::to_string(i)};
        } else {
            return at;
        }
    }
}

SchemaNode schema_node(const json& root, const std::string& key) {
    SchemaNode at{&root, ""};
    std::size_t from = 0;
    while (from <= key.size()) {
        const auto dot = key.find('.', from);
        const std::string segment = key.substr(from, dot == std::string::npos ? dot : dot - from);
        from = dot == std::string::npos ? key.size() + 1 : dot + 1;
        const auto bracket = segment.find('[');
        std::string name = segment.substr(0, bracket);
        name = name == "*" ? "table" : name; // every axis is the same #/$defs/axis
        at = resolved(root, at);
        const std::string pointer = at.pointer + "/properties/" + name;
        at = {&root.at(json::json_pointer(pointer)), pointer};
        for (std::size_t b = bracket; b != std::string::npos; b = segment.find('[', b + 1)) {
            const std::string index = segment.substr(b + 1, segment.find(']', b) - b - 1);
            at = resolved(root, at);
            const std::string next =
                at.pointer + (index.empty() ? "/items" : "/prefixItems/" + index);
            at = {&root.at(json::json_pointer(next)), next};
        }
    }
    return resolved(root, at);
}

const json& profile_schema() {
    static const json schema = json::parse(
        parsons::test::read_bytes(parsons::test::source_path("docs/schemas/profile.schema.json")));
    return schema;
}

// Every node of the schema that bounds a number, by its pointer.
void bounded_nodes(const json& node, const std::string& pointer, std::set<std::string>& out) {
    if (node.is_object()) {
        for (const char* word : {"minimum", "maximum", "exclusiveMinimum", "exclusiveMaximum"}) {
            if (node.contains(word)) {
                out.insert(pointer);
            }
        }
        for (const auto& [k, v] : node.items()) {
            bounded_nodes(v, pointer + "/" + k, out);
        }
    } else if (node.is_array()) {
        for (std::size_t i = 0; i < node.size(); ++i) {
            bounded_nodes(node.at(i), pointer + "/" + std::to_string(i), out);
        }
    }
}

constexpr std::string_view kDocsBegin = "<!-- ranges: written from axes/profile_keys.cpp and "
                                        "axes/profile_relations.cpp; tests/profile_keys_test.cpp "
                                        "holds it to them -->\n";
constexpr std::string_view kDocsEnd = "<!-- /ranges -->";

} // namespace profile_keys_test

TEST_CASE("Profile: every number's range in the one table is the loader's: its ends accepted, a "
          "step past them refused naming the key",
          "[profile][profile-keys]") {
    using namespace profile_keys_test;
    for (const KeyRange& r : parsons::axes::profile_key_ranges()) {
        const std::string key(r.key);
        INFO(key << " " << parsons::axes::range_words(r));
        std::string where;
        const std::string refused = "must be a ";
        // An end's value inside, and the nearest value past it (a finite end), or the farthest
        // a JSON number may go (no end).
        const auto check_end = [&](double end, bool open, double inward) {
            if (!std::isfinite(end)) {
                const double far = end > 0 ? 1e308 : -1e308;
                CHECK(loaded(key, as_json(r, far), &where).rfind(where + ": " + refused, 0) ==
                      std::string::npos);
                return;
            }
            const double inside = open ? step(r, end, inward) : end;
            const double outside = open ? end : step(r, end, -inward);
            INFO("inside " << as_json(r, inside).dump() << ", outside "
                           << as_json(r, outside).dump());
            // Inside: not refused for its range (a relation to another key may still refuse it,
            // naming that relation).
            CHECK(loaded(key, as_json(r, inside), &where).rfind(where + ": " + refused, 0) ==
                  std::string::npos);
            CHECK(loaded(key, as_json(r, outside), &where).rfind(where + ": " + refused, 0) == 0);
        };
        check_end(r.least, r.least_open, parsons::axes::kNoEnd);
        check_end(r.most, r.most_open, -parsons::axes::kNoEnd);
        CHECK(loaded(key, "1", &where).rfind(where + ": " + refused, 0) == 0);
        if (r.type == KeyType::whole) {
            CHECK(loaded(key, r.least + 0.5, &where).rfind(where + ": " + refused, 0) == 0);
        }
    }
}

TEST_CASE("Profile: the JSON Schema bounds each number exactly as the one table does, and bounds "
          "no number the table does not list",
          "[profile][profile-keys][schema]") {
    using namespace profile_keys_test;
    const json& schema = profile_schema();
    std::set<std::string> listed;
    for (const KeyRange& r : parsons::axes::profile_key_ranges()) {
        INFO(r.key);
        const SchemaNode at = schema_node(schema, std::string(r.key));
        INFO(at.pointer);
        listed.insert(at.pointer);
        const json& n = *at.node;
        CHECK(n.value("type", "") == (r.type == KeyType::whole ? "integer" : "number"));
        const auto bound = [&](bool finite, bool open, const char* open_word, const char* shut_word,
                               double value) {
            CHECK(n.contains(open_word) == (finite && open));
            CHECK(n.contains(shut_word) == (finite && !open));
            if (finite) {
                CHECK(n.value(open ? open_word : shut_word, std::nan("")) == value);
            }
        };
        bound(std::isfinite(r.least), r.least_open, "exclusiveMinimum", "minimum", r.least);
        bound(std::isfinite(r.most), r.most_open, "exclusiveMaximum", "maximum", r.most);
    }
    std::set<std::string> bounded;
    bounded_nodes(schema, "", bounded);
    for (const std::string& pointer : bounded) {
        INFO(pointer << ": bounds a number no key of axes/profile_keys.cpp lists");
        CHECK(listed.count(pointer) == 1);
    }
}

TEST_CASE("Profile: docs/machine-profile.md's table of every number's range and the relations "
          "is the one the loader's tables write",
          "[profile][profile-keys][docs-table]") {
    using namespace profile_keys_test;
    const auto path = parsons::test::source_path("docs/machine-profile.md");
    const std::string page = parsons::test::read_bytes(path);
    const auto begin = page.find(kDocsBegin);
    const auto end = page.find(kDocsEnd);
    REQUIRE(begin != std::string::npos);
    REQUIRE(end != std::string::npos);
    REQUIRE(begin < end);
    const std::string stated =
        page.substr(begin + kDocsBegin.size(), end - begin - kDocsBegin.size());
    const std::string written = parsons::axes::profile_ranges_markdown();
    if (std::getenv("PARSONS_UPDATE_GOLDEN") != nullptr && stated != written) {
        parsons::test::write_bytes(path, page.substr(0, begin + kDocsBegin.size()) + written +
                                             page.substr(end));
        WARN("rewrote the ranges of docs/machine-profile.md");
        return;
    }
    CHECK(stated == written);
    // Every key and every relation appears in it, each once.
    for (const KeyRange& r : parsons::axes::profile_key_ranges()) {
        CHECK(parsons::test::count(stated, "| `" + std::string(r.key) + "` |") == 1);
    }
    for (const auto& rel : parsons::axes::profile_relations()) {
        CHECK(parsons::test::count(stated, "- `" + std::string(rel.rule) + "`") == 1);
    }
}

namespace profile_keys_test {

// A relation broken at its edge and held a step inside it, over a built-in profile.
struct RelationEdge {
    std::string_view rule;
    bool extended; // over parsons-extended (else parsons-1952)
    const char* broken;
    const char* held;
    const char* refusal; // how the message starts
};

const RelationEdge kEdges[] = {
    {"axes.*.travel_min_in < axes.*.travel_max_in", false,
     R"({"axes": {"tilt": {"travel_min_in": 2, "travel_max_in": 2}}})",
     R"({"axes": {"tilt": {"travel_min_in": 2, "travel_max_in": 2.0000000000000004}}})",
     "axes.tilt: travel_min_in must be below travel_max_in"},
    {"axes.*.soft_limits_in[0] < axes.*.soft_limits_in[1]", false,
     R"({"axes": {"cross": {"soft_limits_in": [1, 1]}}})",
     R"({"axes": {"cross": {"soft_limits_in": [1, 1.0000000000000002]}}})",
     "axes.cross: soft_limits_in: the minimum must be below the maximum"},
    {"1 + the slope of each axis's error tables > 0", false,
     R"({"axes": {"table": {"lead_error_in": [[0, 0], [1, -1]]}}})",
     R"({"axes": {"table": {"lead_error_in": [[0, 0], [1, -0.9999999999999999]]}}})",
     "axes.table: lead_error_in: the error falls faster than the screw advances after 0 in"},
    {"1 + the slope of each axis's error tables > 0", false,
     R"({"axes": {"vertical": {"screw_error_in": [[0, 0], [1, -0.5]],
         "instrument_error_in": [[0, 0], [1, 0.5]], "cam_160_in": [[0, 0], [1, 0.5]]}}})",
     R"({"axes": {"vertical": {"screw_error_in": [[0, 0], [1, -0.5]],
         "instrument_error_in": [[0, 0], [1, 0.5]], "cam_160_in": [[0, 0], [1, 0.4999999999]]}}})",
     "axes.vertical: screw_error_in + lead_error_in - cam_160_in: the error falls"},
    {"first_bank_s + relay_operate_s < second_bank_s", false, R"({"relay_operate_s": 0.15})",
     R"({"relay_operate_s": 0.14999999999999997})", "first_bank_s: first_bank_s + relay_operate_s"},
    {"second_bank_s + 3 stepping_switch_step_s <= reader_cycle_s", false,
     R"({"second_bank_s": 0.25, "stepping_switch_step_s": 0.125, "reader_cycle_s": 0.6249999999999999})",
     R"({"second_bank_s": 0.25, "stepping_switch_step_s": 0.125, "reader_cycle_s": 0.625})",
     "reader_cycle_s: second_bank_s + 3 stepping_switch_step_s <= reader_cycle_s must hold"},
    {"feed_gap_s < first_bank_s", false, R"({"feed_gap_s": 0.15})",
     R"({"feed_gap_s": 0.14999999999999997})", "feed_gap_s: feed_gap_s < first_bank_s"},
    {"press.rod_in > press.stroke_in / 2", false, R"({"press": {"stroke_in": 4, "rod_in": 2}})",
     R"({"press": {"stroke_in": 4, "rod_in": 2.0000000000000004}})", "press.rod_in: "},
    {"press.feeder_hold_lag_in = 0 or >= 0.001", true,
     R"({"press": {"feeder_hold_lag_in": 0.0009999999999999998}})",
     R"({"press": {"feeder_hold_lag_in": 0.001}})", "press.feeder_hold_lag_in: "},
    {"press.pressing_from_deg < press.pressing_to_deg", false,
     R"({"press": {"pressing_from_deg": 210, "pressing_to_deg": 210}})",
     R"({"press": {"pressing_from_deg": 209.99999999999997, "pressing_to_deg": 210}})",
     "press.pressing_from_deg: must be below pressing_to_deg"},
    {"press.strokes_per_min × 6 × press.pulses_per_degree × (1 + press.variation) × max(1, "
     "press.change_factor) <= max_stepping_rate_per_s",
     true, R"({"max_stepping_rate_per_s": 47.99999999999999, "spindle_sync": false})",
     R"({"max_stepping_rate_per_s": 48, "spindle_sync": false})", "press.strokes_per_min: "},
    {"spindle.first_tool among spindle.heads[].tool", false, R"({"spindle": {"first_tool": 4}})",
     R"({"spindle": {"first_tool": 3}})", "spindle.first_tool: tool 4 is on no head"},
    {"spindle.max_rpm × max(1, spindle.change_factor) × spindle.encoder_pulses_per_rev / 60 <= "
     "max_stepping_rate_per_s",
     true, R"({"spindle": {"max_rpm": 250.00000000000003}})", R"({"spindle": {"max_rpm": 250}})",
     "spindle.max_rpm: "},
    {"spindle.max_rpm × max(1, spindle.change_factor) / 60 × spindle.sample_s < 0.5", true,
     R"({"spindle": {"sample_s": 0.125}})", R"({"spindle": {"sample_s": 0.12499999999999999}})",
     "spindle.sample_s: "},
    {"contour.ramp_steps_per_s2 <= contour.acceleration_steps_per_s2", true,
     R"({"contour": {"ramp_steps_per_s2": 2000.0000000000002}})",
     R"({"contour": {"ramp_steps_per_s2": 2000}})", "contour.ramp_steps_per_s2: "},
};

} // namespace profile_keys_test

TEST_CASE("Profile: each relation between keys is refused at its exact edge, naming its key, and "
          "held a step inside it, and every relation has its edge here",
          "[profile][profile-keys][relations]") {
    using namespace profile_keys_test;
    std::set<std::string_view> edged;
    for (const RelationEdge& e : kEdges) {
        INFO(e.rule);
        edged.insert(e.rule);
        const auto base =
            e.extended ? parsons::axes::extended_profile() : parsons::axes::default_profile();
        CHECK_THROWS_WITH(profile_from_json(e.broken, base), Catch::StartsWith(e.refusal));
        CHECK_NOTHROW(profile_from_json(e.held, base));
        // A relation the loader checks is one of the list (the docs state each).
        bool listed = false;
        for (const auto& rel : parsons::axes::profile_relations()) {
            listed = listed || rel.rule == e.rule;
        }
        CHECK(listed);
    }
    for (const auto& rel : parsons::axes::profile_relations()) {
        INFO(rel.rule);
        CHECK(edged.count(rel.rule) == 1);
    }
}

TEST_CASE("Profile: sync_drive.position_gain_per_s 0 turns processor 63's position loop off, as "
          "documented, and is accepted",
          "[profile][profile-keys]") {
    using namespace profile_keys_test;
    const auto p = profile_from_json(R"({"sync_drive": {"position_gain_per_s": 0}})",
                                     parsons::axes::extended_profile());
    CHECK(p.sync_drive.position_gain_per_s == 0);
    CHECK_THROWS_WITH(profile_from_json(R"({"sync_drive": {"position_gain_per_s": -1e-300}})",
                                        parsons::axes::extended_profile()),
                      Catch::StartsWith("sync_drive.position_gain_per_s: must be a number at "
                                        "least 0 and at most 100"));
}
