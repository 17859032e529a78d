// `parsons show` and `parsons check` do not mislead (issue 11, item 6; issue 29): what they say
// the machine does is what a run of the deck does, told from its relays; and the run report's
// position error counts the counters' wrap-arounds.
#include "outputs/report/machine_story.hpp"
#include "tests/machine_support.hpp"
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

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

namespace {

// The story of a run (outputs/report/machine_story.hpp) heard from signals made by hand: the
// table's motor 38 and the inches switch 104 of its absolute counter, each turn of which is one
// phrase of the table's tale ("the counters passed 9.999 ...").
struct HeardStory {
    cli::MachineStory story;
    relaylogic::SignalId motor = 0;
    relaylogic::SignalId inches = 1;
    double t = 0;

    HeardStory() {
        story.on_signal_defined({motor, "table", "motor_38", "motor 38", "38", 1}, 0);
        story.on_signal_defined({inches, "table", "absolute_counter_104", "switch 104", "104", 4},
                                0);
    }
    // Card `index` (number `index`) read; the table's motor starts (one phrase) and its
    // counters go round `turns` times (one phrase each).
    void card(std::int64_t index, int turns) {
        story.on_card(t, index, test::idle_card(static_cast<int>(index), {0, 0, 0, 0, 0}));
        story.on_signal(t += 1, motor, 0, 1);
        for (int i = 0; i < turns; ++i) {
            story.on_signal(t += 1, inches, 9, 0);
        }
    }
    std::vector<std::string> stop(std::int64_t card, std::optional<cardreader::Axis> axis) {
        relaylogic::StopInfo s;
        s.reason =
            axis ? relaylogic::StopReason::limit_switch : relaylogic::StopReason::sequence_stall;
        s.card = card;
        s.card_number = static_cast<int>(card);
        s.axis = axis;
        s.message = "stopped";
        story.on_stop(t, s);
        story.on_finish(t);
        return story.stop_chain();
    }
};

} // namespace

TEST_CASE("Stop chain: an axis's tale is shortened only where that leaves out two events or more, "
          "never one",
          "[check][story]") {
    // Its first 4 phrases and last 8 are told; 13 phrases are told whole (a "... 1 more events
    // ..." would hide one event behind a line as long as it), 14 leave out 2.
    HeardStory whole;
    whole.card(1, 12); // 13 phrases
    const auto told = whole.stop(1, cardreader::Axis::table);
    REQUIRE(told.size() == 2);
    CHECK(count(told[0], "the counters passed 9.999") == 12);
    CHECK(told[0].find("more events") == std::string::npos);

    HeardStory shortened;
    shortened.card(1, 13); // 14 phrases
    const auto cut = shortened.stop(1, cardreader::Axis::table);
    REQUIRE(cut.size() == 2);
    CHECK(count(cut[0], "the counters passed 9.999") == 11);
    // The head (the motor and 3 turns), the line that stands for the 2 left out, the tail (8).
    const std::string turn = "the counters passed 9.999 and counted on from 0.000, 10 inches on";
    CHECK_THAT(cut[0], Catch::EndsWith("at 0.000; " + turn + "; " + turn + "; " + turn +
                                       "; ... 2 more events ...; " + turn + "; " + turn + "; " +
                                       turn + "; " + turn + "; " + turn + "; " + turn + "; " +
                                       turn + "; " + turn));
}

TEST_CASE("Stop chain: the card before the stop's card is told first, then the stop's card, then "
          "the stop",
          "[check][story]") {
    HeardStory s;
    s.card(1, 1);
    s.card(2, 2);
    const auto chain = s.stop(2, cardreader::Axis::table);
    REQUIRE(chain.size() == 3);
    CHECK(chain[0].rfind("card 1 (number 0001), table: motor 38 started", 0) == 0);
    CHECK(count(chain[0], "the counters passed") == 1);
    CHECK(chain[1].rfind("card 2 (number 0002), table: motor 38 started", 0) == 0);
    CHECK(count(chain[1], "the counters passed") == 2);
    CHECK(chain[2].rfind("the machine stopped: limit_switch: stopped", 0) == 0);
}

TEST_CASE("Stop chain: a stop of no axis is told from its own card alone, not the card before",
          "[check][story]") {
    HeardStory s;
    s.card(1, 1);
    s.card(2, 0);
    const auto chain = s.stop(2, std::nullopt);
    REQUIRE(chain.size() == 2);
    CHECK(chain[0].rfind("card 2 (number 0002), table: motor 38 started", 0) == 0);
    CHECK(chain[1].rfind("the machine stopped: sequence_stall: stopped", 0) == 0);
    for (const std::string& line : chain) {
        CHECK(line.find("card 1 (number 0001)") == std::string::npos);
    }
}

TEST_CASE("Check, show and the summary: an axis that ends a whole turn of its counters from where "
          "its cards put it is warned of, from the run's own count",
          "[check][show][report][cli]") {
    TempDir dir;
    // Card 2 moves the table 0.003 from 0.001 on speed 1, its slow-downs 0.002 and 0.003: the
    // motor has barely started when slow-down 1 steps 236, and delay 258 (0.150 s) still holds
    // channel 257 open as the counters pass 0.003 and 0.004. The table runs on, round the
    // counters, until they read 0.003 and 0.004 again: 10 inches on. Every 1952 check agrees
    // (the counters read the card's number, the increment counter its check).
    write_bytes(dir.path("turn.csv"),
                std::string(kHeader) + "1,0,table,+,3,,,0.001,0.001,1\n" + idle_rest(1) +
                    "2,0,table,+,1,0.002,0.003,0.004,0.003,1\n" + idle_rest(2));
    const std::string deck = q(dir.str("turn.csv"));
    const std::string said = "ends +10.000 in from where its cards put it: the cards ordered "
                             "0.004 in, the part is at 10.00425 in; its counters read 0.004, the "
                             "card's number, having gone round once more than the cards ordered";
    const auto run = run_parsons("run " + deck);
    INFO(run.output);
    CHECK(run.exit_code == 0); // the machine completes: faithful to the relays
    CHECK_THAT(run.output, Catch::Contains("warning: table " + said));
    CHECK(count(run.output, "from where its cards put it") == 1);

    const auto check = run_parsons("check " + deck);
    INFO(check.output);
    CHECK(check.exit_code == 0);
    CHECK_THAT(check.output, Catch::Contains("card 2 (number 0002): observed: table: " + said));
    CHECK_THAT(check.output, Catch::Contains("1 observed"));
    const auto json = nlohmann::json::parse(run_parsons("check " + deck + " --json").output);
    bool found = false;
    for (const auto& f : json["findings"]) {
        if (f["kind"] == "observed" && f["axis"] == "table" && f["card"] == 2 && f["number"] == 2 &&
            f["message"].get<std::string>().rfind("ends +10.000 in", 0) == 0) {
            found = true;
        }
    }
    CHECK(found);

    const auto show = run_parsons("show " + deck);
    INFO(show.output);
    CHECK_THAT(show.output, Catch::Contains(said));

    SECTION("a deck that crosses zero both ways and ends where its cards put it is not warned "
            "of") {
        // 9.000 forward, 9.400 back through zero (the part at -0.400, the counters at 9.600),
        // and 9.900 forward through zero again to 9.500.
        write_bytes(dir.path("ok.csv"), std::string(kHeader) + "1,0,table,+,3,,,9.000,9.000,1\n" +
                                            idle_rest(1) + "2,0,table,-,3,,,9.600,9.400,1\n" +
                                            idle_rest(2) + "3,0,table,+,3,,,9.500,9.900,1\n" +
                                            idle_rest(3));
        const auto ok = run_parsons("run " + q(dir.str("ok.csv")));
        INFO(ok.output);
        CHECK(ok.exit_code == 0);
        CHECK(count(ok.output, "warning") == 0);
        const auto quiet = run_parsons("check " + q(dir.str("ok.csv")));
        INFO(quiet.output);
        CHECK(quiet.exit_code == 0);
        CHECK(count(quiet.output, "observed:") == 0);
    }
}
