#include "tests/property/key_ranges.hpp"

#include "tests/test_support.hpp"

#include <fmt/format.h>

#include <array>
#include <stdexcept>

namespace parsons::test {
namespace {

using nlohmann::json;

// A number the schema leaves unbounded above (an acceleration, a rate, a length) is drawn up
// to this: far past anything a built-in profile holds, short of what no machine could be.
constexpr double kAssumedMax = 1000;

const json& resolve(const json& schema, const json& node) {
    if (node.contains("$ref")) {
        const std::string ref = node.at("$ref").get<std::string>();
        const std::string prefix = "#/$defs/";
        if (ref.rfind(prefix, 0) != 0) {
            throw std::runtime_error("profile schema: a $ref outside $defs: " + ref);
        }
        return schema.at("$defs").at(ref.substr(prefix.size()));
    }
    return node;
}

// A number or integer leaf, if it has a lower bound (every ranged key does).
bool number_range(const json& n, const std::string& key, std::vector<KeyRange>& out) {
    const std::string type = n.value("type", "");
    if (type != "number" && type != "integer") {
        return false;
    }
    KeyRange r;
    r.key = key;
    r.kind = type == "integer" ? KeyRange::Kind::integer : KeyRange::Kind::number;
    if (n.contains("minimum")) {
        r.min = n.at("minimum").get<double>();
    } else if (n.contains("exclusiveMinimum")) {
        r.min = n.at("exclusiveMinimum").get<double>();
        r.min_exclusive = true;
    } else {
        return true; // no range (travel_min_in): the generator leaves it to the deck recipe
    }
    if (n.contains("maximum")) {
        r.max = n.at("maximum").get<double>();
    } else if (n.contains("exclusiveMaximum")) {
        r.max = n.at("exclusiveMaximum").get<double>();
        r.max_exclusive = true;
    } else {
        r.max = std::max(kAssumedMax, r.min * 10);
        r.max_documented = false;
    }
    out.push_back(r);
    return true;
}

void walk(const json& schema, const json& node, const std::string& key,
          std::vector<KeyRange>& out) {
    const json& n = resolve(schema, node);
    if (n.contains("properties")) {
        for (const auto& [name, child] : n.at("properties").items()) {
            if (name == "name" || name == "base") {
                continue;
            }
            walk(schema, child, key.empty() ? name : key + "." + name, out);
        }
        return;
    }
    if (n.contains("enum")) {
        KeyRange r;
        r.key = key;
        r.kind = KeyRange::Kind::choice;
        for (const auto& c : n.at("enum")) {
            r.choices.push_back(c.get<std::string>());
        }
        out.push_back(r);
        return;
    }
    const std::string type = n.value("type", "");
    if (type == "boolean") {
        KeyRange r;
        r.key = key;
        r.kind = KeyRange::Kind::boolean;
        out.push_back(r);
        return;
    }
    // A fixed array of ranged numbers (an axis's three speeds): each element a key.
    if (type == "array" && n.contains("items") && n.value("minItems", 0) > 0 &&
        n.value("minItems", 0) == n.value("maxItems", -1)) {
        const json& item = resolve(schema, n.at("items"));
        for (int i = 0; i < n.at("minItems").get<int>(); ++i) {
            number_range(item, fmt::format("{}[{}]", key, i), out);
        }
        return;
    }
    number_range(n, key, out); // other arrays (tables, tools, heads) and strings: not drawn
}

} // namespace

std::vector<KeyRange> ranges_from_schema(const json& schema) {
    std::vector<KeyRange> out;
    walk(schema, schema, "", out);
    return out;
}

const std::vector<KeyRange>& key_ranges() {
    static const std::vector<KeyRange> ranges = ranges_from_schema(
        json::parse(read_bytes(source_path("docs/schemas/profile.schema.json"))));
    return ranges;
}

std::string loader_key(const std::string& key) {
    const auto bracket = key.find('[');
    return bracket == std::string::npos ? key : key.substr(0, bracket);
}

} // namespace parsons::test
