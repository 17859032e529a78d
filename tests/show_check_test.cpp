// `parsons show` and `parsons check` do not mislead (issue 11, item 6; issue 29): what they say
// the machine does is what a run of the deck does, told from its relays; and the run report's
// position error counts the counters' wrap-arounds.
#include "tests/machine_support.hpp"
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <cmath>
#include <string>

using namespace parsons;
using parsons::test::count;
using parsons::test::idle_rest;
using parsons::test::kHeader;
using parsons::test::q;
using parsons::test::read_bytes;
using parsons::test::run_parsons;
using parsons::test::TempDir;
using parsons::test::write_bytes;

TEST_CASE("Show: silent on a correct move across zero, and the machine agrees", "[show][cli]") {
    TempDir dir;
    // Reverse from 0.000 through 9.999 to 9.900, then forward through 0.000 to 0.150.
    write_bytes(dir.path("zero.csv"), std::string(kHeader) + "1,0,table,-,3,,,9.900,0.100,1\n" +
                                          idle_rest(1) + "2,0,table,+,2,0.050,,0.150,0.250,1\n" +
                                          idle_rest(2));
    auto show = run_parsons("show " + q(dir.str("zero.csv")));
    INFO(show.output);
    CHECK(show.exit_code == 0);
    CHECK(show.output.find("2 cards read, 0 notes, 0 with bad punches; the machine runs it "
                           "through") != std::string::npos);
    auto check = run_parsons("check " + q(dir.str("zero.csv")));
    CHECK(check.exit_code == 0);
    CHECK(count(check.output, "observed:") == 0);
    CHECK(check.output.find("the machine runs the deck through: 2 cards") != std::string::npos);
    auto run = run_parsons("run " + q(dir.str("zero.csv")) + " --report " + q(dir.str("r.json")));
    CHECK(run.exit_code == 0);
    const std::string report = read_bytes(dir.path("r.json"));
    CHECK(report.find("\"status\": \"completed\"") != std::string::npos);
}

TEST_CASE("Show and check: a sequence stall is the run's, told from the relays of its card",
          "[show][check][cli][sequence]") {
    TempDir dir;
    // Table and cross both moving, both punched at position 1 only.
    write_bytes(dir.path("stall.csv"),
                std::string(kHeader) + "1,0,table,+,3,,,0.100,0.100,1\n" +
                    "1,0,cross,+,3,,,0.200,0.200,1\n1,0,vertical,+,3,,,0.000,0.000,3\n"
                    "1,0,swivel,+,3,,,0.000,0.000,4\n1,0,tilt,+,3,,,0.000,0.000,5\n");
    auto show = run_parsons("show " + q(dir.str("stall.csv")));
    INFO(show.output);
    CHECK(show.output.find("the machine stops here: sequence_stall: card 1 (number 0001)") !=
          std::string::npos);
    auto check = run_parsons("check " + q(dir.str("stall.csv")));
    INFO(check.output);
    CHECK(check.exit_code == 3);
    CHECK(check.output.find("the machine stops at card 1 (number 0001): sequence_stall") !=
          std::string::npos);
    // The chain: the table stopped at its stop and stepped shaft 280 on; the cross was left
    // running at position 2, where nothing answers.
    CHECK(check.output.find("card 1 (number 0001), table: motor 38 started on speed 3 at 0.000; "
                            "at 0.100 the absolute comparer 122' met the stop 0.100 and the "
                            "increment comparer 122'' met the check 0.100: relay 256 stepped 236 "
                            "from speed 3 to off (contact 238 closed)") != std::string::npos);
    CHECK(check.output.find("card 1 (number 0001), cross: motor 50 started on speed 3 at 0.000") !=
          std::string::npos);
    auto run = run_parsons("run " + q(dir.str("stall.csv")) + " --report " + q(dir.str("r.json")));
    CHECK(run.exit_code == 3);
    CHECK(read_bytes(dir.path("r.json")).find("sequence_stall") != std::string::npos);
}

TEST_CASE("Check: slow-downs a thousandth before the stop are told as the relays saw them, and "
          "the table runs on to its limit switch on that card",
          "[check][cli][coast]") {
    TempDir dir;
    // Slow-downs 8.983 and 8.984 before the stop 8.985 share every bank digit but the last: the
    // absolute comparer 122' closes at 8.983 and stays closed through 8.985, so the stop sends
    // no impulse of its own to relay 256 and the table never stops (the check of before
    // foresaw a coast and a mismatch on card 2 instead). 0.200 and 0.100 before it are fine.
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
    auto close = run_parsons("check " + q(dir.str("close.csv")));
    INFO(close.output);
    CHECK(close.exit_code == 3);
    CHECK(close.output.find("the machine stops at card 1 (number 0001), table: limit_switch") !=
          std::string::npos);
    CHECK(close.output.find("at 8.983 the absolute comparer 122' met slow-down 1 at 8.983: relay "
                            "256 stepped 236 from speed 1 to speed 2; at 8.985 the increment "
                            "comparer 122'' met the check 8.985 while the absolute comparer 122' "
                            "still conducted from the number before") != std::string::npos);
    CHECK(close.output.find("the counters passed 9.999 and counted on from 0.000") !=
          std::string::npos);
    auto far = run_parsons("check " + q(dir.str("far.csv")));
    CHECK(far.exit_code == 0);
    CHECK(count(far.output, "observed:") == 0);
    // The machine agrees: the close deck stops on card 1, the far one completes.
    auto ran = run_parsons("run -q " + q(dir.str("close.csv")));
    CHECK(ran.exit_code == 3);
    CHECK(ran.output.find("limit_switch: card 1 (number 0001), table") != std::string::npos);
    CHECK(run_parsons("run -q " + q(dir.str("far.csv"))).exit_code == 0);
    // A profile that brakes hard does not help: the stop is never met.
    write_bytes(dir.path("hard.json"), R"({"axes": {"table": {"braking_in_per_s2": 10.0}}})");
    CHECK(run_parsons("check " + q(dir.str("close.csv")) + " --profile " + q(dir.str("hard.json")))
              .exit_code == 3);
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
    CHECK_THAT(run.output, Catch::Contains("warning: table ends -10.0003 in from where its "
                                           "counters say (the lead screw's drive slipped -10.0000 "
                                           "in (fault slip)"));
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
