// Tap cards (an addition after EP 0360190) through the commands: check, show and run refuse
// what the profile cannot tap by card and column, show explains the card, convert carries it
// through every format (the card itself, its listing and its review: tap_card_test.cpp).
#include "tests/tap_support.hpp"
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <filesystem>

using namespace parsons;
using namespace parsons::cardreader;
using parsons::test::deck_with;
using parsons::test::motion_rows;

TEST_CASE("Tap card: check, show and run exit 2 on a tap card the profile cannot tap, naming "
          "card and column, and run refuses before any motion",
          "[tap_card][cli]") {
    test::TempDir dir;
    test::write_bytes(dir.path("tap.csv"),
                      deck_with("2,tap,1,vertical,reverse,0.600,0.05000,240\n"));
    const std::string says = "tap.csv: card 2, column 76: a tap card (an addition after EP "
                             "0360190, Mitsubishi): profile parsons-1952 has no spindle "
                             "synchronisation; the built-in profile parsons-extended has it";
    const auto run = test::run_parsons("run " + test::q(dir.str("tap.csv")) + " -q --events " +
                                       test::q(dir.str("e.jsonl")));
    CHECK(run.exit_code == 2);
    CHECK_THAT(run.output, Catch::Contains(says));
    CHECK_THAT(run.output, Catch::Contains("refused before any motion"));
    CHECK_FALSE(std::filesystem::exists(dir.path("e.jsonl"))); // refused before anything ran
    for (const char* command : {"check", "show"}) {
        INFO(command);
        const auto r = test::run_parsons(std::string(command) + " " + test::q(dir.str("tap.csv")));
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Catch::Contains(says));
    }
    // parsons-extended has spindle synchronisation: the deck has no deck error.
    const auto checked =
        test::run_parsons("check " + test::q(dir.str("tap.csv")) + " --profile parsons-extended");
    INFO(checked.output);
    CHECK(checked.exit_code == 0);

    // What parsons-extended cannot tap: each refused by run and check, by card and column.
    struct Refusal {
        const char* row;
        const char* says;
    };
    const std::vector<Refusal> refusals = {
        {"2,tap,7,vertical,reverse,0.600,0.05000,240\n",
         "card 2, column 2: tap tool 7: no spindle head 31 of profile parsons-extended holds it"},
        // Tool 3's head holds a cutter (radius 0.25 in): a tap card may not feed it as a tap.
        {"2,tap,3,vertical,reverse,0.600,0.02000,240\n",
         "card 2, column 2: tap tool 3: its spindle head 31 holds a cutter, not a tap (profile "
         "parsons-extended)"},
        {"2,tap,1,vertical,reverse,0.600,0.01000,300\n",
         "card 2, column 15: tap speed S 300 rev/min is above spindle motor 27's fastest, 240 "
         "rev/min"},
        {"2,tap,2,vertical,reverse,0.600,0.09000,240\n",
         "card 2, column 10: tap pitch 0.09000 in at S 240 rev/min through tool 2's gear ratio "
         "0.3333 needs the vertical axis to feed 7.20 in/min; the follower drive follows at most "
         "5.4 in/min: at most 0.06750 in per tool revolution at that speed"},
    };
    for (const Refusal& r : refusals) {
        INFO(r.row);
        test::write_bytes(dir.path("bad.csv"), deck_with(r.row));
        for (const char* command : {"run", "check"}) {
            INFO(command);
            const auto out =
                test::run_parsons(std::string(command) + " " + test::q(dir.str("bad.csv")) +
                                  " --profile parsons-extended");
            CHECK(out.exit_code == 2);
            CHECK_THAT(out.output, Catch::Contains(std::string("bad.csv: ") + r.says));
        }
    }

    // The follower drive is the profile's: a slower one refuses the example's 3.0 in/min.
    test::write_bytes(dir.path("slow.json"),
                      R"({"name": "parsons-extended", "sync_drive": {"max_in_per_min": 2.0}})");
    const auto slow = test::run_parsons("run " + test::q(dir.str("tap.csv")) + " -q --profile " +
                                        test::q(dir.str("slow.json")));
    CHECK(slow.exit_code == 2);
    CHECK_THAT(slow.output, Catch::Contains("tap.csv: card 2, column 10: tap pitch 0.05000 in at S "
                                            "240 rev/min through tool 1's gear ratio 0.25 needs "
                                            "the vertical axis to feed 3.00 in/min; the follower "
                                            "drive follows at most 2 in/min: at most 0.03333 in"));
}

TEST_CASE("Tap card: a card the reader cannot read is a bad punch, named by card and column",
          "[tap_card][cli]") {
    // The example with its feed-axis digit 7 and its depth 0000, as a text card image.
    test::TempDir dir;
    std::string line(80, ' ');
    line.replace(1, 17, "01710000050000240");
    line.replace(75, 5, "30012");
    test::write_bytes(dir.path("bad.txt"), line + "\n");
    const auto show =
        test::run_parsons("show " + test::q(dir.str("bad.txt")) + " --profile parsons-extended");
    // show tells the stop the reader would make and exits 0, as for every stop it shows
    // (docs/stop-codes.md); check and run judge it.
    CHECK(show.exit_code == 0);
    CHECK_THAT(show.output, Catch::Contains("bad_punch: card 1, column 4: tap feed axis is 7: "
                                            "expected 1-5"));
    const auto convert = test::run_parsons("convert " + test::q(dir.str("bad.txt")) + " -o " +
                                           test::q(dir.str("bad.csv")));
    CHECK(convert.exit_code == 2);
    CHECK_THAT(convert.output, Catch::Contains("card 1, column 4: tap feed axis is 7"));
    CHECK_FALSE(std::filesystem::exists(dir.path("bad.csv")));
    line.replace(3, 1, "3"); // the vertical axis: now the depth is the fault
    test::write_bytes(dir.path("bad.txt"), line + "\n");
    const auto check =
        test::run_parsons("check " + test::q(dir.str("bad.txt")) + " --profile parsons-extended");
    CHECK(check.exit_code == 3); // the reader stops the machine on it, as on every bad punch
    CHECK_THAT(check.output, Catch::Contains("the machine stops at card 1: bad_punch: card 1, "
                                             "column 6: tap depth is 0000: a tap of depth 0 taps "
                                             "nothing"));
}

TEST_CASE("Tap card: check takes the feed axis its depth into the work and back",
          "[tap_card][cli]") {
    test::TempDir dir;
    // Up to 1.000, tap down 0.600 (to 0.400), then up 0.800 from 1.000 to 1.800.
    test::write_bytes(dir.path("tap.csv"),
                      deck_with("2,tap,1,vertical,reverse,0.600,0.05000,240\n") +
                          motion_rows(3, "1.800", "0.800"));
    const auto inside = test::run_parsons("check " + test::q(dir.str("tap.csv")) +
                                          " --profile parsons-extended --limit vertical=0.3:1.9");
    INFO(inside.output);
    CHECK(inside.exit_code == 0);
    const auto deep = test::run_parsons("check " + test::q(dir.str("tap.csv")) +
                                        " --profile parsons-extended --limit vertical=0.5:1.9");
    CHECK(deep.exit_code == 3);
    CHECK_THAT(deep.output,
               Catch::Contains("card 2 (number 0002): past a limit: vertical taps -0.600 in, from "
                               "1.000 to 0.400 in, past its soft limit 0.500 in"));
    CHECK_THAT(deep.output, Catch::Contains("1 move past a limit"));
    // After the tap the axis stands at 1.000 again: card 3 ends at 1.800, past 1.5.
    const auto after = test::run_parsons("check " + test::q(dir.str("tap.csv")) +
                                         " --profile parsons-extended --limit vertical=0.3:1.5");
    CHECK(after.exit_code == 3);
    CHECK_THAT(after.output,
               Catch::Contains("card 3 (number 0003): past a limit: vertical moves +0.800 in, "
                               "from 1.000 to 1.800 in, past its soft limit"));
    CHECK_THAT(after.output, Catch::Contains("1 move past a limit"));
}

TEST_CASE("Tap card: show explains it field by field, in --json and as a picture",
          "[tap_card][cli]") {
    test::TempDir dir;
    test::write_bytes(dir.path("tap.csv"),
                      deck_with("2,tap,1,vertical,reverse,0.600,0.05000,240\n"));
    const auto text =
        test::run_parsons("show " + test::q(dir.str("tap.csv")) +
                          " --profile parsons-extended --svg " + test::q(dir.str("cards")));
    INFO(text.output);
    CHECK(text.exit_code == 0);
    for (const char* says :
         {"card 2 · card number 0002 (columns 77-80) · TAP CARD (column 76 row 3; an addition "
          "after EP 0360190, Mitsubishi)",
          "2-3      tap tool       T01: PC 130 puts on the spindle head that holds it",
          "4        tap feed axis  3: the vertical axis feeds in step with the tool",
          "5        tap sense      row 1: reverse into the work (its counters count down)",
          "6-9      tap depth      0.600 in into the work, and back out as the spindle reverses",
          "10-14    tap pitch      0.05000 in per tool revolution",
          "15-18    tap speed      S 240 rev/min of spindle motor 27",
          "the tool turns S x A = 240 x 0.25 = 60.0 rev/min (A: head 1's gear ratio in profile "
          "parsons-extended), so the vertical axis feeds 0.05000 x 60.0 = 3.00 in/min"}) {
        CHECK_THAT(text.output, Catch::Contains(says));
    }
    const std::string svg = test::read_bytes(dir.path("cards/card-0002.svg"));
    for (const char* label :
         {"TOOL T", "AXIS", "SENSE", "DEPTH", "PITCH", "SPEED S", "TAP (EP 0360190)", "EXTENSION",
          "CARD NO.", "tap card (an addition after EP 0360190)"}) {
        CHECK_THAT(svg, Catch::Contains(label));
    }
    CHECK_THAT(svg, !Catch::Contains("SLOW 1"));
    CHECK_THAT(svg, !Catch::Contains("F/PULSE"));
    CHECK_THAT(test::read_bytes(dir.path("cards/card-0001.svg")), Catch::Contains("SLOW 1"));

    const auto json = test::run_parsons("show " + test::q(dir.str("tap.csv")) +
                                        " --profile parsons-extended --json");
    CHECK(json.exit_code == 0);
    const auto doc = nlohmann::json::parse(json.output);
    const auto& card = doc.at("cards").at(1);
    CHECK(card.at("kind") == "tap");
    CHECK(card.at("number") == 2);
    CHECK(card.at("tool") == 1);
    CHECK(card.at("axis") == "vertical");
    CHECK(card.at("sense") == "reverse");
    CHECK(card.at("depth").get<double>() == Approx(0.6));
    CHECK(card.at("pitch").get<double>() == Approx(0.05));
    CHECK(card.at("rpm") == 240);
    // docs/json-output.md names each of them.
    const std::string keys = test::read_bytes(test::source_path("docs/json-output.md"));
    for (const auto& [key, value] : card.items()) {
        INFO(key);
        CHECK_THAT(keys, Catch::Contains("`" + key + "`"));
    }
    CHECK_THAT(keys, Catch::Contains("`\"tap\"`"));
}

TEST_CASE("Tap card: convert carries it through every format and back to the same listing, "
          "and .five refuses it as it refuses every card with column 76 punched",
          "[tap_card][cli]") {
    test::TempDir dir;
    const std::string deck = deck_with("2,tap,1,vertical,reverse,0.600,0.05000,240\n"
                                       "3,tap,99,tilt,forward,9.999,0.99999,9999\n");
    test::write_bytes(dir.path("tap.csv"), deck);
    for (const char* medium : {"cbn", "txt", "bin", "tape"}) {
        INFO(medium);
        const std::string cards = dir.str(std::string("tap.") + medium);
        const std::string back = dir.str(std::string("back-") + medium + ".csv");
        CHECK(test::run_parsons("convert " + test::q(dir.str("tap.csv")) + " -o " + test::q(cards))
                  .exit_code == 0);
        CHECK(test::run_parsons("convert " + test::q(cards) + " -o " + test::q(back)).exit_code ==
              0);
        CHECK(test::read_bytes(back) == deck);
    }
    // Every column of a tap card is one digit punch: a text card image keeps it as characters.
    const auto lines = test::lines_of(test::read_bytes(dir.path("tap.txt")));
    REQUIRE(lines.size() == 3);
    CHECK(lines.at(1) == " 01310600050000240" + std::string(57, ' ') + "30002");
    CHECK(lines.at(2) == " 99509999999999999" + std::string(57, ' ') + "30003");

    const auto five = test::run_parsons("convert " + test::q(dir.str("tap.csv")) + " -o " +
                                        test::q(dir.str("tap.five")));
    CHECK(five.exit_code == 2);
    CHECK_THAT(five.output, Catch::Contains("card 2: column 76 is punched, but the five-card "
                                            "layout carries no field of that column"));
    CHECK_FALSE(std::filesystem::exists(dir.path("tap.five")));
}
