// The card, read (issue 52, item 2; web/reader.js): the record carries each card the brushes
// sensed, hole for hole, and the brushes' wiring (relaylogic::brush_wiring), and the wiring is
// the machine's: every hole picks the relay its wire names, and nothing picks without a hole.
#include "tests/machine_support.hpp"

#include "outputs/replay/run_timeline.hpp"
#include "relaylogic/card_reader.hpp"

#include "axes/machine_profile.hpp"
#include "cardreader/layout.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <map>
#include <set>
#include <string>
#include <vector>

using parsons::cli::RunTimeline;
using parsons::test::idle_card;
using parsons::test::order;
using parsons::test::run_orders;
namespace cr = parsons::cardreader;
namespace rl = parsons::relaylogic;

namespace {

// Three cards: slow-downs, a reverse move, a card whose swivel and tilt stand still.
std::vector<cr::CardOrders> reader_deck() {
    auto c1 = idle_card(1, {0, 0, 0, 0, 0});
    c1.axis(cr::Axis::table) = order(0, 1507, 1, 1307, 1407, 1);
    c1.axis(cr::Axis::cross) = order(0, 250, 2, 150, {}, 2);
    auto c2 = idle_card(2, {1507, 250, 0, 0, 0});
    c2.axis(cr::Axis::table) = order(1507, 205, 2, 305, {}, 1);
    c2.axis(cr::Axis::swivel) = order(0, 500, 3, {}, {}, 8);
    auto c3 = idle_card(3, {205, 250, 0, 500, 0});
    c3.axis(cr::Axis::tilt) = order(0, 999, 3, {}, {}, 16);
    return {c1, c2, c3};
}

// The row names a column's Hollerith word has holes in (12, 11, 0 .. 9).
std::vector<int> rows_of(unsigned word) {
    static const int kNames[12] = {12, 11, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
    std::vector<int> rows;
    for (int bit = 11; bit >= 0; --bit) {
        if ((word >> bit & 1U) != 0) {
            rows.push_back(kNames[11 - bit]);
        }
    }
    return rows;
}

} // namespace

TEST_CASE("Card reader view: every hole picks the part its brush is wired to, nothing else picks",
          "[timeline][reader]") {
    const auto profile = parsons::axes::default_profile();
    RunTimeline timeline;
    const rl::RunResult result = run_orders(reader_deck(), profile, &timeline);
    INFO((result.stop ? result.stop->message : std::string()));
    REQUIRE_FALSE(result.stop);
    const nlohmann::json h = timeline.header();
    REQUIRE(h["brushes"].size() == 3);
    std::map<int, std::vector<nlohmann::json>> wires; // column -> its wires
    for (const auto& w : h["brush_wiring"]) {
        wires[w["column"].get<int>()].push_back(w);
    }
    std::map<std::string, std::uint32_t> id_of;
    for (std::size_t i = 0; i < h["signals"].size(); ++i) {
        const auto& s = h["signals"][i];
        id_of[s["scope"].get<std::string>() + "." + s["name"].get<std::string>()] =
            static_cast<std::uint32_t>(i);
    }
    // Every wire names a signal the cabinet defines (a digit wire: each of its ten relays).
    int named = 0;
    for (const auto& [column, list] : wires) {
        for (const auto& w : list) {
            std::string picks = w["picks"];
            if (const auto hash = picks.find('#'); hash != std::string::npos) {
                for (int d = 0; d <= 9; ++d) {
                    named += id_of.count(picks.substr(0, hash) + std::to_string(d));
                }
            } else {
                named += static_cast<int>(id_of.count(picks)) * 10;
            }
        }
    }
    CHECK(named == 10 * static_cast<int>(h["brush_wiring"].size()));

    const auto& t = timeline.change_times();
    const auto& ids = timeline.change_ids();
    const auto& values = timeline.change_values();
    for (std::size_t k = 0; k < h["brushes"].size(); ++k) {
        const auto& card = h["brushes"][k];
        const std::string holes = card["holes"];
        REQUIRE(holes.size() == 240);
        // The signals at the end of this card's reader cycle (read_complete).
        const double end = card["t"].get<double>() - profile.first_bank_s + profile.reader_cycle_s;
        std::vector<std::uint32_t> now(h["signals"].size());
        for (std::size_t i = 0; i < now.size(); ++i) {
            now[i] = h["signals"][i]["initial"];
        }
        const double fed = card["t"].get<double>() - profile.first_bank_s;
        std::set<std::uint32_t> rose; // a signal that came to a value other than 0 in the cycle
        for (std::size_t i = 0; i < t.size() && t[i] <= end; ++i) {
            now[ids[i]] = values[i];
            if (t[i] > fed && values[i] != 0) {
                rose.insert(ids[i]);
            }
        }
        std::set<std::string> picked_by_holes;
        for (int column = 1; column <= 80; ++column) {
            const unsigned word = std::stoul(holes.substr(3 * (column - 1), 3), nullptr, 16);
            for (const int row : rows_of(word)) {
                for (const auto& w : wires[column]) {
                    const auto& rows = w["rows"];
                    if (std::find(rows.begin(), rows.end(), row) == rows.end()) {
                        continue;
                    }
                    std::string picks = w["picks"];
                    if (const auto hash = picks.find('#'); hash != std::string::npos) {
                        picks = picks.substr(0, hash) + std::to_string(row);
                    }
                    picked_by_holes.insert(picks);
                }
            }
        }
        INFO("card " << k + 1);
        // Every holding relay and sequence contact a hole names is closed...
        int relays = 0;
        for (const auto& name : picked_by_holes) {
            if (name.find(".relay_") != std::string::npos ||
                name.find("sequence_switch_224") != std::string::npos) {
                INFO(name);
                CHECK(now.at(id_of.at(name)) == 1);
                ++relays;
            }
        }
        CHECK(relays >= 5 * 8); // five axes: at least the stop's four banks and the check's four
        // ... and every one closed is named by a hole.
        for (const auto& [name, id] : id_of) {
            if ((name.find("storage_") != std::string::npos &&
                 name.find(".relay_") != std::string::npos) ||
                name.find("sequence_switch_224.contact_") != std::string::npos) {
                if (now[id] == 1) {
                    INFO(name);
                    CHECK(picked_by_holes.count(name) == 1);
                }
            }
        }
        // The speed column's holes stepped switch 236 off "off" (an axis with no move may be
        // back on "off" by the cycle's end); the card number is checked.
        for (const char* axis : {"table", "cross", "vertical", "swivel", "tilt"}) {
            const std::string sw = std::string(axis) + ".speed_switch_236";
            INFO(sw);
            CHECK(rose.count(id_of.at(sw)) == picked_by_holes.count(sw));
        }
        CHECK(now.at(id_of.at("cabinet.card_number_check")) == k + 1);
    }
}
