#include "cardreader/deck_review.hpp"

#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <cmath>

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
        c.axis(a).sequence = static_cast<SequencePattern>(1U << axis_index(a)); // 1, 2 .. 5
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

TEST_CASE("Review: a check that is not the travel in the direction of motion is a warning",
          "[review]") {
    DeckReviewer reviewer;
    CHECK(
        reviewer.review(card_with_table(1, order(Motion::forward, 3, {}, {}, 2000, 2000))).empty());
    auto notes = reviewer.review(card_with_table(2, order(Motion::reverse, 3, {}, {}, 1500, 600)));
    REQUIRE(notes.size() == 1);
    CHECK(notes[0].message == "check 0.600 but the stop 1.500 is 0.500 from the previous stop "
                              "2.000 counting down (motion -) (the counters wrap at 9.999 / "
                              "0.000): the increment comparer will disagree with the absolute one "
                              "and the machine stops");
    // One thousandth off either way is caught.
    for (int check : {499, 501}) {
        DeckReviewer r;
        r.review(card_with_table(1, order(Motion::forward, 3, {}, {}, 2000, 2000)));
        CHECK(r.review(card_with_table(2, order(Motion::reverse, 3, {}, {}, 1500,
                                                static_cast<Thousandths>(check))))
                  .size() == 1);
    }
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

TEST_CASE("Review: motion against the stop with the short check, and an empty sequence pattern",
          "[review]") {
    DeckReviewer reviewer;
    auto o = order(Motion::reverse, 3, {}, {}, 1000, 1000);
    o.sequence = 0;
    auto notes = reviewer.review(card_with_table(1, o));
    REQUIRE(notes.size() == 3);
    CHECK(notes[0].message == "no sequence position punched: the axis never runs (sequence stall)");
    CHECK(notes[1].message == "check 1.000 but the stop 1.000 is 9.000 from the previous stop "
                              "0.000 counting down (motion -) (the counters wrap at 9.999 / "
                              "0.000): the increment comparer will disagree with the absolute one "
                              "and the machine stops; the check is the travel the other way "
                              "round: is the motion column wrong?");
    CHECK(notes[2].message == "sequence stall: position 1 of stepping shaft 280 is answered by no "
                              "running axis (still waiting: table, cross, vertical, swivel and "
                              "tilt): no impulse comes and the shaft never returns home");
}

TEST_CASE("Review: travel is counted modulo 10 inches in the direction of motion", "[review]") {
    CHECK(travel_in_motion(9900, 100, Motion::forward) == 200);
    CHECK(travel_in_motion(100, 9900, Motion::reverse) == 200);
    CHECK(travel_in_motion(100, 9900, Motion::forward) == 9800);
    CHECK(travel_in_motion(9900, 100, Motion::reverse) == 9800);
    CHECK(travel_in_motion(2000, 1500, Motion::reverse) == 500);
    CHECK(travel_in_motion(1500, 2000, Motion::forward) == 500);
    CHECK(travel_in_motion(0, 9999, Motion::reverse) == 1);
    CHECK(travel_in_motion(9999, 0, Motion::forward) == 1);
    CHECK(travel_in_motion(4321, 4321, Motion::reverse) == 0);
}

TEST_CASE("Review: a correct move across 0.000 / 9.999 is silent, both ways", "[review]") {
    DeckReviewer reviewer;
    // Reverse from 0.000 through 9.999 to 9.900, then forward through 0.000 to 0.100.
    CHECK(
        reviewer.review(card_with_table(1, order(Motion::reverse, 3, {}, {}, 9900, 100))).empty());
    CHECK(reviewer.review(card_with_table(2, order(Motion::forward, 3, {}, {}, 100, 200))).empty());
    // With slow-downs on the far side of zero: reverse from 0.100 past 9.980 (0.120 on) and
    // 9.950 (0.150 on) to the stop 9.900 (0.200 on).
    CHECK(reviewer.review(card_with_table(3, order(Motion::reverse, 1, 9980, 9950, 9900, 200)))
              .empty());
    // The old |stop - previous stop| would be 9.800 here: that check is now the wrong one.
    DeckReviewer wrong;
    wrong.review(card_with_table(1, order(Motion::reverse, 3, {}, {}, 9900, 100)));
    auto notes = wrong.review(card_with_table(2, order(Motion::forward, 3, {}, {}, 100, 9800)));
    REQUIRE(notes.size() == 1);
    CHECK(notes[0].message.find("check 9.800 but the stop 0.100 is 0.200 from the previous stop "
                                "9.900 counting up (motion +)") == 0);
}

namespace {

// The patent's pattern: table and cross at 1 and 2, vertical and swivel at 3 and 4, tilt at 5.
CardOrders patterned(const std::array<SequencePattern, 5>& patterns,
                     const std::array<Thousandths, 5>& stops) {
    CardOrders c;
    c.number = 1;
    for (Axis a : kAxes) {
        const auto i = axis_index(a);
        c.axis(a) = order(Motion::forward, 3, {}, {}, stops.at(i), stops.at(i));
        c.axis(a).sequence = patterns.at(i);
    }
    return c;
}

std::vector<std::string> whole_card_notes(const std::vector<ReviewNote>& notes) {
    std::vector<std::string> out;
    for (const auto& n : notes) {
        if (!n.axis) {
            out.push_back(n.message);
        }
    }
    return out;
}

} // namespace

TEST_CASE("Review: the sequence pattern is replayed on shaft 280 (Fig. 10)", "[review][sequence]") {
    const std::array<Thousandths, 5> moving = {100, 200, 300, 400, 500};
    SECTION("the patent's pattern runs through") {
        DeckReviewer r;
        CHECK(r.review(patterned({0b00011, 0b00011, 0b01100, 0b01100, 0b10000}, moving)).empty());
    }
    SECTION("one axis a position runs through") {
        DeckReviewer r;
        CHECK(r.review(patterned({1, 2, 4, 8, 16}, moving)).empty());
    }
    SECTION("two moving axes punched at position 1 only") {
        DeckReviewer r;
        const auto notes = whole_card_notes(
            r.review(patterned({0b00001, 0b00001, 0b01100, 0b01100, 0b10000}, moving)));
        REQUIRE(notes.size() == 2);
        CHECK(notes[0] == "table and cross are punched at position 1 only: the first of them to "
                          "stop steps shaft 280 on to 2, and the others are left short of their "
                          "stops (sequence stall)");
        CHECK(notes[1] == "sequence stall: after table stops, position 2 of stepping shaft 280 is "
                          "answered by no running axis (still waiting: cross, vertical, swivel "
                          "and tilt): no impulse comes and the shaft never returns home");
    }
    SECTION("two idle axes at one position stop together: unit 284 counts both") {
        DeckReviewer r;
        CHECK(r.review(
                   patterned({0b00001, 0b00001, 0b00100, 0b01000, 0b10000}, {0, 0, 300, 400, 500}))
                  .empty());
    }
    SECTION("a position nobody is punched at") {
        DeckReviewer r;
        const auto notes = whole_card_notes(r.review(patterned({1, 2, 4, 16, 16}, moving)));
        REQUIRE(notes.size() == 2); // and swivel and tilt share position 5 only
        CHECK(notes[0].find("swivel and tilt are punched at position 5 only") == 0);
        CHECK(notes[1].find("sequence stall: after table, cross and vertical stop, position 4 ") ==
              0);
    }
    SECTION("a pattern that stalls in one order of stopping only") {
        // Table at 1 only, cross at 1 and 2: if the cross stops first, the table is left short.
        DeckReviewer r;
        const auto notes = whole_card_notes(
            r.review(patterned({0b00001, 0b00011, 0b00100, 0b01000, 0b10000}, moving)));
        REQUIRE(notes.size() == 1);
        CHECK(notes[0] == "sequence may stall, depending on which axis stops first: if they stop "
                          "in this order, after cross stops, position 2 of stepping shaft 280 is "
                          "answered by no running axis (still waiting: table, vertical, swivel "
                          "and tilt): no impulse comes and the shaft never returns home");
    }
}

TEST_CASE("Review: the coast is v^2/2a with the braking deceleration, from the speed at the stop",
          "[review][coast]") {
    AxisDynamics dyn;
    dyn.speed_in_per_s = {0.09, 0.03, 0.01};
    dyn.acceleration_in_per_s2 = 0.2;
    dyn.braking_in_per_s2 = 0.5;
    const double a = dyn.acceleration_in_per_s2;
    // Slow-downs 0.200 and 0.100 before the stop: it reaches the stop at speed 3.
    const auto far = order(Motion::forward, 1, 2800, 2900, 3000, 3000);
    CHECK(speed_at_stop(far, 0, dyn) == Approx(0.01));
    CHECK(coast_in(far, 0, dyn) == Approx(0.01 * 0.01 / (2 * 0.5)));
    // Slow-downs 0.002 and 0.001 before the stop: v^2 falls by 2a per inch only.
    const auto close = order(Motion::forward, 1, 2998, 2999, 3000, 3000);
    const double v2 = 0.09 * 0.09 - 2 * a * 0.001 - 2 * a * 0.001;
    CHECK(speed_at_stop(close, 0, dyn) == Approx(std::sqrt(v2)));
    CHECK(coast_in(close, 0, dyn) == Approx(v2 / (2 * 0.5)));
    // A short move never reaches speed 1: v^2 = 2 a x.
    const auto short_move = order(Motion::forward, 1, {}, {}, 5, 5);
    CHECK(speed_at_stop(short_move, 0, dyn) == Approx(std::sqrt(2 * a * 0.005)));
    // In reverse, across zero: slow-downs counted in the direction of motion.
    const auto across = order(Motion::reverse, 1, 9802, 9801, 9800, 400);
    CHECK(speed_at_stop(across, 200, dyn) == Approx(std::sqrt(v2)));
}

TEST_CASE("Review: a slow-down too close to its stop is a warning, with the coast from the "
          "profile",
          "[review][coast]") {
    AxisDynamics dyn;
    dyn.speed_in_per_s = {0.09, 0.03, 0.01};
    dyn.acceleration_in_per_s2 = 0.2;
    dyn.braking_in_per_s2 = 0.2;
    std::array<AxisDynamics, 5> all{};
    all.fill(dyn);
    DeckReviewer far(all);
    CHECK(
        far.review(card_with_table(1, order(Motion::forward, 1, 8785, 8885, 8985, 8985))).empty());
    DeckReviewer close(all);
    auto notes =
        close.review(card_with_table(1, order(Motion::forward, 1, 8983, 8984, 8985, 8985)));
    REQUIRE(notes.size() == 1);
    const double v2 = 0.09 * 0.09 - 4 * 0.2 * 0.001;
    CHECK(notes[0].message ==
          fmt::format("slow-down too close to the stop: it reaches the stop 8.985 still at {:.2f} "
                      "in/min (speed 3 is 0.60) and coasts about {:.3f} in past it (v^2/2a, "
                      "braking 0.2 in/s^2); the counters count the coast and the next card's "
                      "check will disagree",
                      std::sqrt(v2) * 60, v2 / 0.4));
    // The threshold is one thousandth of coast: braking so that it is just under, and just at.
    for (const auto& [braking, warns] : {std::pair{0.0101 * 0.0101 / 0.002 * 1.0001, false},
                                         std::pair{0.0101 * 0.0101 / 0.002 * 0.9999, true}}) {
        AxisDynamics d = dyn;
        d.speed_in_per_s = {0.0101, 0.0101, 0.0101};
        d.braking_in_per_s2 = braking;
        std::array<AxisDynamics, 5> each{};
        each.fill(d);
        DeckReviewer r(each);
        CHECK(r.review(card_with_table(1, order(Motion::forward, 3, {}, {}, 3000, 3000))).size() ==
              (warns ? 1U : 0U));
    }
}

TEST_CASE("Review: a slow-down on the stop itself is not reached before the stop, one thousandth "
          "short of it is",
          "[review][mutation]") {
    // Only the notes about slow-downs off the way (the shared banks may add their own).
    auto off_the_way = [](const AxisOrder& o) {
        DeckReviewer reviewer;
        std::vector<std::string> found;
        for (const auto& n : reviewer.review(card_with_table(1, o))) {
            if (n.message.find("is not on the way") != std::string::npos) {
                found.push_back(n.message);
            }
        }
        return found;
    };
    // Counting up from 0.000 to 1.000: a second slow-down at 1.000 is the stop's own number.
    CHECK(off_the_way(order(Motion::forward, 1, 900, 1000, 1000, 1000)) ==
          std::vector<std::string>{"second slow-down 1.000 is not on the way from 0.000 to the "
                                   "stop 1.000: the counters never reach it before the stop"});
    CHECK(off_the_way(order(Motion::forward, 1, 900, 999, 1000, 1000)).empty());
    // Counting down through the wrap, from 0.000 to 9.000: slow-down 9.000 is the stop, 9.001
    // comes before it.
    CHECK(off_the_way(order(Motion::reverse, 2, 9000, {}, 9000, 1000)) ==
          std::vector<std::string>{"first slow-down 9.000 is not on the way from 0.000 to the "
                                   "stop 9.000: the counters never reach it before the stop"});
    CHECK(off_the_way(order(Motion::reverse, 2, 9001, {}, 9000, 1000)).empty());
}
