// Sync cards on the command line: check, show and run refuse a sync card the profile cannot
// take, naming card and column, and run refuses before any motion (split from
// tests/sync_card_test.cpp, which keeps the card, its listing and its review).
#include "tests/card_support.hpp"
#include "tests/test_support.hpp"

#include "cardreader/listing_format.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

TEST_CASE("Sync card: check, show and run exit 2 on a sync card under parsons-1952, naming card "
          "and column, and run refuses before any motion",
          "[sync_card][cli]") {
    parsons::test::TempDir dir;
    const std::string header = std::string(parsons::cardreader::kListingHeader) + "\n";
    const std::string deck = header + "1,sync,position,30\n1,sync,speed,table,0.00100\n" +
                             parsons::test::table_cross_rows(2, "0.100", "0.100");
    parsons::test::write_bytes(dir.path("sync.csv"), deck);
    const std::string says = "sync.csv: card 1, column 76: a sync card (an addition after EP "
                             "0436887, Mitsubishi): profile parsons-1952 has no press "
                             "synchronisation; the built-in profile parsons-extended has it";
    const auto run =
        parsons::test::run_parsons("run " + parsons::test::q(dir.str("sync.csv")) +
                                   " -q --events " + parsons::test::q(dir.str("e.jsonl")));
    CHECK(run.exit_code == 2);
    CHECK_THAT(run.output, Catch::Contains(says));
    CHECK_FALSE(std::filesystem::exists(dir.path("e.jsonl"))); // refused before anything ran
    for (const char* command : {"check", "show"}) {
        INFO(command);
        const auto r = parsons::test::run_parsons(std::string(command) + " " +
                                                  parsons::test::q(dir.str("sync.csv")));
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Catch::Contains(says));
    }
    // parsons-extended has press synchronisation: the deck has no deck error.
    const auto checked = parsons::test::run_parsons(
        "check " + parsons::test::q(dir.str("sync.csv")) + " --profile parsons-extended");
    INFO(checked.output);
    CHECK(checked.exit_code == 0);

    // A travel the drive cannot follow: run refuses it under parsons-extended too.
    parsons::test::write_bytes(dir.path("fast.csv"),
                               header + "1,sync,speed,table,0.01000\n" +
                                   parsons::test::table_cross_rows(2, "0.100", "0.100"));
    const auto fast = parsons::test::run_parsons("run " + parsons::test::q(dir.str("fast.csv")) +
                                                 " -q --profile parsons-extended");
    CHECK(fast.exit_code == 2);
    CHECK_THAT(fast.output, Catch::Contains("fast.csv: card 1, column 16: table travel per pulse "
                                            "0.01000 in needs 28.8 in/min"));
}

TEST_CASE("Sync card: run refuses a deck whose only addition's card comes after its motion "
          "cards, naming that card, before any motion",
          "[sync_card][cli]") {
    // The review before a run reads the cards through to find an addition's card and decodes
    // nothing when there is none (cli/support/deck_files.cpp): one after three motion cards is
    // still found.
    parsons::test::TempDir dir;
    const std::string deck = std::string(parsons::cardreader::kListingHeader) + "\n" +
                             parsons::test::table_cross_rows(1, "0.100", "0.100") +
                             parsons::test::table_cross_rows(2, "0.200", "0.100") +
                             parsons::test::table_cross_rows(3, "0.300", "0.100") +
                             "4,sync,position,30\n4,sync,speed,table,0.00100\n" +
                             parsons::test::table_cross_rows(5, "0.400", "0.100");
    parsons::test::write_bytes(dir.path("late.csv"), deck);
    const auto run =
        parsons::test::run_parsons("run " + parsons::test::q(dir.str("late.csv")) +
                                   " -q --events " + parsons::test::q(dir.str("e.jsonl")));
    CHECK(run.exit_code == 2);
    CHECK_THAT(run.output, Catch::Contains("late.csv: card 4, column 76: a sync card"));
    CHECK_FALSE(std::filesystem::exists(dir.path("e.jsonl")));
}
