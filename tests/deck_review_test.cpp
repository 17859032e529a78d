#include "cardreader/deck_review.hpp"

#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <optional>
#include <random>
#include <vector>

using namespace parsons::cardreader;

namespace {

AxisOrder review_order(Motion m, int speed, std::optional<Thousandths> s1,
                       std::optional<Thousandths> s2, Thousandths stop, Thousandths check) {
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
        c.axis(a) = review_order(Motion::forward, 3, std::nullopt, std::nullopt, 0, 0);
        c.axis(a).sequence = static_cast<SequencePattern>(1U << axis_index(a)); // 1, 2 .. 5
    }
    c.axis(Axis::table) = table;
    return c;
}

} // namespace

TEST_CASE("Shared banks: 8.785 / 8.885 / 8.985 compare equal only at those three numbers "
          "(Fig. 12)",
          "[review][fig12]") {
    auto o = review_order(Motion::forward, 1, 8785, 8885, 8985, 8985);
    CHECK(shared_bank_matches(o) == std::vector<Thousandths>{8785, 8885, 8985});
    CHECK(spurious_matches_on_path(o, 0).empty());
}

TEST_CASE("Shared banks: stop 9.050 with slow-downs 8.850, 8.950 also matches 8.050 on the way",
          "[review][fig12]") {
    auto o = review_order(Motion::forward, 1, 8850, 8950, 9050, 9050);
    const auto spurious = spurious_matches_on_path(o, 0);
    REQUIRE_FALSE(spurious.empty());
    CHECK(spurious.front() == 8050);
    // Digits {8,9} {8,9,0} {5} {0}: 8.050 8.850 8.950 9.050 9.850 9.950 ... the ones below 9.050
    // that are not punched: 8.050 only.
    CHECK(spurious == std::vector<Thousandths>{8050});
    // The review gives no prediction of it (the run does: tests/check_command_test.cpp).
    DeckReviewer reviewer;
    CHECK(reviewer.review(card_with_table(1, o)).empty());
}

TEST_CASE("Review: advice on slow-downs that do not match the start speed, or lie past the stop",
          "[review]") {
    DeckReviewer reviewer;
    auto notes =
        reviewer.review(card_with_table(1, review_order(Motion::forward, 1, 700, {}, 900, 900)));
    REQUIRE(notes.size() == 1);
    CHECK(notes[0].message == "start speed 1 with 1 slow-down(s) punched: a card punches 3 - start "
                              "speed = 2 of them, one for each step of speed switch 236 to speed "
                              "3");
    DeckReviewer second;
    notes =
        second.review(card_with_table(1, review_order(Motion::forward, 2, 1100, {}, 1000, 1000)));
    REQUIRE(notes.size() == 1);
    CHECK(notes[0].message ==
          "first slow-down 1.100 is not on the way from the stop before, 0.000, "
          "to the stop 1.000");
}

TEST_CASE("Shared banks: a match at the starting position counts: the comparer conducts there",
          "[review][fig12]") {
    // Slow-down 0.500, stop 1.000: banks hold {0,1} {5,0} {0} {0}, so 0.000 also matches.
    auto o = review_order(Motion::forward, 2, 500, {}, 1000, 1000);
    CHECK(spurious_matches_on_path(o, 0) == std::vector<Thousandths>{0});
    CHECK(spurious_matches_on_path(o, 200).empty());
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
    CHECK(reviewer.review(card_with_table(1, review_order(Motion::reverse, 3, {}, {}, 9900, 100)))
              .empty());
    CHECK(reviewer.review(card_with_table(2, review_order(Motion::forward, 3, {}, {}, 100, 200)))
              .empty());
    // With slow-downs on the far side of zero: reverse from 0.100 past 9.980 (0.120 on) and
    // 9.950 (0.150 on) to the stop 9.900 (0.200 on).
    CHECK(
        reviewer.review(card_with_table(3, review_order(Motion::reverse, 1, 9980, 9950, 9900, 200)))
            .empty());
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
    CHECK(off_the_way(review_order(Motion::forward, 1, 900, 1000, 1000, 1000)) ==
          std::vector<std::string>{"second slow-down 1.000 is not on the way from the stop "
                                   "before, 0.000, to the stop 1.000"});
    CHECK(off_the_way(review_order(Motion::forward, 1, 900, 999, 1000, 1000)).empty());
    // Counting down through the wrap, from 0.000 to 9.000: slow-down 9.000 is the stop, 9.001
    // comes before it.
    CHECK(off_the_way(review_order(Motion::reverse, 2, 9000, {}, 9000, 1000)) ==
          std::vector<std::string>{"first slow-down 9.000 is not on the way from the stop "
                                   "before, 0.000, to the stop 9.000"});
    CHECK(off_the_way(review_order(Motion::reverse, 2, 9001, {}, 9000, 1000)).empty());
}

TEST_CASE("Shared banks: the matches are every number whose each digit a punched number closes "
          "in its bank, ascending, and the generator's test finds a spurious one exactly when "
          "the list has one",
          "[review][fig12]") {
    std::mt19937 rng(51);
    std::uniform_int_distribution<int> number(0, 9999);
    std::uniform_int_distribution<int> speed(1, 3);
    for (int n = 0; n < 400; ++n) {
        const int start = speed(rng);
        const std::optional<Thousandths> s1 =
            start <= 2 ? std::optional(static_cast<Thousandths>(number(rng))) : std::nullopt;
        const std::optional<Thousandths> s2 =
            start == 1 ? std::optional(static_cast<Thousandths>(number(rng))) : std::nullopt;
        const auto stop = static_cast<Thousandths>(number(rng));
        const auto o =
            review_order(n % 2 == 0 ? Motion::forward : Motion::reverse, start, s1, s2, stop, stop);
        // The rule itself, number by number (Fig. 12: each bank compares one digit).
        std::vector<Thousandths> punched = {stop};
        for (const auto& s : {s1, s2}) {
            if (s) {
                punched.push_back(*s);
            }
        }
        std::vector<Thousandths> expected;
        for (int m = 0; m < 10000; ++m) {
            bool every_digit = true;
            for (int place = 1; place <= 1000; place *= 10) {
                bool closed = false;
                for (Thousandths p : punched) {
                    closed = closed || (p / place) % 10 == (m / place) % 10;
                }
                every_digit = every_digit && closed;
            }
            if (every_digit) {
                expected.push_back(static_cast<Thousandths>(m));
            }
        }
        INFO("order " << n);
        REQUIRE(shared_bank_matches(o) == expected);
        const auto from = static_cast<Thousandths>(number(rng));
        CHECK(spurious_match_on_path(o, from) == !spurious_matches_on_path(o, from).empty());
    }
}
