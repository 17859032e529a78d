#include "cardreader/deck_review.hpp"

#include <catch2/catch.hpp>

using namespace parsons::cardreader;

namespace {

AxisOrder order(Motion m, int speed, std::optional<Thousandths> s1, std::optional<Thousandths> s2,
                Thousandths stop, Thousandths check) {
    AxisOrder o;
    o.motion = m;
    o.start_speed = speed;
    o.slow_down = {s1, s2};
    o.stop = stop;
    o.check = check;
    o.sequence = 1;
    return o;
}

CardOrders card_with_table(int number, const AxisOrder& table) {
    CardOrders c;
    c.number = number;
    for (Axis a : kAxes) {
        c.axis(a) = order(Motion::forward, 3, std::nullopt, std::nullopt, 0, 0);
    }
    c.axis(Axis::table) = table;
    return c;
}

} // namespace

TEST_CASE("Shared banks: 8.785 / 8.885 / 8.985 compare equal only at those three numbers "
          "(Fig. 12)",
          "[review][fig12]") {
    auto o = order(Motion::forward, 1, 8785, 8885, 8985, 8985);
    CHECK(shared_bank_matches(o) == std::vector<Thousandths>{8785, 8885, 8985});
    CHECK(spurious_matches_on_path(o, 0).empty());
}

TEST_CASE("Shared banks: stop 9.050 with slow-downs 8.850, 8.950 also matches 8.050 on the way",
          "[review][fig12]") {
    auto o = order(Motion::forward, 1, 8850, 8950, 9050, 9050);
    const auto spurious = spurious_matches_on_path(o, 0);
    REQUIRE_FALSE(spurious.empty());
    CHECK(spurious.front() == 8050);
    // Digits {8,9} {8,9,0} {5} {0}: 8.050 8.850 8.950 9.050 9.850 9.950 ... the ones below 9.050
    // that are not punched: 8.050 only.
    CHECK(spurious == std::vector<Thousandths>{8050});
    DeckReviewer reviewer;
    auto notes = reviewer.review(card_with_table(1, o));
    REQUIRE(notes.size() == 1);
    CHECK(notes[0].axis == Axis::table);
    CHECK(notes[0].message == "shared-bank hazard: the absolute banks 350-356 also compare equal "
                              "at 8.050 on the way from 0.000 to 9.050 (slow-downs and stop "
                              "differ in more than one digit)");
}

TEST_CASE("Review: a check that is not |stop - previous stop| is a warning", "[review]") {
    DeckReviewer reviewer;
    CHECK(
        reviewer.review(card_with_table(1, order(Motion::forward, 3, {}, {}, 2000, 2000))).empty());
    auto notes = reviewer.review(card_with_table(2, order(Motion::reverse, 3, {}, {}, 1500, 600)));
    REQUIRE(notes.size() == 1);
    CHECK(notes[0].message == "check 0.600 but the stop moves 0.500 from the previous stop 2.000 "
                              "(check = |stop - previous stop|): the increment comparer will "
                              "disagree with the absolute one and the machine stops");
}

TEST_CASE("Review: a card number out of order is named with both numbers", "[review]") {
    DeckReviewer reviewer;
    reviewer.review(card_with_table(9999, order(Motion::forward, 3, {}, {}, 0, 0)));
    CHECK(reviewer.review(card_with_table(0, order(Motion::forward, 3, {}, {}, 0, 0))).empty());
    auto notes = reviewer.review(card_with_table(5, order(Motion::forward, 3, {}, {}, 0, 0)));
    REQUIRE(notes.size() == 1);
    CHECK_FALSE(notes[0].axis);
    CHECK(notes[0].message == "card number 0005 follows 0000 (expected 0001): the card-number "
                              "check stops the machine before any axis moves");
}

TEST_CASE("Review: slow-downs that do not match the start speed, or lie past the stop",
          "[review]") {
    DeckReviewer reviewer;
    auto notes = reviewer.review(card_with_table(1, order(Motion::forward, 1, 700, {}, 900, 900)));
    REQUIRE(notes.size() == 1);
    CHECK(notes[0].message == "start speed 1 with 1 slow-down(s) punched (a card punches 3 - start "
                              "speed = 2): speed switch 236 will not stand on speed 3 at the stop");
    DeckReviewer second;
    notes = second.review(card_with_table(1, order(Motion::forward, 2, 1100, {}, 1000, 1000)));
    REQUIRE(notes.size() == 1);
    CHECK(notes[0].message == "first slow-down 1.100 is not on the way from 0.000 to the stop "
                              "1.000: the counters never reach it before the stop");
}

TEST_CASE("Shared banks: a match at the starting position counts: the comparer conducts there",
          "[review][fig12]") {
    // Slow-down 0.500, stop 1.000: banks hold {0,1} {5,0} {0} {0}, so 0.000 also matches.
    auto o = order(Motion::forward, 2, 500, {}, 1000, 1000);
    CHECK(spurious_matches_on_path(o, 0) == std::vector<Thousandths>{0});
    CHECK(spurious_matches_on_path(o, 200).empty());
}

TEST_CASE("Review: motion against the stop and an empty sequence pattern", "[review]") {
    DeckReviewer reviewer;
    auto o = order(Motion::reverse, 3, {}, {}, 1000, 1000);
    o.sequence = 0;
    auto notes = reviewer.review(card_with_table(1, o));
    REQUIRE(notes.size() == 2);
    CHECK(notes[1].message == "motion - (reverse) but the stop 1.000 is above the previous stop "
                              "0.000: the counters count the long way round through 0.000 to "
                              "9.999");
    CHECK(notes[0].message == "no sequence position punched: the axis never runs (sequence stall)");
}
