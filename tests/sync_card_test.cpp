// Sync cards, an addition after EP 0436887 (Mitsubishi): the card (column 76 row 2),
// its listing rows, its picture, the deck review's errors and the CLI's exit codes. What the
// sync units do with a sync card while the machine runs is relaylogic's and is tested there.
#include "tests/card_support.hpp"
#include "tests/machine_support.hpp"
#include "tests/test_support.hpp"

#include "cardreader/card_svg.hpp"
#include "cardreader/deck_error.hpp"
#include "cardreader/deck_review.hpp"
#include "cardreader/listing_format.hpp"
#include "cardreader/sync_card.hpp"
#include "cardreader/sync_listing.hpp"
#include "cardreader/sync_review.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <functional>
#include <sstream>

using namespace parsons;
using namespace parsons::cardreader;
using parsons::test::idle_card;
using parsons::test::listing_error;
using parsons::test::order;
using parsons::test::review_all;
using parsons::test::table_cross_rows;

using parsons::test::digit;
using parsons::test::punched;

namespace {

// The seed's step 3, "G95 G101 R30 F10", on card `number`: start at 30 degrees, the table
// 0.00150 in and the cross 0.00100 in per pulse (within what the default sync drive follows,
// 0.00187 in per pulse).
CardOrders seed_step3(int number) {
    CardOrders c;
    c.kind = CardKind::sync;
    c.number = number;
    c.sync.position_sync = true;
    c.sync.angle_deg = 30;
    c.sync.travel_per_pulse.at(axis_index(Axis::table)) = 150;
    c.sync.travel_per_pulse.at(axis_index(Axis::cross)) = 100;
    return c;
}

CardOrders speed_only(int number, Axis axis, int travel) {
    CardOrders c;
    c.kind = CardKind::sync;
    c.number = number;
    c.sync.travel_per_pulse.at(axis_index(axis)) = travel;
    return c;
}

CardOrders loop_card(int number, int to, int count) {
    CardOrders c;
    c.kind = CardKind::sync;
    c.number = number;
    c.sync.loop = true;
    c.sync.loop_to = to;
    c.sync.loop_count = count;
    return c;
}

// A motion card: the table and the cross from 0 to `to` at speed 3, the others idle.
CardOrders moving_card(int number, int from, int to) {
    CardOrders c = idle_card(number, {from, from, 0, 0, 0});
    c.axis(Axis::table) = order(from, to, 3, {}, {}, 1);
    c.axis(Axis::cross) = order(from, to, 3, {}, {}, 2);
    return c;
}

} // namespace

TEST_CASE("Sync card: the seed's G95 G101 R30 F is punched in its columns and read back, column "
          "76 row 2 marking it",
          "[sync_card][card]") {
    const CardOrders card = seed_step3(3);
    const Card c = punched(card);
    CHECK(c.column(76) == row_bit(Row::r2));
    CHECK(c.column(1) == 0);
    CHECK(c.column(2) == row_bit(Row::r0)); // G101
    CHECK(c.column(3) == digit(0));         // R 030
    CHECK(c.column(4) == digit(3));
    CHECK(c.column(5) == digit(0));
    for (int col = 6; col <= 15; ++col) { // no loop
        CHECK(c.column(col) == 0);
    }
    const std::array<int, 5> table = {0, 0, 1, 5, 0}; // 0.00150 in columns 16-20
    const std::array<int, 5> cross = {0, 0, 1, 0, 0}; // 0.00100 in columns 21-25
    for (int i = 0; i < 5; ++i) {
        CHECK(c.column(16 + i) == digit(table.at(static_cast<std::size_t>(i))));
        CHECK(c.column(21 + i) == digit(cross.at(static_cast<std::size_t>(i))));
    }
    for (int col = 26; col <= 75; ++col) { // vertical, swivel, tilt not synchronised
        CHECK(c.column(col) == 0);
    }
    CHECK(c.column(79) == digit(0));
    CHECK(c.column(80) == digit(3));
    CHECK(is_sync_card(c, fig8_layout()));
    CHECK_FALSE(is_condition_card(c, fig8_layout()));
    CHECK(is_extension_card(c, fig8_layout()));
    CHECK_FALSE(is_extension_card(punched(moving_card(1, 0, 100)), fig8_layout()));

    const DecodeResult d = decode(c, fig8_layout());
    REQUIRE(d);
    CHECK(d.orders == card);
    CHECK(d.orders.sync.speed_sync());

    // Every field at its extremes, each travel field on its own axis.
    CardOrders wide;
    wide.kind = CardKind::sync;
    wide.number = 9999;
    wide.sync.position_sync = true;
    wide.sync.angle_deg = 359;
    for (Axis a : kAxes) {
        wide.sync.travel_per_pulse.at(axis_index(a)) = 1 + 20000 * static_cast<int>(axis_index(a));
    }
    wide.sync.travel_per_pulse.at(axis_index(Axis::tilt)) = kMaxTravelPerPulse;
    const Card w = punched(wide);
    CHECK(w.column(40) == digit(9)); // tilt 0.99999 ends in column 40
    CHECK(w.column(20) == digit(1)); // table 0.00001
    CHECK(decode(w, fig8_layout()).orders == wide);
    CardOrders zero = seed_step3(0);
    zero.sync.angle_deg = 0; // R000: top dead centre
    CHECK(decode(punched(zero), fig8_layout()).orders == zero);

    // The seed's M99, a loop card alone: back to card 1, 100 times.
    const CardOrders loop = loop_card(12, 1, 100);
    const Card l = punched(loop);
    CHECK(l.column(2) == 0);
    CHECK(l.column(6) == row_bit(Row::r0));
    for (int col = 7; col <= 10; ++col) { // target 0001
        CHECK(l.column(col) == digit(col == 10 ? 1 : 0));
    }
    for (int col = 11; col <= 14; ++col) { // count 0100
        CHECK(l.column(col) == digit(col == 12 ? 1 : 0));
    }
    CHECK(decode(l, fig8_layout()).orders == loop);
}

TEST_CASE("Sync card: orders no card can hold are refused by the keypunch", "[sync_card][card]") {
    auto error_of = [](CardOrders o) {
        const EncodeResult e = encode(o, fig8_layout());
        return e.error.value_or("no error");
    };
    CardOrders angle = seed_step3(1);
    angle.sync.angle_deg = 360;
    CHECK_THAT(error_of(angle), Catch::Contains("sync angle 360 is not 0..359"));
    CardOrders none = seed_step3(1);
    none.sync = SyncOrder{};
    CHECK_THAT(error_of(none), Catch::Contains("nothing on it"));
    CardOrders both = loop_card(1, 0, 1);
    both.sync.position_sync = true;
    CHECK_THAT(error_of(both), Catch::Contains("stands alone"));
    CardOrders zero = speed_only(1, Axis::swivel, 0);
    CHECK_THAT(error_of(zero), Catch::Contains("a travel per pulse of 0"));
    CHECK_THAT(error_of(speed_only(1, Axis::swivel, 100000)), Catch::Contains("not 1..99999"));
    CHECK_THAT(error_of(loop_card(1, 0, 0)), Catch::Contains("loop count 0 is not 1..9999"));
}

TEST_CASE("Sync card: a bad punch is named by its column", "[sync_card][card]") {
    const Card base = punched(seed_step3(5));
    const Card loop = punched(loop_card(6, 1, 2));
    struct Case {
        const char* what;
        const Card* from;
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
        {"angle 365", &base,
         [&](Card& c) {
             set_digits(c, 3, {3, 6, 5});
         },
         3, "angle 365 outside 0-359"},
        {"angle 999", &base,
         [&](Card& c) {
             set_digits(c, 3, {9, 9, 9});
         },
         3, "angle 999 outside 0-359"},
        {"an angle without position sync", &base, [](Card& c) { c.set_column(2, 0); }, 2,
         "position sync (column 2, row 0) is blank"},
        {"position sync without an angle", &base, [&](Card& c) { clear(c, 3, 5); }, 3,
         "sync angle is blank"},
        {"a table travel per pulse of 00000", &base,
         [&](Card& c) {
             set_digits(c, 16, {0, 0, 0, 0, 0});
         },
         16, "table travel per pulse is 00000: a travel per pulse of 0"},
        {"a cross travel per pulse of 00000", &base,
         [&](Card& c) {
             set_digits(c, 21, {0, 0, 0, 0, 0});
         },
         21, "a travel per pulse of 0"},
        {"a double punch in the vertical travel", &base,
         [&](Card& c) {
             set_digits(c, 26, {0, 0, 1, 0, 0});
             c.punch(28, Row::r4);
         },
         28, "double punch (rows 1 and 4) in vertical travel per pulse"},
        {"a blank digit inside the tilt travel", &base,
         [&](Card& c) {
             set_digits(c, 36, {0, 0, 1, 0});
         },
         40, "blank digit inside the number in tilt travel per pulse"},
        {"a hole in the blank column 41", &base, [](Card& c) { c.punch(41, Row::r3); }, 41,
         "column 41, which layout fig8 leaves unused on a sync card"},
        {"row 3 in column 15, the reset's", &base, [](Card& c) { c.punch(15, Row::r3); }, 15,
         "punch in row 3 where none belongs (in register 14 reset)"},
        {"a hole in column 41", &base, [](Card& c) { c.punch(41, Row::r1); }, 41,
         "leaves unused on a sync card"},
        {"row 1 in the position-sync column", &base, [](Card& c) { c.punch(2, Row::r1); }, 2,
         "punch in row 1 where none belongs (in position sync)"},
        {"row 12 over the angle", &base, [](Card& c) { c.punch(4, Row::r12); }, 4,
         "where none belongs (in sync angle)"},
        {"rows 1 and 2 in column 76", &base, [](Card& c) { c.punch(76, Row::r1); }, 76,
         "row 1 marks a condition card, row 2 a sync card, not both"},
        {"the card number blank", &base, [&](Card& c) { clear(c, 77, 80); }, 77,
         "card number is blank"},
        {"the mark and nothing else", &base, [&](Card& c) { clear(c, 1, 75); }, 76,
         "no synchronisation, register reset or loop is punched"},
        {"a loop mark without its target", &loop, [&](Card& c) { clear(c, 7, 10); }, 7,
         "loop target is blank"},
        {"a loop mark without its count", &loop, [&](Card& c) { clear(c, 11, 14); }, 11,
         "loop count is blank"},
        {"a loop count of 0000", &loop,
         [&](Card& c) {
             set_digits(c, 11, {0, 0, 0, 0});
         },
         11, "loop count 0000"},
        {"a target and count without the loop mark", &loop, [](Card& c) { c.set_column(6, 0); }, 6,
         "loop mark (column 6, row 0) is blank, but a loop target is punched"},
        {"a loop with position sync", &loop,
         [&](Card& c) {
             c.punch(2, Row::r0);
             set_digits(c, 3, {0, 3, 0});
         },
         6, "stands alone, but this one also carries position sync"},
        {"a loop with speed sync", &loop,
         [&](Card& c) {
             set_digits(c, 31, {0, 0, 1, 0, 0});
         },
         6, "stands alone, but this one also carries speed sync"},
    };
    for (const Case& k : cases) {
        INFO(k.what);
        Card c = *k.from;
        k.spoil(c);
        const DecodeResult d = decode(c, fig8_layout());
        REQUIRE_FALSE(d);
        CHECK(d.bad_punch->column == k.column);
        CHECK_THAT(d.bad_punch->what, Catch::Contains(k.says));
    }
}

TEST_CASE("Sync card: listing rows position, speed and loop read as one card per card number and "
          "are written back the same",
          "[sync_card][listing]") {
    const std::string rows = "3,sync,position,30\n"
                             "3,sync,speed,table,0.00150\n"
                             "3,sync,speed,cross,0.00100\n" +
                             table_cross_rows(4, "1.000", "1.000") +
                             "5,sync,speed,table,0.00100\n" +
                             table_cross_rows(6, "0.000", "1.000") + "7,sync,loop,3,100\n";
    const std::string text = std::string(kListingHeader) + "\n" + rows;
    std::istringstream in(text);
    ListingReader reader(in, "t.csv");
    auto first = reader.next();
    REQUIRE(first);
    CHECK(first->orders == seed_step3(3));
    CHECK(first->first_line == 2);
    auto motion = reader.next();
    REQUIRE(motion);
    CHECK(motion->orders.kind == CardKind::motion);
    auto second = reader.next();
    REQUIRE(second);
    CHECK(second->orders == speed_only(5, Axis::table, 100));
    REQUIRE(reader.next());
    auto loop = reader.next();
    REQUIRE(loop);
    CHECK(loop->orders == loop_card(7, 3, 100));
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
    // The rows of one card keep the order position, speed by axis, loop.
    CardOrders two = seed_step3(9);
    CHECK(sync_rows(two) == std::vector<std::string>{"9,sync,position,30",
                                                     "9,sync,speed,table,0.00150",
                                                     "9,sync,speed,cross,0.00100"});
    // Two sync cards in a row with other numbers are two cards.
    std::istringstream pair(std::string(kListingHeader) +
                            "\n1,sync,position,10\n2,sync,position,20\n");
    ListingReader pairs(pair, "p.csv");
    CHECK(pairs.next()->orders.sync.angle_deg == 10);
    CHECK(pairs.next()->orders.sync.angle_deg == 20);
    CHECK_FALSE(pairs.next());
}

TEST_CASE("Sync card: the listing's errors name file and line", "[sync_card][listing]") {
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"3,sync,position,365\n", "t.csv:2: angle '365' outside 0-359"},
        {"3,sync,position\n", "t.csv:2: a sync position row has 4 comma-separated fields"},
        {"3,sync,speed,table\n", "t.csv:2: a sync speed row has 5"},
        {"3,sync,speed,table,0.0042\n", "t.csv:2: travel per pulse '0.0042': needs exactly five"},
        {"3,sync,speed,table,1.00000\n", "over 0.99999 in per pulse"},
        {"3,sync,speed,table,0.00000\n", "t.csv:2: travel per pulse '0.00000': a travel per "
                                         "pulse of 0"},
        {"3,sync,speed,spindle,0.00100\n", "unknown axis 'spindle'"},
        {"3,sync,speed,table,0.00100\n3,sync,speed,table,0.00200\n",
         "t.csv:3: card 3 has a second speed row for the table axis (first on line 2)"},
        {"3,sync,position,10\n3,sync,position,20\n",
         "t.csv:3: card 3 has a second position row (first on line 2)"},
        {"3,sync,loop,1,0\n", "t.csv:2: loop count '0' is not 1..9999"},
        {"3,sync,loop,10000,1\n", "loop target '10000' is not 0..9999"},
        {"3,sync,position,30\n3,sync,loop,1,5\n",
         "t.csv:3: card 3: a loop and synchronisation on one card"},
        {"3,sync,jump,1\n", "t.csv:2: unknown sync order 'jump' (position, speed, loop or reset)"},
        {"3,sync,reset,1\n", "t.csv:2: a sync reset row has 3 comma-separated fields"},
        {"3,sync,reset\n3,sync,reset\n",
         "t.csv:3: card 3 has a second reset row (first on line 2)"},
        {"3,sync,loop,1,5\n3,sync,reset\n",
         "t.csv:3: card 3: a loop and a register reset on one card"},
        {"3,sync\n", "t.csv:2: a sync row is card,sync,position,ANGLE"},
        {"1,0,table,+,3,,,0.000,0.000,1\n1,sync,position,30\n",
         "t.csv:3: a sync row begins, but card 1 (from line 2) has no row for the cross axis"},
    };
    for (const auto& [rows, says] : cases) {
        INFO(rows);
        CHECK_THAT(listing_error(rows), Catch::Contains(says));
    }
}

TEST_CASE("Sync card: the deck review names each deck error by card and column",
          "[sync_card][review]") {
    SECTION("a sync card under a profile without press synchronisation: column 76") {
        DeckReviewer faithful;
        faithful.allow_sync(false, "parsons-1952");
        const auto notes = review_all(faithful, {seed_step3(1), moving_card(2, 0, 1000)});
        REQUIRE(notes.size() == 1);
        CHECK(notes.at(0).deck_error);
        CHECK(notes.at(0).card == 1);
        CHECK(notes.at(0).column == 76);
        CHECK_THAT(notes.at(0).message,
                   Catch::Contains("a sync card (an addition after EP 0436887, Mitsubishi): "
                                   "profile parsons-1952 has no press synchronisation; the "
                                   "built-in profile parsons-extended has it"));
    }
    SECTION("a good deck has no deck error") {
        DeckReviewer reviewer;
        const auto notes = review_all(reviewer, {seed_step3(1), moving_card(2, 0, 1000),
                                                 speed_only(3, Axis::cross, 100),
                                                 moving_card(4, 1000, 0), loop_card(5, 1, 10)});
        for (const ReviewNote& n : notes) {
            INFO(n.message);
            CHECK_FALSE(n.deck_error);
        }
    }
    SECTION("a sync card with no motion card after it: the deck ends, or a loop card comes") {
        DeckReviewer ends;
        auto notes = review_all(ends, {moving_card(1, 0, 100), seed_step3(2)});
        REQUIRE(notes.size() == 1);
        CHECK(notes.at(0).card == 2);
        CHECK(notes.at(0).column == 76);
        CHECK_THAT(notes.at(0).message, Catch::Contains("no motion card after it: the deck ends"));
        DeckReviewer looped;
        notes = review_all(looped, {moving_card(1, 0, 100), seed_step3(2), loop_card(3, 1, 2)});
        REQUIRE(notes.size() == 1);
        CHECK(notes.at(0).card == 2);
        CHECK(notes.at(0).column == 76);
        CHECK_THAT(notes.at(0).message, Catch::Contains("loop card 3 comes next"));
    }
    SECTION("two sync cards before one motion card: the second, column 76") {
        DeckReviewer reviewer;
        const auto notes = review_all(
            reviewer, {seed_step3(1), speed_only(2, Axis::table, 100), moving_card(3, 0, 100)});
        REQUIRE(notes.size() == 1);
        CHECK(notes.at(0).card == 2);
        CHECK(notes.at(0).column == 76);
        CHECK_THAT(notes.at(0).message,
                   Catch::Contains("a second sync card before one motion card (the first is "
                                   "card 1)"));
    }
    SECTION("speed sync on an axis the next motion card does not move: that axis's field") {
        DeckReviewer reviewer;
        const auto notes =
            review_all(reviewer, {speed_only(1, Axis::vertical, 100), moving_card(2, 0, 100),
                                  speed_only(3, Axis::table, 100), moving_card(4, 100, 200)});
        REQUIRE(notes.size() == 1);
        CHECK(notes.at(0).card == 1);
        CHECK(notes.at(0).column == 26);
        CHECK(notes.at(0).axis == Axis::vertical);
        CHECK_THAT(notes.at(0).message,
                   Catch::Contains("speed sync on the vertical axis (0.00100 in per pulse), which "
                                   "motion card 2 does not move (check 0.000)"));
    }
    SECTION("a travel per pulse the sync drive cannot follow: its column, and what it can") {
        DeckReviewer reviewer;
        reviewer.allow_sync(true, "parsons-extended", PressLimits{}); // 2 strokes, 4 pulses
        CardOrders fast = speed_only(1, Axis::table, 1000);           // 0.01000 in
        fast.sync.travel_per_pulse.at(axis_index(Axis::cross)) = 187; // just within
        const auto notes = review_all(reviewer, {fast, moving_card(2, 0, 100)});
        REQUIRE(notes.size() == 1);
        CHECK(notes.at(0).card == 1);
        CHECK(notes.at(0).column == 16);
        CHECK(notes.at(0).message ==
              "table travel per pulse 0.01000 in needs 28.8 in/min at the press's fastest (2 "
              "strokes a minute, 4 pulses a degree); the sync drive follows at most 5.4 in/min: "
              "at most 0.00187 in per pulse");
        // 0.00188 in is just over: 0.00188 x 48 pulses/s x 60 = 5.41 in/min.
        DeckReviewer over;
        const auto o = review_all(over, {speed_only(1, Axis::cross, 188), moving_card(2, 0, 100)});
        REQUIRE(o.size() == 1);
        CHECK(o.at(0).column == 21);
        // A press that runs up to 25 % faster (change_factor 1.25) halves nothing but lowers
        // the limit: 0.00187 x 1.25 is over.
        PressLimits varying;
        varying.fastest_factor = 1.25;
        CHECK(varying.max_travel_per_pulse() == 150);
        DeckReviewer faster;
        faster.allow_sync(true, "parsons-extended", varying);
        const auto f =
            review_all(faster, {speed_only(1, Axis::table, 187), moving_card(2, 0, 100)});
        REQUIRE(f.size() == 1);
        CHECK_THAT(f.at(0).message, Catch::Contains("x 1.25 with its variation"));
        CHECK_THAT(f.at(0).message, Catch::Contains("at most 0.00150 in per pulse"));
    }
    SECTION("a loop to a card number the deck does not hold before the loop card: column 7") {
        DeckReviewer reviewer;
        const auto notes = review_all(reviewer, {moving_card(1, 0, 100), loop_card(2, 7, 3)});
        REQUIRE(notes.size() == 1);
        CHECK(notes.at(0).card == 2);
        CHECK(notes.at(0).column == 7);
        CHECK_THAT(notes.at(0).message,
                   Catch::Contains("a loop to card number 0007, which the deck does not hold "
                                   "before this card"));
        DeckReviewer self;
        CHECK(review_all(self, {moving_card(1, 0, 100), loop_card(2, 2, 3)}).size() == 1); // itself
        DeckReviewer back;
        CHECK(review_all(back, {moving_card(1, 0, 100), loop_card(2, 1, 3)}).empty());
    }
    SECTION("a condition card between a sync card and its motion card is no motion card") {
        DeckReviewer reviewer;
        CardOrders cond;
        cond.kind = CardKind::condition;
        cond.number = 2;
        cond.condition_count = 1;
        cond.conditions.at(0) = {1, Axis::table, 50, PassingSense::forward, ActionKind::lamp, 1};
        const auto notes = review_all(reviewer, {seed_step3(1), cond, moving_card(3, 0, 100)});
        for (const ReviewNote& n : notes) {
            INFO(n.message);
            CHECK_FALSE(n.deck_error);
        }
    }
}

TEST_CASE("Sync card: show prints it field by field, in --json and as a picture",
          "[sync_card][cli]") {
    test::TempDir dir;
    const std::string deck = std::string(kListingHeader) + "\n" +
                             "1,sync,position,30\n1,sync,speed,table,0.00100\n" +
                             table_cross_rows(2, "0.100", "0.100") + "3,sync,loop,1,100\n";
    test::write_bytes(dir.path("sync.csv"), deck);
    const auto text =
        test::run_parsons("show " + test::q(dir.str("sync.csv")) +
                          " --profile parsons-extended --svg " + test::q(dir.str("cards")));
    INFO(text.output);
    CHECK(text.exit_code == 0);
    CHECK_THAT(text.output, Catch::Contains("SYNC CARD (column 76 row 2"));
    CHECK_THAT(text.output, Catch::Contains("30 degrees from top dead centre"));
    CHECK_THAT(text.output, Catch::Contains("G95: 0.00100 in per detector pulse"));
    CHECK_THAT(text.output, Catch::Contains("to card number 0001"));
    CHECK_THAT(text.output, Catch::Contains("100 times"));
    const std::string svg = test::read_bytes(dir.path("cards/card-0001.svg"));
    for (const char* label :
         {"G101", "ANGLE R", "M99", "LOOP TO", "F/PULSE", "TABLE", "TILT", "EXTENSION", "CARD NO.",
          "sync card (an addition after EP 0436887)"}) {
        CHECK_THAT(svg, Catch::Contains(label));
    }
    CHECK_THAT(svg, !Catch::Contains("SLOW 1"));
    CHECK_THAT(test::read_bytes(dir.path("cards/card-0002.svg")), Catch::Contains("SLOW 1"));

    const auto json = test::run_parsons("show " + test::q(dir.str("sync.csv")) +
                                        " --profile parsons-extended --json");
    CHECK(json.exit_code == 0);
    const auto doc = nlohmann::json::parse(json.output);
    const auto& first = doc.at("cards").at(0);
    CHECK(first.at("kind") == "sync");
    CHECK(first.at("position_sync") == 30);
    CHECK(first.at("speed_sync").at("table").get<double>() == Approx(0.001));
    CHECK(first.at("loop").is_null());
    const auto& loop = doc.at("cards").at(2);
    CHECK(loop.at("loop").at("to") == 1);
    CHECK(loop.at("loop").at("count") == 100);
}

TEST_CASE("Sync card: convert carries it through .cbn and text card images and back to the same "
          "listing",
          "[sync_card][cli]") {
    test::TempDir dir;
    const std::string deck = std::string(kListingHeader) + "\n" +
                             "1,sync,position,190\n1,sync,speed,cross,0.00417\n" +
                             table_cross_rows(2, "0.100", "0.100") + "3,sync,loop,1,9999\n";
    test::write_bytes(dir.path("sync.csv"), deck);
    for (const char* medium : {"cbn", "txt", "bin", "tape"}) {
        INFO(medium);
        const std::string cards = dir.str(std::string("sync.") + medium);
        const std::string back = dir.str(std::string("back-") + medium + ".csv");
        CHECK(test::run_parsons("convert " + test::q(dir.str("sync.csv")) + " -o " + test::q(cards))
                  .exit_code == 0);
        CHECK(test::run_parsons("convert " + test::q(cards) + " -o " + test::q(back)).exit_code ==
              0);
        CHECK(test::read_bytes(back) == deck);
    }
    // Every column of a sync card is one digit punch: a text card image keeps it as characters.
    const std::string text = test::read_bytes(dir.path("sync.txt"));
    const auto lines = test::lines_of(text);
    REQUIRE(lines.size() == 3);
    CHECK(lines.at(0).rfind(" 0190", 0) == 0);
    CHECK(lines.at(0).substr(75, 5) == "20001");
    CHECK(lines.at(2).substr(0, 14) == "     000019999");
}

TEST_CASE("Sync card: crank angle 359, the last whole degree before top dead centre, is read "
          "back as the keypunch wrote it, and 360 is refused",
          "[sync_card][card][mutation]") {
    CardOrders last = seed_step3(4);
    last.sync.angle_deg = 359;
    CHECK_FALSE(sync_order_error(last.sync));
    const Card c = punched(last);
    CHECK(c.column(3) == digit(3));
    CHECK(c.column(4) == digit(5));
    CHECK(c.column(5) == digit(9));
    const DecodeResult d = decode(c, fig8_layout());
    INFO((d.bad_punch ? d.bad_punch->what : std::string()));
    REQUIRE(d);
    CHECK_FALSE(d.bad_punch);
    CHECK(d.orders == last);
    // From a listing row, as `punch` reads it.
    std::istringstream in(std::string(kListingHeader) + "\n4,sync,position,359\n");
    ListingReader reader(in, "t.csv");
    const auto read = reader.next();
    REQUIRE(read);
    CHECK(read->orders.sync.position_sync);
    CHECK(read->orders.sync.angle_deg == 359);
    CHECK(encode(read->orders, fig8_layout()));
    // 360 is a full turn: the keypunch refuses it, and a card punched 360 is a bad punch.
    CardOrders full = last;
    full.sync.angle_deg = 360;
    CHECK(sync_order_error(full.sync));
    Card punched_360 = c;
    punched_360.set_column(3, digit(3));
    punched_360.set_column(4, digit(6));
    punched_360.set_column(5, digit(0));
    const DecodeResult bad = decode(punched_360, fig8_layout());
    REQUIRE(bad.bad_punch);
    CHECK(bad.bad_punch->column == 3);
    CHECK_THAT(bad.bad_punch->what, Catch::Contains("sync angle 360 outside 0-359"));
    CHECK_THAT(listing_error("3,sync,position,360\n"),
               Catch::Contains("angle '360' outside 0-359"));
}

TEST_CASE("Sync card: a loop back to card number 9999, the last a deck can number, is punched and "
          "read back, and 10000 is refused by the keypunch",
          "[sync_card][card][mutation]") {
    const CardOrders last = loop_card(12, 9999, 3);
    CHECK_FALSE(sync_order_error(last.sync));
    const Card c = punched(last);
    for (int col = 7; col <= 10; ++col) { // target 9999
        CHECK(c.column(col) == digit(9));
    }
    const DecodeResult d = decode(c, fig8_layout());
    REQUIRE(d);
    CHECK(d.orders == last);
    const CardOrders first = loop_card(12, 0, 3); // card number 0000 follows 9999
    CHECK(decode(punched(first), fig8_layout()).orders == first);
    const CardOrders beyond = loop_card(12, 10000, 3);
    CHECK(sync_order_error(beyond.sync) == "loop target 10000 is not a card number 0..9999");
    CHECK_FALSE(encode(beyond, fig8_layout()));
}

TEST_CASE("Sync card (claim 5): the reset of register 14 is punched in column 15 row 0, alone or "
          "with synchronisation, never with a loop, and listed as card,sync,reset",
          "[sync_card][card][listing]") {
    // With position sync: the seed's G101 R30, the reset on the same card.
    CardOrders with = seed_step3(4);
    with.sync.register_reset = true;
    const Card both = punched(with);
    CHECK(both.column(15) == row_bit(Row::r0));
    CHECK(punched(seed_step3(4)).column(15) == 0);
    const DecodeResult back = decode(both, fig8_layout());
    REQUIRE_FALSE(back.bad_punch);
    CHECK(back.orders == with);
    // Alone: a card of the reset only is a sound card (it synchronises nothing).
    CardOrders alone;
    alone.kind = CardKind::sync;
    alone.number = 8;
    alone.sync.register_reset = true;
    CHECK_FALSE(alone.sync.synchronises());
    CHECK_FALSE(sync_order_error(alone.sync));
    const Card only = punched(alone);
    for (int col = 1; col <= 75; ++col) {
        INFO("column " << col);
        CHECK(only.column(col) == (col == 15 ? row_bit(Row::r0) : 0));
    }
    const DecodeResult alone_back = decode(only, fig8_layout());
    REQUIRE_FALSE(alone_back.bad_punch);
    CHECK(alone_back.orders == alone);
    // Never with a loop: the keypunch refuses it, the reader names column 6.
    CardOrders looped = loop_card(9, 1, 2);
    looped.sync.register_reset = true;
    CHECK_FALSE(encode(looped, fig8_layout()));
    Card spoiled = punched(loop_card(9, 1, 2));
    spoiled.punch(15, Row::r0);
    const DecodeResult bad = decode(spoiled, fig8_layout());
    REQUIRE(bad.bad_punch);
    CHECK(bad.bad_punch->column == 6);
    CHECK_THAT(bad.bad_punch->what, Catch::Contains("also carries the reset of register 14 "
                                                    "(switch 16A)"));
    // Row 0 only.
    Card row1 = only;
    row1.set_column(15, row_bit(Row::r1));
    const DecodeResult wrong = decode(row1, fig8_layout());
    REQUIRE(wrong.bad_punch);
    CHECK(wrong.bad_punch->column == 15);
    CHECK_THAT(wrong.bad_punch->what, Catch::Contains("register 14 reset"));

    // The listing: the reset row first, with or without synchronisation.
    const std::string text = std::string(kListingHeader) + "\n" +
                             "4,sync,reset\n4,sync,position,30\n4,sync,speed,table,0.00150\n"
                             "4,sync,speed,cross,0.00100\n" +
                             table_cross_rows(5, "1.000", "1.000") + "8,sync,reset\n";
    std::istringstream in(text);
    ListingReader reader(in, "r.csv");
    auto first = reader.next();
    REQUIRE(first);
    CHECK(first->orders == with);
    REQUIRE(reader.next());
    auto last = reader.next();
    REQUIRE(last);
    CHECK(last->orders == alone);
    CHECK(sync_rows(with).front() == "4,sync,reset");
    CHECK(sync_rows(alone) == std::vector<std::string>{"8,sync,reset"});
    // The rows may come in any order; written back the reset comes first.
    std::istringstream later(std::string(kListingHeader) + "\n4,sync,position,30\n4,sync,reset\n");
    ListingReader later_reader(later, "l.csv");
    const auto l = later_reader.next();
    REQUIRE(l);
    CHECK(l->orders.sync.register_reset);
    CHECK(l->orders.sync.position_sync);
}

TEST_CASE("Sync card (claim 5): a card of the reset alone needs no motion card after it, and is a "
          "second sync card after one that waits",
          "[sync_card][review]") {
    CardOrders reset;
    reset.kind = CardKind::sync;
    reset.number = 2;
    reset.sync.register_reset = true;
    DeckReviewer trailing;
    CHECK(review_all(trailing, {moving_card(1, 0, 100), reset}).empty());
    DeckReviewer between;
    CardOrders sync3 = seed_step3(3);
    CHECK(review_all(between, {moving_card(1, 0, 100), reset, sync3, moving_card(4, 100, 0)})
              .empty());
    DeckReviewer second;
    CardOrders after = reset;
    after.number = 2;
    const auto notes = review_all(second, {seed_step3(1), after, moving_card(3, 0, 100)});
    REQUIRE(notes.size() == 1);
    CHECK(notes.at(0).card == 2);
    CHECK(notes.at(0).column == 76);
    CHECK_THAT(notes.at(0).message, Catch::Contains("a second sync card before one motion card"));
}
