// `parsons show` and `parsons check` do not mislead (issue 11, item 6): travel modulo 10 inches
// in the direction of motion, the sequence pattern replayed, the coast estimated from the
// machine profile; and the run report's position error counts the counters' wrap-arounds.
#include "tests/machine_support.hpp"
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <cmath>
#include <string>

using namespace parsons;
using parsons::test::idle_rest;
using parsons::test::kHeader;
using parsons::test::q;
using parsons::test::read_bytes;
using parsons::test::run_parsons;
using parsons::test::TempDir;
using parsons::test::write_bytes;

namespace {

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
        ++n;
    }
    return n;
}

} // namespace

TEST_CASE("Show: silent on a correct move across zero, and the machine agrees", "[show][cli]") {
    TempDir dir;
    // Reverse from 0.000 through 9.999 to 9.900, then forward through 0.000 to 0.150.
    write_bytes(dir.path("zero.csv"), std::string(kHeader) + "1,0,table,-,3,,,9.900,0.100,1\n" +
                                          idle_rest(1) + "2,0,table,+,2,0.050,,0.150,0.250,1\n" +
                                          idle_rest(2));
    auto show = run_parsons("show " + q(dir.str("zero.csv")));
    INFO(show.output);
    CHECK(show.exit_code == 0);
    CHECK(count(show.output, "warning:") == 0);
    CHECK(show.output.find("2 cards read, 0 warnings") != std::string::npos);
    auto check = run_parsons("check " + q(dir.str("zero.csv")));
    CHECK(check.exit_code == 0);
    CHECK(count(check.output, "warning:") == 0);
    auto run = run_parsons("run " + q(dir.str("zero.csv")) + " --report " + q(dir.str("r.json")));
    CHECK(run.exit_code == 0);
    const std::string report = read_bytes(dir.path("r.json"));
    CHECK(report.find("\"status\": \"completed\"") != std::string::npos);
}

TEST_CASE("Show: warns on a sequence stall the machine then stops on", "[show][cli][sequence]") {
    TempDir dir;
    // Table and cross both moving, both punched at position 1 only.
    write_bytes(dir.path("stall.csv"),
                std::string(kHeader) + "1,0,table,+,3,,,0.100,0.100,1\n" +
                    "1,0,cross,+,3,,,0.200,0.200,1\n1,0,vertical,+,3,,,0.000,0.000,3\n"
                    "1,0,swivel,+,3,,,0.000,0.000,4\n1,0,tilt,+,3,,,0.000,0.000,5\n");
    auto show = run_parsons("show " + q(dir.str("stall.csv")));
    INFO(show.output);
    CHECK(show.output.find("warning: table and cross are punched at position 1 only") !=
          std::string::npos);
    CHECK(show.output.find("warning: sequence stall: after table stops, position 2 of stepping "
                           "shaft 280 is answered by no running axis") != std::string::npos);
    auto check = run_parsons("check " + q(dir.str("stall.csv")));
    CHECK(check.output.find("STOP: sequence stall") != std::string::npos);
    CHECK(check.exit_code == 3);
    auto run = run_parsons("run " + q(dir.str("stall.csv")) + " --report " + q(dir.str("r.json")));
    CHECK(run.exit_code == 3);
    CHECK(read_bytes(dir.path("r.json")).find("sequence_stall") != std::string::npos);
}

TEST_CASE("Show: warns on slow-downs too close to the stop, from the profile's braking",
          "[show][cli][coast]") {
    TempDir dir;
    // docs/design-rules.md rule 7: slow-downs 0.001 and 0.002 before the stop overshoot; 0.200 and
    // 0.100 do not.
    write_bytes(dir.path("close.csv"), std::string(kHeader) +
                                           "1,0,table,+,1,8.983,8.984,8.985,"
                                           "8.985,1\n" +
                                           idle_rest(1) + "2,0,table,+,3,,,9.085,0.100,1\n" +
                                           idle_rest(2));
    write_bytes(dir.path("far.csv"), std::string(kHeader) +
                                         "1,0,table,+,1,8.785,8.885,8.985,"
                                         "8.985,1\n" +
                                         idle_rest(1) + "2,0,table,+,3,,,9.085,0.100,1\n" +
                                         idle_rest(2));
    auto close = run_parsons("show " + q(dir.str("close.csv")));
    INFO(close.output);
    CHECK(count(close.output, "warning:") == 2); // on the card that coasts, and the next
    CHECK(close.output.find("warning: table: slow-down too close to the stop: it reaches the stop "
                            "8.985 still at ") != std::string::npos);
    CHECK(close.output.find("warning: table: the previous card's stop coasts about") !=
          std::string::npos);
    auto far = run_parsons("show " + q(dir.str("far.csv")));
    CHECK(count(far.output, "warning:") == 0);
    // The machine agrees: the close deck stops on the next card's check, the far one completes.
    CHECK(run_parsons("run -q " + q(dir.str("close.csv"))).exit_code == 3);
    CHECK(run_parsons("run -q " + q(dir.str("far.csv"))).exit_code == 0);
    // A profile that brakes hard enough makes the same card safe: the estimate is the profile's.
    write_bytes(dir.path("hard.json"), R"({"axes": {"table": {"braking_in_per_s2": 10.0}}})");
    auto hard =
        run_parsons("show " + q(dir.str("close.csv")) + " --profile " + q(dir.str("hard.json")));
    CHECK(count(hard.output, "warning:") == 0);
    auto checked = run_parsons("check " + q(dir.str("close.csv")));
    CHECK(checked.output.find("slow-down too close to the stop") != std::string::npos);
}

TEST_CASE("Report: a 10-inch slip across the counters' wrap is not hidden in the position error",
          "[report][cli]") {
    TempDir dir;
    // 9.000 forward, then 2.000 more through 9.999 -> 0.000 to 1.000: 11 000 impulses. The screw
    // slips for the first 10 000 of them: the part ends at 1.000, as the counter reads, but the
    // counter has been round once more: the part is 10 inches short of what was counted.
    write_bytes(dir.path("wrap.csv"), std::string(kHeader) + "1,0,table,+,3,,,9.000,9.000,1\n" +
                                          idle_rest(1) + "2,0,table,+,3,,,1.000,2.000,1\n" +
                                          idle_rest(2));
    // Counting the screw's turns (the departure): the patent's chain would count the part.
    write_bytes(dir.path("turns.json"), R"({"measuring_chain": "screw_turns"})");
    auto run =
        run_parsons("run " + q(dir.str("wrap.csv")) + " --fault slip:table:1:10000" +
                    " --profile " + q(dir.str("turns.json")) + " --report " + q(dir.str("r.json")));
    INFO(run.output);
    const std::string report = read_bytes(dir.path("r.json"));
    INFO(report);
    const auto table = report.find("\"table\"");
    REQUIRE(table != std::string::npos);
    const auto key = report.find("\"position_error\"", table);
    REQUIRE(key != std::string::npos);
    CHECK(std::stod(report.substr(report.find(':', key) + 1)) == Approx(-10.0).margin(0.0005));
    CHECK(run.output.find("table lead screw slipped: the part is -10.000") != std::string::npos);
}

TEST_CASE("Report: a correct move below zero wraps the counter and leaves no position error",
          "[report][cabinet]") {
    // Reverse from 0.000 to 9.900: the part stands at -0.100, the counter reads 9.900.
    cardreader::CardOrders card = test::idle_card(1, {0, 0, 0, 0, 0});
    card.axis(cardreader::Axis::table) = test::order(0, 9900, 3);
    card.axis(cardreader::Axis::table).motion = cardreader::Motion::reverse;
    card.axis(cardreader::Axis::table).check = 100;
    const auto pace = GENERATE(relaylogic::Pace::fast_forward, relaylogic::Pace::impulse_level);
    const auto r = test::run_orders({card}, axes::default_profile(), nullptr, {}, pace);
    REQUIRE(r.completed);
    const auto& table = r.axes.at(0);
    CHECK(table.counter_in == Approx(9.9));
    CHECK(table.real_in == Approx(-0.1).margin(0.0006));
    CHECK(std::abs(table.error_in) < 0.0006);
}
