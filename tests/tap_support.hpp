// Listing rows for the tap-card tests (an addition after EP 0360190): a motion card of the
// vertical axis, and a deck that taps after it.
#pragma once

#include "cardreader/listing_format.hpp"
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <string>

namespace parsons::test {

// The pitches of the two taps of the tapping tests (inches a turn).
inline constexpr double kPitch1 = 0.05;   // tool 1's tap, head ratio 1/4
inline constexpr double kPitch2 = 0.0625; // tool 2's tap, head ratio 1/3

// One motion card's five listing rows: the vertical axis forward to `stop` with check `check`,
// the others idle, each axis at its own sequence position.
inline std::string motion_rows(int card, const char* stop, const char* check) {
    std::string rows;
    rows += fmt::format("{},0,table,+,3,,,0.000,0.000,1\n", card);
    rows += fmt::format("{},0,cross,+,3,,,0.000,0.000,2\n", card);
    rows += fmt::format("{},0,vertical,+,3,,,{},{},3\n", card, stop, check);
    rows += fmt::format("{},0,swivel,+,3,,,0.000,0.000,4\n", card);
    rows += fmt::format("{},0,tilt,+,3,,,0.000,0.000,5\n", card);
    return rows;
}

// A deck: the vertical axis up to 1.000 in, then the tap row given.
inline std::string deck_with(const std::string& tap_row_text) {
    return std::string(cardreader::kListingHeader) + "\n" + motion_rows(1, "1.000", "1.000") +
           tap_row_text;
}

// The deck of one tap row (deck_with) written to DIR/tap.csv, punched to tap.cbn (exit 0), that
// converted back to a listing holding the row as it was, and shown under parsons-extended (exit
// 0): returns what show printed.
inline std::string tap_row_round_trip(const TempDir& dir, const std::string& row) {
    write_bytes(dir.path("tap.csv"), deck_with(row));
    const auto punched =
        run_parsons("punch " + q(dir.str("tap.csv")) + " -o " + q(dir.str("tap.cbn")));
    INFO(punched.output);
    REQUIRE(punched.exit_code == 0);
    const auto back =
        run_parsons("convert " + q(dir.str("tap.cbn")) + " -o " + q(dir.str("back.csv")));
    REQUIRE(back.exit_code == 0);
    CHECK_THAT(read_bytes(dir.path("back.csv")), Catch::Contains(row));
    const auto shown = run_parsons("show " + q(dir.str("tap.cbn")) + " --profile parsons-extended");
    CHECK(shown.exit_code == 0);
    return shown.output;
}

} // namespace parsons::test
