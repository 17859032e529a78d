// Tap cards, an addition after EP 0360190 (Mitsubishi): the card (column 76 row 3),
// its listing row, its picture and the deck review's refusals (through the commands:
// tap_card_cli_test.cpp). What motor
// 27, PC 130 and the feed do with a tap card while the machine runs is relaylogic's and is
// tested there.
#include "tests/card_support.hpp"
#include "tests/machine_support.hpp"
#include "tests/tap_support.hpp"
#include "tests/test_support.hpp"

#include "cardreader/deck_error.hpp"
#include "cardreader/deck_review.hpp"
#include "cardreader/listing_format.hpp"
#include "cardreader/tap_card.hpp"
#include "cardreader/tap_listing.hpp"
#include "cardreader/tap_review.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <functional>
#include <map>
#include <random>
#include <sstream>

using namespace parsons;
using namespace parsons::cardreader;
using parsons::test::deck_with;
using parsons::test::idle_card;
using parsons::test::listing_error;
using parsons::test::motion_rows;
using parsons::test::order;
using parsons::test::review_all;

using parsons::test::digit;
using parsons::test::punched;

namespace {

TapOrder tap(int tool, Axis axis, Motion motion, int depth, int pitch, int rpm) {
    TapOrder t;
    t.tool = tool;
    t.axis = axis;
    t.motion = motion;
    t.depth = static_cast<Thousandths>(depth);
    t.pitch = pitch;
    t.rpm = rpm;
    return t;
}

// The brief's example: card 12, tool 1, the vertical axis down (reverse) 0.600 in, 0.05000 in
// per tool revolution at 240 rev/min.
TapOrder example() {
    return tap(1, Axis::vertical, Motion::reverse, 600, 5000, 240);
}

CardOrders tap_orders(int number, const TapOrder& t) {
    CardOrders c;
    c.kind = CardKind::tap;
    c.number = number;
    c.tap = t;
    return c;
}

// A motion card that takes the vertical axis from `from` to `to` (thousandths), the others idle.
CardOrders vertical_move(int number, int from, int to) {
    CardOrders c = idle_card(number, {0, 0, from, 0, 0});
    c.axis(Axis::vertical) = order(from, to, 3, {}, {}, 4);
    return c;
}

std::vector<ReviewNote> deck_errors(const std::vector<ReviewNote>& notes) {
    std::vector<ReviewNote> errors;
    for (const ReviewNote& n : notes) {
        if (n.deck_error) {
            errors.push_back(n);
        }
    }
    return errors;
}

} // namespace

TEST_CASE("Tap card: the example order is punched in its columns hole by hole, column 76 row 3 "
          "marking it, and read back",
          "[tap_card][card]") {
    const CardOrders card = tap_orders(12, example());
    const Card c = punched(card);
    // Every column of the card: the holes expected, blank elsewhere. The digit fields: tool
    // 01, the vertical axis (3), 0.600 in, 0.05000 in per revolution, 240 rev/min, card 0012.
    std::map<int, ColumnWord> expected;
    for (const auto& [first, digits] : std::vector<std::pair<int, std::string>>{
             {2, "01"}, {4, "3"}, {6, "0600"}, {10, "05000"}, {15, "0240"}, {77, "0012"}}) {
        for (std::size_t i = 0; i < digits.size(); ++i) {
            expected[first + static_cast<int>(i)] = digit(digits.at(i) - '0');
        }
    }
    expected[5] = row_bit(Row::r1);  // reverse into the work
    expected[76] = row_bit(Row::r3); // the mark
    for (int col = 1; col <= kColumns; ++col) {
        INFO("column " << col);
        const auto it = expected.find(col);
        CHECK(c.column(col) == (it == expected.end() ? ColumnWord{0} : it->second));
    }
    CHECK(is_tap_card(c, fig8_layout()));
    CHECK_FALSE(is_sync_card(c, fig8_layout()));
    CHECK_FALSE(is_condition_card(c, fig8_layout()));
    CHECK(is_extension_card(c, fig8_layout()));
    CHECK_FALSE(is_tap_card(punched(vertical_move(1, 0, 100)), fig8_layout()));

    const DecodeResult d = decode(c, fig8_layout());
    REQUIRE(d);
    CHECK(d.orders == card);
    CHECK(d.orders.kind == CardKind::tap);

    // The convenience the job generator uses gives the same card.
    const EncodeResult direct = tap_card(example(), 12);
    REQUIRE(direct);
    CHECK(direct.card == c);
}

TEST_CASE("Tap card: each field changes only its own columns", "[tap_card][card]") {
    const Card base = punched(tap_orders(12, example()));
    struct Case {
        const char* what;
        std::function<void(TapOrder&)> change;
        int first;
        std::vector<ColumnWord> holes;
    };
    const std::vector<Case> cases = {
        {"tool 99", [](TapOrder& t) { t.tool = 99; }, 2, {digit(9), digit(9)}},
        {"tool 10", [](TapOrder& t) { t.tool = 10; }, 2, {digit(1), digit(0)}},
        {"the table", [](TapOrder& t) { t.axis = Axis::table; }, 4, {digit(1)}},
        {"the cross", [](TapOrder& t) { t.axis = Axis::cross; }, 4, {digit(2)}},
        {"the swivel", [](TapOrder& t) { t.axis = Axis::swivel; }, 4, {digit(4)}},
        {"the tilt", [](TapOrder& t) { t.axis = Axis::tilt; }, 4, {digit(5)}},
        {"forward", [](TapOrder& t) { t.motion = Motion::forward; }, 5, {row_bit(Row::r0)}},
        {"depth 9.999",
         [](TapOrder& t) { t.depth = 9999; },
         6,
         {digit(9), digit(9), digit(9), digit(9)}},
        {"depth 0.001",
         [](TapOrder& t) { t.depth = 1; },
         6,
         {digit(0), digit(0), digit(0), digit(1)}},
        {"pitch 0.99999",
         [](TapOrder& t) { t.pitch = kMaxPitch; },
         10,
         {digit(9), digit(9), digit(9), digit(9), digit(9)}},
        {"pitch 0.01234",
         [](TapOrder& t) { t.pitch = 1234; },
         10,
         {digit(0), digit(1), digit(2), digit(3), digit(4)}},
        {"speed 9999",
         [](TapOrder& t) { t.rpm = 9999; },
         15,
         {digit(9), digit(9), digit(9), digit(9)}},
        {"speed 1", [](TapOrder& t) { t.rpm = 1; }, 15, {digit(0), digit(0), digit(0), digit(1)}},
    };
    for (const Case& k : cases) {
        INFO(k.what);
        TapOrder t = example();
        k.change(t);
        const Card c = punched(tap_orders(12, t));
        const int last = k.first + static_cast<int>(k.holes.size()) - 1;
        for (int col = 1; col <= kColumns; ++col) {
            INFO("column " << col);
            if (col >= k.first && col <= last) {
                CHECK(c.column(col) == k.holes.at(static_cast<std::size_t>(col - k.first)));
            } else {
                CHECK(c.column(col) == base.column(col));
            }
        }
        CHECK(decode(c, fig8_layout()).orders.tap == t);
    }
}

TEST_CASE("Tap card: random orders are punched and read back the same, as cards and as listing "
          "rows",
          "[tap_card][card][listing]") {
    std::mt19937 rng(360190);
    auto uniform = [&rng](int lo, int hi) {
        return std::uniform_int_distribution<int>(lo, hi)(rng);
    };
    for (int i = 0; i < 2000; ++i) {
        const TapOrder t =
            tap(uniform(1, kMaxTapTool), kAxes.at(static_cast<std::size_t>(uniform(0, 4))),
                uniform(0, 1) == 0 ? Motion::forward : Motion::reverse, uniform(1, 9999),
                uniform(1, kMaxPitch), uniform(1, kMaxTapRpm));
        const CardOrders o = tap_orders(uniform(0, 9999), t);
        INFO(tap_row(o));
        const DecodeResult d = decode(punched(o), fig8_layout());
        REQUIRE(d);
        REQUIRE(d.orders == o);
        const auto [number, back] = read_tap_row(tap_row(o), "r.csv", 1);
        REQUIRE(number == o.number);
        REQUIRE(back == t);
    }
}

TEST_CASE("Tap card: orders no card can hold are refused by the keypunch", "[tap_card][card]") {
    auto error_of = [](TapOrder t) {
        const EncodeResult e = encode(tap_orders(1, t), fig8_layout());
        return e.error.value_or("no error");
    };
    auto with = [](std::function<void(TapOrder&)> change) {
        TapOrder t = example();
        change(t);
        return t;
    };
    CHECK(error_of(example()) == "no error");
    CHECK_THAT(error_of(with([](TapOrder& t) { t.tool = 0; })),
               Catch::Contains("tap tool 0 is not 1..99"));
    CHECK_THAT(error_of(with([](TapOrder& t) { t.tool = 100; })),
               Catch::Contains("tap tool 100 is not 1..99"));
    CHECK_THAT(error_of(with([](TapOrder& t) { t.axis = static_cast<Axis>(5); })),
               Catch::Contains("tap feed axis 5 is none of the five axes"));
    CHECK_THAT(error_of(with([](TapOrder& t) { t.depth = 0; })),
               Catch::Contains("tap depth 0 is not 0.001..9.999 in"));
    CHECK_THAT(error_of(with([](TapOrder& t) { t.depth = 10000; })),
               Catch::Contains("tap depth 10000"));
    CHECK_THAT(error_of(with([](TapOrder& t) { t.pitch = 0; })),
               Catch::Contains("tap pitch 0 is not 1..99999"));
    CHECK_THAT(error_of(with([](TapOrder& t) { t.pitch = 100000; })),
               Catch::Contains("tap pitch 100000 is not 1..99999"));
    CHECK_THAT(error_of(with([](TapOrder& t) { t.rpm = 0; })),
               Catch::Contains("tap speed 0 is not 1..9999 rev/min"));
    CHECK_THAT(error_of(with([](TapOrder& t) { t.rpm = 10000; })),
               Catch::Contains("tap speed 10000 is not 1..9999 rev/min"));
    CHECK(tap_order_error(example()) == std::nullopt);
    const EncodeResult number = tap_card(example(), 10000);
    CHECK_THAT(number.error.value_or(""), Catch::Contains("card number 10000 is outside 0..9999"));
}

TEST_CASE("Tap card: a bad punch is named by its column", "[tap_card][card]") {
    const Card base = punched(tap_orders(12, example()));
    struct Case {
        const char* what;
        std::function<void(Card&)> spoil;
        int column;
        const char* says;
    };
    auto set_digits = [](Card& c, int first, std::initializer_list<int> digits) {
        for (int d : digits) {
            c.set_column(first++, digit(d));
        }
    };
    auto clear = [](Card& c, int first, int last) {
        for (int col = first; col <= last; ++col) {
            c.set_column(col, 0);
        }
    };
    const std::vector<Case> cases = {
        {"the tool blank", [&](Card& c) { clear(c, 2, 3); }, 2, "tap tool is blank"},
        {"tool 00",
         [&](Card& c) {
             set_digits(c, 2, {0, 0});
         },
         2, "tap tool is 00: tools are numbered 01-99"},
        {"a double punch in the tool", [](Card& c) { c.punch(3, Row::r7); }, 3,
         "double punch (rows 1 and 7) in tap tool"},
        {"half a tool", [&](Card& c) { clear(c, 3, 3); }, 3,
         "blank digit inside the number in tap tool"},
        {"the axis blank", [&](Card& c) { clear(c, 4, 4); }, 4, "tap feed axis is blank"},
        {"axis digit 0", [&](Card& c) { set_digits(c, 4, {0}); }, 4,
         "tap feed axis is 0: expected 1-5 (table, cross, vertical, swivel, tilt)"},
        {"axis digit 6", [&](Card& c) { set_digits(c, 4, {6}); }, 4,
         "tap feed axis is 6: expected 1-5"},
        {"axis digit 9", [&](Card& c) { set_digits(c, 4, {9}); }, 4,
         "tap feed axis is 9: expected 1-5"},
        {"the sense blank", [&](Card& c) { clear(c, 5, 5); }, 5, "tap sense is blank"},
        {"both senses", [](Card& c) { c.punch(5, Row::r0); }, 5,
         "tap sense punched both forward (row 0) and reverse (row 1)"},
        {"row 2 in the sense column", [](Card& c) { c.punch(5, Row::r2); }, 5,
         "punch in row 2 where none belongs (in tap sense)"},
        {"depth 0000",
         [&](Card& c) {
             set_digits(c, 6, {0, 0, 0, 0});
         },
         6, "tap depth is 0000: a tap of depth 0 taps nothing"},
        {"the depth blank", [&](Card& c) { clear(c, 6, 9); }, 6, "tap depth is blank"},
        {"a blank digit inside the depth", [&](Card& c) { clear(c, 8, 8); }, 8,
         "blank digit inside the number in tap depth"},
        {"pitch 00000",
         [&](Card& c) {
             set_digits(c, 10, {0, 0, 0, 0, 0});
         },
         10, "tap pitch is 00000: a pitch of 0 feeds nothing"},
        {"the pitch blank", [&](Card& c) { clear(c, 10, 14); }, 10, "tap pitch is blank"},
        {"a double punch in the pitch", [](Card& c) { c.punch(14, Row::r9); }, 14,
         "double punch (rows 0 and 9) in tap pitch"},
        {"speed 0000",
         [&](Card& c) {
             set_digits(c, 15, {0, 0, 0, 0});
         },
         15, "tap speed is 0000: the spindle must turn to tap"},
        {"the speed blank", [&](Card& c) { clear(c, 15, 18); }, 15, "tap speed is blank"},
        {"a hole in the blank column 1", [](Card& c) { c.punch(1, Row::r0); }, 1,
         "column 1, which layout fig8 leaves unused on a tap card"},
        {"a hole in column 25", [](Card& c) { c.punch(25, Row::r5); }, 25,
         "punch in row 5 where none belongs (in column 25, which layout fig8 leaves unused on a "
         "tap card)"},
        {"columns 21-24 (peck depth) punched 0000",
         [](Card& c) {
             for (int col = 21; col <= 24; ++col) {
                 c.punch(col, Row::r0);
             }
         },
         21, "tap peck depth is 0000: leave it blank for one pass"},
        {"column 20 (retract multiple) punched 7", [](Card& c) { c.punch(20, Row::r7); }, 20,
         "tap retract multiple is 7: blank or 1 (out at S, as in), or 2-4"},
        {"column 19 (index wait) punched 5", [](Card& c) { c.punch(19, Row::r5); }, 19,
         "tap index wait is 5: blank (the feed follows from the tool's first turn) or 1"},
        {"a hole in column 75", [](Card& c) { c.punch(75, Row::r1); }, 75,
         "leaves unused on a tap card"},
        {"row 12 over the tool", [](Card& c) { c.punch(2, Row::r12); }, 2,
         "punch in row 12 where none belongs (in tap tool)"},
        {"row 5 in column 76", [](Card& c) { c.punch(76, Row::r5); }, 76,
         "punch in row 5 where none belongs"},
        {"the card number blank", [&](Card& c) { clear(c, 77, 80); }, 77, "card number is blank"},
        {"rows 2 and 3 in column 76", [](Card& c) { c.punch(76, Row::r2); }, 76,
         "column 76 punched in rows 2 and 3: row 2 marks a sync card, row 3 a tap card, not both"},
        {"rows 1 and 3 in column 76", [](Card& c) { c.punch(76, Row::r1); }, 76,
         "column 76 punched in rows 1 and 3: row 1 marks a condition card, row 3 a tap card, not "
         "both"},
        {"rows 1, 2 and 3 in column 76",
         [](Card& c) {
             c.punch(76, Row::r1);
             c.punch(76, Row::r2);
         },
         76,
         "column 76 punched in rows 1, 2 and 3: row 1 marks a condition card, row 2 a sync card, "
         "row 3 a tap card, only one of them"},
        {"two faults: the lower column is named",
         [&](Card& c) {
             clear(c, 15, 18);
             set_digits(c, 4, {7});
         },
         4, "tap feed axis is 7"},
    };
    for (const Case& k : cases) {
        INFO(k.what);
        Card c = base;
        k.spoil(c);
        const DecodeResult d = decode(c, fig8_layout());
        REQUIRE_FALSE(d);
        CHECK(d.bad_punch->column == k.column);
        CHECK_THAT(d.bad_punch->what, Catch::Contains(k.says));
    }
    // Rows 1 and 2 together keep their message from before tap cards.
    Card both = punched(vertical_move(1, 0, 100));
    both.punch(76, Row::r1);
    both.punch(76, Row::r2);
    CHECK(decode(both, fig8_layout()).bad_punch->what ==
          "column 76 punched in rows 1 and 2: row 1 marks a condition card, row 2 a sync card, "
          "not both");
}

TEST_CASE("Tap card: its listing row reads as one card and is written back the same",
          "[tap_card][listing]") {
    const std::string text =
        std::string(kListingHeader) + "\n" + motion_rows(11, "1.000", "1.000") +
        "12,tap,1,vertical,reverse,0.600,0.05000,240\n" +
        "13,tap,2,table,forward,0.250,0.06250,100\n" + motion_rows(14, "0.000", "1.000");
    std::istringstream in(text);
    ListingReader reader(in, "t.csv");
    REQUIRE(reader.next()->orders.kind == CardKind::motion);
    auto first = reader.next();
    REQUIRE(first);
    CHECK(first->orders == tap_orders(12, example()));
    CHECK(first->first_line == 7);
    auto second = reader.next();
    REQUIRE(second);
    CHECK(second->orders == tap_orders(13, tap(2, Axis::table, Motion::forward, 250, 6250, 100)));
    auto motion = reader.next();
    REQUIRE(motion);
    CHECK(motion->orders.kind == CardKind::motion);
    CHECK(motion->orders.number == 14);
    CHECK_FALSE(reader.next());

    // Punched by the listing source, written by the listing sink: the same rows.
    std::istringstream again(text);
    DeckOptions options;
    options.format = DeckFormat::listing;
    options.file_name = "t.csv";
    auto source = open_card_source(again, options);
    std::ostringstream out;
    {
        auto sink = open_card_sink(out, options);
        while (auto card = source->next()) {
            sink->write(*card);
        }
    }
    CHECK(out.str() == text);

    // Leading zeros and spaces are read; the row is written without them.
    std::istringstream padded(std::string(kListingHeader) +
                              "\n0012, tap, 01, vertical, reverse, 0.600, 0.05000, 0240\n");
    ListingReader pad(padded, "p.csv");
    const auto read = pad.next();
    REQUIRE(read);
    CHECK(read->orders == tap_orders(12, example()));
    CHECK(tap_row(read->orders) == "12,tap,1,vertical,reverse,0.600,0.05000,240");
    CHECK(is_tap_row("12,tap,1"));
    CHECK_FALSE(is_tap_row("12,sync,position,30"));
    CHECK_FALSE(is_tap_row("12,0,table,+,3,,,0.000,0.000,1"));
}

TEST_CASE("Tap card: the listing's errors name file and line", "[tap_card][listing]") {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"12,tap,1,vertical,reverse,0.600,0.05000\n",
         "t.csv:2: a tap row has 8 comma-separated fields "
         "(card,tap,TOOL,AXIS,SENSE,DEPTH,PITCH,RPM), then the rigid-tapping words if any "
         "(index, retract=K, peck=D.DDD), found 7"},
        {"12,tap\n", "t.csv:2: a tap row has 8 comma-separated fields"},
        {"10000,tap,1,vertical,reverse,0.600,0.05000,240\n",
         "t.csv:2: card number '10000' is not 0..9999"},
        {"12,tap,0,vertical,reverse,0.600,0.05000,240\n", "t.csv:2: tool '0' is not 1..99"},
        {"12,tap,100,vertical,reverse,0.600,0.05000,240\n", "t.csv:2: tool '100' is not 1..99"},
        {"12,tap,T1,vertical,reverse,0.600,0.05000,240\n", "tool 'T1' is not 1..99"},
        {"12,tap,1,spindle,reverse,0.600,0.05000,240\n",
         "t.csv:2: unknown axis 'spindle' (table, cross, vertical, swivel or tilt)"},
        {"12,tap,1,vertical,-,0.600,0.05000,240\n",
         "t.csv:2: sense '-' is not forward (counters count up into the work) or reverse"},
        {"12,tap,1,vertical,reverse,,0.05000,240\n", "t.csv:2: depth is blank"},
        {"12,tap,1,vertical,reverse,0.000,0.05000,240\n",
         "t.csv:2: depth '0.000': a tap of depth 0 taps nothing"},
        {"12,tap,1,vertical,reverse,0.6,0.05000,240\n",
         "t.csv:2: depth '0.6': needs exactly three decimals"},
        {"12,tap,1,vertical,reverse,10.000,0.05000,240\n", "depth '10.000': over 9.999 inches"},
        {"12,tap,1,vertical,reverse,0.600,0.0500,240\n",
         "t.csv:2: pitch '0.0500': needs exactly five decimals"},
        {"12,tap,1,vertical,reverse,0.600,1.00000,240\n",
         "pitch '1.00000': over 0.99999 in per tool revolution"},
        {"12,tap,1,vertical,reverse,0.600,0.00000,240\n",
         "t.csv:2: pitch '0.00000': a pitch of 0 feeds nothing"},
        {"12,tap,1,vertical,reverse,0.600,x,240\n", "pitch 'x': not a number of inches"},
        {"12,tap,1,vertical,reverse,0.600,0.05000,0\n", "t.csv:2: speed '0' is not 1..9999"},
        {"12,tap,1,vertical,reverse,0.600,0.05000,10000\n", "speed '10000' is not 1..9999"},
        {"12,tap,1,vertical,reverse,0.600,0.05000,240\n12,tap,2,table,forward,0.100,0.06250,"
         "100\n",
         "t.csv:3: card 12 has a second tap row (first on line 2): a tap card taps one hole"},
        {"1,0,table,+,3,,,0.000,0.000,1\n1,tap,1,vertical,reverse,0.600,0.05000,240\n",
         "t.csv:3: a tap row begins, but card 1 (from line 2) has no row for the cross axis"},
    };
    for (const auto& [rows, says] : cases) {
        INFO(rows);
        CHECK_THAT(listing_error(rows), Catch::Contains(says));
    }
    CHECK(listing_error("12,tap,1,vertical,reverse,0.600,0.05000,240\n13,tap,1,vertical,reverse,"
                        "0.600,0.05000,240\n") == "no error");
}

TEST_CASE("Tap card: the deck review names each refusal by card and column", "[tap_card][review]") {
    const CardOrders up = vertical_move(1, 0, 1000);
    SECTION("a tap card under a profile without spindle synchronisation: column 76") {
        DeckReviewer faithful;
        faithful.allow_tap(false, "parsons-1952");
        const auto notes = deck_errors(review_all(faithful, {up, tap_orders(2, example())}));
        REQUIRE(notes.size() == 1);
        CHECK(notes.at(0).card == 2);
        CHECK(notes.at(0).column == 76);
        CHECK(notes.at(0).message ==
              "a tap card (an addition after EP 0360190, Mitsubishi): profile parsons-1952 has no "
              "spindle synchronisation; the built-in profile parsons-extended has it (--profile "
              "parsons-extended)");
    }
    SECTION("a good deck has no deck error, and the tap leaves the axes where they were") {
        DeckReviewer reviewer;
        const auto notes = review_all(
            reviewer, {up, tap_orders(2, example()), vertical_move(3, 1000, 0),
                       tap_orders(4, tap(2, Axis::table, Motion::forward, 100, 6250, 240))});
        for (const ReviewNote& n : notes) {
            INFO(n.message);
            CHECK_FALSE(n.deck_error);
            // card 3's slow-downs count from 1.000, where card 1 left the vertical axis
            CHECK(n.message.find("not on the way") == std::string::npos);
        }
    }
    SECTION("a tool no spindle head holds: column 2, naming the tools the heads hold") {
        DeckReviewer reviewer;
        TapOrder t = example();
        t.tool = 7;
        const auto notes = deck_errors(review_all(reviewer, {up, tap_orders(2, t)}));
        REQUIRE(notes.size() == 1);
        CHECK(notes.at(0).card == 2);
        CHECK(notes.at(0).column == 2);
        CHECK(notes.at(0).axis == Axis::vertical);
        CHECK(notes.at(0).message == "tap tool 7: no spindle head 31 of profile parsons-extended "
                                     "holds it (its heads hold tools 1, 2, 3): PC 130 has "
                                     "nothing to put on");
    }
    SECTION("a speed above motor 27's fastest: column 15") {
        DeckReviewer reviewer;
        TapOrder t = example();
        t.rpm = 241;
        t.pitch = 1000; // the feed is within the drive's
        const auto notes = deck_errors(review_all(reviewer, {up, tap_orders(2, t)}));
        REQUIRE(notes.size() == 1);
        CHECK(notes.at(0).column == 15);
        CHECK(notes.at(0).message == "tap speed S 241 rev/min is above spindle motor 27's "
                                     "fastest, 240 rev/min (max_rpm of profile "
                                     "parsons-extended)");
        DeckReviewer at_max;
        t.rpm = 240;
        CHECK(deck_errors(review_all(at_max, {up, tap_orders(2, t)})).empty());
    }
    SECTION("a feed the follower drive cannot follow: column 10, with the most pitch at that "
            "speed") {
        // Tool 2's head turns the tool a third of the motor's speed: at 240 rev/min the tool
        // turns 80, and the drive's 5.4 in/min allow 0.0675 in per revolution.
        DeckReviewer reviewer;
        const TapOrder fast = tap(2, Axis::vertical, Motion::reverse, 600, 9000, 240);
        const auto notes = deck_errors(review_all(reviewer, {up, tap_orders(2, fast)}));
        REQUIRE(notes.size() == 1);
        CHECK(notes.at(0).card == 2);
        CHECK(notes.at(0).column == 10);
        CHECK(notes.at(0).message ==
              "tap pitch 0.09000 in at S 240 rev/min through tool 2's gear ratio 0.3333 needs the "
              "vertical axis to feed 7.20 in/min; the follower drive follows at most 5.4 in/min: "
              "at most 0.06750 in per tool revolution at that speed");
        DeckReviewer just;
        CHECK(
            deck_errors(review_all(just, {up, tap_orders(2, tap(2, Axis::vertical, Motion::reverse,
                                                                600, 6750, 240))}))
                .empty());
        DeckReviewer over;
        CHECK(
            deck_errors(review_all(over, {up, tap_orders(2, tap(2, Axis::vertical, Motion::reverse,
                                                                600, 6751, 240))}))
                .size() == 1);
        // The ratio is the head's: the same pitch and speed with tool 1 (ratio 0.25) is within.
        DeckReviewer other_head;
        CHECK(deck_errors(
                  review_all(other_head, {up, tap_orders(2, tap(1, Axis::vertical, Motion::reverse,
                                                                600, 9000, 240))}))
                  .empty());
    }
    SECTION("the limits are the profile's: a slower drive, other heads, another motor") {
        SpindleLimits limits;
        limits.heads = {{5, 1.0}};
        limits.max_rpm = 100;
        limits.drive_max_in_per_min = 2.0;
        CHECK(limits.max_pitch(100, 1.0) == 2000);
        CHECK(SpindleLimits::feed_in_per_min(5000, 240, 0.25) == Approx(3.0));
        DeckReviewer reviewer;
        reviewer.allow_tap(true, "mine", limits);
        const auto notes = deck_errors(review_all(
            reviewer, {up, tap_orders(2, tap(5, Axis::vertical, Motion::reverse, 600, 2500, 100)),
                       tap_orders(3, tap(1, Axis::vertical, Motion::reverse, 600, 5000, 101))}));
        REQUIRE(notes.size() == 3);
        CHECK(notes.at(0).card == 2);
        CHECK(notes.at(0).column == 10);
        CHECK_THAT(notes.at(0).message, Catch::Contains("needs the vertical axis to feed 2.50 "
                                                        "in/min; the follower drive follows at "
                                                        "most 2 in/min: at most 0.02000 in"));
        CHECK(notes.at(1).card == 3);
        CHECK(notes.at(1).column == 2);
        CHECK_THAT(notes.at(1).message, Catch::Contains("profile mine holds it (its heads hold "
                                                        "tools 5)"));
        CHECK(notes.at(2).column == 15);
        CHECK_THAT(notes.at(2).message, Catch::Contains("fastest, 100 rev/min"));
    }
    SECTION("a feed slower than the drive's least is refused on the pitch, with the least pitch") {
        // Tool 1 (ratio 0.25) at 240 rev/min turns 60 rev/min: 0.5 in/min needs 0.00834 in.
        CHECK(SpindleLimits::min_pitch(240, 0.25) == 834);
        DeckReviewer reviewer;
        const auto slow = deck_errors(review_all(
            reviewer, {up, tap_orders(2, tap(1, Axis::vertical, Motion::reverse, 600, 833, 240))}));
        REQUIRE(slow.size() == 1);
        CHECK(slow.at(0).card == 2);
        CHECK(slow.at(0).column == 10);
        CHECK_THAT(slow.at(0).message, Catch::Contains("feeds the vertical axis 0.500 in/min") &&
                                           Catch::Contains("no slower than 0.5 in/min: at least "
                                                           "0.00834 in"));
        DeckReviewer within;
        CHECK(deck_errors(
                  review_all(within, {up, tap_orders(2, tap(1, Axis::vertical, Motion::reverse, 600,
                                                            834, 240))}))
                  .empty());
    }
    SECTION("conditions wait across a tap card for their motion card") {
        CardOrders cond;
        cond.kind = CardKind::condition;
        cond.number = 2;
        cond.condition_count = 1;
        cond.conditions.at(0) = {1, Axis::vertical, 1500, PassingSense::forward, ActionKind::lamp,
                                 1};
        DeckReviewer reviewer;
        const auto notes = review_all(
            reviewer, {up, cond, tap_orders(3, example()), vertical_move(4, 1000, 2000)});
        for (const ReviewNote& n : notes) {
            INFO(n.message);
            CHECK_FALSE(n.deck_error);
        }
        // A condition card with only a tap card after it has no motion card after it.
        DeckReviewer alone;
        const auto left = deck_errors(review_all(alone, {up, cond, tap_orders(3, example())}));
        REQUIRE(left.size() == 1);
        CHECK(left.at(0).card == 2);
        CHECK_THAT(left.at(0).message, Catch::Contains("no motion card after it"));
    }
}
