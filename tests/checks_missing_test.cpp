// Issue 11, item 7 (the cabinet's share): behaviours a one-line change could break unnoticed
// before. A stuck relay must hold through zeroizing; the card number wraps 9999 -> 0000 and
// nothing else; `parsons check` exits 3 when a bad punch is its only finding; a profile is
// chosen by name.
#include "tests/machine_support.hpp"
#include "tests/test_support.hpp"

#include "cardreader/deck_review.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

using namespace parsons::cardreader;
using namespace parsons::relaylogic;
using namespace parsons::test;

namespace {

// The sample deck as .bin with one extra hole: card `card`, column `column`, row 5.
std::string sample_with_row5(TempDir& dir, long card, int column) {
    REQUIRE(
        run_parsons("punch " + q(source_path(kSample)) + " -o " + q(dir.str("s.bin"))).exit_code ==
        0);
    std::string bytes = read_bytes(dir.path("s.bin"));
    const auto i = static_cast<std::size_t>(160 * (card - 1) + 2 * (column - 1) + 1);
    bytes.at(i) = static_cast<char>(bytes.at(i) | 0x01); // word bit 4 = row 5
    const std::string name = fmt::format("bad{}_{}.bin", card, column);
    write_bytes(dir.path(name), bytes);
    return dir.str(name);
}

} // namespace

TEST_CASE("Fault stuck-relay: the relay holds through zeroizing and makes its spurious match on "
          "the second card",
          "[faults][fig13]") {
    // Card 1 stops the table at 0.300 before 0.500; card 2 runs on to 0.700 past 0.500, where
    // relay 5 of bank 352, stuck closed since the start, lets the comparer conduct.
    CardOrders one = idle_card(1, {0, 0, 0, 0, 0});
    one.axis(Axis::table) = order(0, 300, 3, {}, {}, 1);
    CardOrders two = idle_card(2, {300, 0, 0, 0, 0});
    two.axis(Axis::table) = order(300, 700, 3, {}, {}, 1);
    RunResult clean = run_orders({one, two});
    CHECK(clean.completed);
    RunResult r = run_orders({one, two}, parsons::axes::default_profile(), nullptr,
                             {parse_fault("stuck-relay:table:352:5")});
    REQUIRE(r.stop);
    CHECK(r.stop->reason == StopReason::check_mismatch);
    CHECK(r.stop->card == 2);
    CHECK(r.axes.at(0).counter_in == Approx(0.500));
    CHECK(r.stop->lamps.back() == "table lamp 270 (absolute comparer 122' conducting)");
}

TEST_CASE("Card order: 0000 follows 9999 and is accepted, 0001 after 9999 stops the machine",
          "[cabinet][card-order]") {
    auto deck = [](int second) {
        CardOrders a = idle_card(9998, {0, 0, 0, 0, 0});
        CardOrders b = idle_card(9999, {0, 0, 0, 0, 0});
        CardOrders c = idle_card(second, {0, 0, 0, 0, 0});
        return std::vector<CardOrders>{a, b, c};
    };
    RunResult wrapped = run_orders(deck(0));
    CHECK(wrapped.completed);
    CHECK(wrapped.cards_read == 3);
    RunResult skipped = run_orders(deck(1));
    REQUIRE(skipped.stop);
    CHECK(skipped.stop->reason == StopReason::out_of_order_card);
    CHECK(skipped.stop->card == 3);
    CHECK(skipped.stop->message.find("card number 0001 follows 9999 (expected 0000)") !=
          std::string::npos);
}

TEST_CASE("Check: a bad punch alone exits 3, named as the reader's refusal (an addition)",
          "[cli][check][bad-punch]") {
    TempDir dir;
    const std::string stray = sample_with_row5(dir, 2, 76); // column 76 is unused
    auto r = run_parsons("check " + q(stray));
    CHECK(r.exit_code == 3);
    CHECK(r.output.find("the machine stops at card 2: bad_punch: card 2, column 76") !=
          std::string::npos);
    CHECK(r.output.find("an addition of this emulator") != std::string::npos);
    CHECK(r.output.find("card 2 was read, and the reader stopped the machine before any axis ran "
                        "on it") != std::string::npos);
    CHECK(r.output.find("0 moves past a limit, 1 machine stop") != std::string::npos);
    auto clean = run_parsons("check " + q(source_path(kSample)));
    CHECK(clean.exit_code == 0);
}

TEST_CASE("Profiles by name: a double punch is a warning in parsons-1952 (two relays) and a "
          "bad punch in parsons-safe, for check and run alike",
          "[cli][check][profile][bad-punch]") {
    TempDir dir;
    const std::string twice = sample_with_row5(dir, 2, 13); // table stop: rows 3 and 5
    auto faithful = run_parsons("check " + q(twice));
    CHECK(faithful.output.find("card 2 (number 0002): double punch: column 13: the reader closes "
                               "two relays") != std::string::npos);
    CHECK(faithful.output.find("BAD PUNCH") == std::string::npos);
    auto safe = run_parsons("check " + q(twice) + " --profile parsons-safe");
    CHECK(safe.exit_code == 3);
    CHECK(safe.output.find("the machine stops at card 2: bad_punch: card 2, column 13: double "
                           "punch") != std::string::npos);

    auto ran_safe = run_parsons("run " + q(twice) + " --profile parsons-safe --report " +
                                q(dir.str("safe.json")));
    CHECK(ran_safe.exit_code == 3);
    const auto safe_report = nlohmann::json::parse(read_bytes(dir.path("safe.json")));
    CHECK(safe_report["stop"]["reason"] == "bad_punch");
    auto ran = run_parsons("run " + q(twice) + " --report " + q(dir.str("1952.json")));
    const auto report = nlohmann::json::parse(read_bytes(dir.path("1952.json")));
    CHECK((report["stop"].is_null() || report["stop"]["reason"] != "bad_punch"));
    CHECK(report["cards_read"].get<long>() >= 2);
    // An unknown profile name that is no file either is bad usage.
    auto unknown = run_parsons("check " + q(twice) + " --profile parsons-1953");
    CHECK(unknown.exit_code == 2);
}
