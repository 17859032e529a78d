// Condition cards, an addition after EP 0640901 (Siemens): the card itself — punched and read
// back field by field, a bad punch named by its column, and the listing's errors by file and line.
#include "tests/condition_support.hpp"
#include "tests/machine_support.hpp"
#include "tests/test_support.hpp"

#include "cardreader/condition_card.hpp"
#include "cardreader/deck_error.hpp"
#include "cardreader/listing_format.hpp"

#include <catch2/catch.hpp>

#include <functional>
#include <sstream>

using namespace parsons;
using namespace parsons::cardreader;
using namespace parsons::test;

TEST_CASE("Condition card: punched by the keypunch and read back, each field in its columns "
          "(column 76 row 1 marks it)",
          "[conditions][card]") {
    const CardOrders card = condition_card(
        12, {cond(7, Axis::cross, 1250, PassingSense::reverse, ActionKind::tool_change, 2),
             cond(42, Axis::tilt, 9999, PassingSense::either, ActionKind::lamp, 9),
             cond(3, Axis::table, 0, PassingSense::forward, ActionKind::dwell, 4),
             cond(99, Axis::vertical, 5, PassingSense::forward, ActionKind::coolant_on),
             cond(1, Axis::swivel, 8765, PassingSense::reverse, ActionKind::spindle_stop)});
    const EncodeResult e = encode(card, fig8_layout());
    REQUIRE(e);
    const Card& c = e.card;
    CHECK(c.column(76) == row_bit(Row::r1));
    CHECK(c.punched(1, Row::r0)); // event 07: columns 1-2
    CHECK(c.punched(2, Row::r7));
    CHECK(c.punched(3, Row::r2));           // axis 2 = cross
    CHECK(c.column(4) == row_bit(Row::r1)); // reverse: row 1
    for (int col : {5, 6, 7, 8}) {          // position 1.250
        CHECK(c.column(col) == row_bit(digit_row(std::array{1, 2, 5, 0}.at(col - 5))));
    }
    CHECK(c.punched(9, Row::r6));  // action 6 = tool change
    CHECK(c.punched(13, Row::r2)); // parameter 0002
    CHECK(c.column(14) == 0);
    CHECK(c.column(15) == 0);
    CHECK(c.column(19) == (row_bit(Row::r0) | row_bit(Row::r1))); // slot 2: either
    CHECK(c.punched(77, Row::r0));
    CHECK(c.punched(80, Row::r2)); // card number 0012

    const DecodeResult d = decode(c, fig8_layout());
    REQUIRE(d);
    CHECK(d.orders == card);

    // The listing: one row per condition, and back.
    std::ostringstream text;
    {
        DeckOptions options;
        options.format = DeckFormat::listing;
        auto sink = open_card_sink(text, options);
        sink->write(c);
    }
    CHECK(text.str().find("12,if,7,cross,-,1.250,tool-change,2\n") != std::string::npos);
    CHECK(text.str().find("12,if,3,table,+,0.000,dwell,swivel\n") != std::string::npos);
    CHECK(text.str().find("12,if,99,vertical,+,0.005,coolant-on,\n") != std::string::npos);
    std::istringstream in(text.str());
    ListingReader reader(in, "t.csv");
    const auto back = reader.next();
    REQUIRE(back);
    CHECK(back->orders == card);
    CHECK_FALSE(reader.next());
}

TEST_CASE("Condition card: a bad punch is named by its column", "[conditions][card]") {
    const CardOrders good = condition_card(
        5, {cond(7, Axis::cross, 1250, PassingSense::reverse, ActionKind::tool_change, 2)});
    const Card base = encode(good, fig8_layout()).card;
    struct Case {
        const char* what;
        std::function<void(Card&)> spoil;
        int column;
        const char* says;
    };
    const std::vector<Case> cases = {
        {"a hole in a blank column of the slot", [](Card& c) { c.punch(15, Row::r3); }, 15,
         "where none belongs"},
        {"event 00", [](Card& c) { c.set_column(2, row_bit(Row::r0)); }, 1, "00"},
        {"axis 6", [](Card& c) { c.set_column(3, row_bit(Row::r6)); }, 3, "expected 1..5"},
        {"no sense", [](Card& c) { c.set_column(4, 0); }, 4, "sense is blank"},
        {"action 9", [](Card& c) { c.set_column(9, row_bit(Row::r9)); }, 9, "expected 1..8"},
        {"tool 0", [](Card& c) { c.set_column(13, 0); }, 10, "tool number"},
        {"a double punch in the position", [](Card& c) { c.punch(6, Row::r3); }, 6, "double punch"},
        {"slot 2 punched, slot 1 blank",
         [](Card& c) {
             for (int col = 1; col <= 15; ++col) {
                 c.set_column(col + 15, c.column(col));
                 c.set_column(col, 0);
             }
         },
         16, "condition 1 before it is blank"},
        {"the mark and no condition",
         [](Card& c) {
             for (int col = 1; col <= 75; ++col) {
                 c.set_column(col, 0);
             }
         },
         76, "no condition is punched"},
        {"the card number blank",
         [](Card& c) {
             for (int col = 77; col <= 80; ++col) {
                 c.set_column(col, 0);
             }
         },
         77, "card number is blank"},
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
    // On a motion card column 76 is unused but for the marks (row 1 a condition card, row 2 a
    // sync card, row 3 a tap card, row 4 a segment card): row 5 there is a bad punch.
    Card motion = encode(idle_card(1, {0, 0, 0, 0, 0}), fig8_layout()).card;
    motion.punch(76, Row::r5);
    const DecodeResult m = decode(motion, fig8_layout());
    REQUIRE_FALSE(m);
    CHECK(m.bad_punch->column == 76);
}

TEST_CASE("Condition card: the listing's errors name file and line", "[conditions][listing]") {
    const std::string header = std::string(kListingHeader) + "\n";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"1,if,7,table,?,1.000,lamp,1\n", "t.csv:2: sense '?'"},
        {"1,if,7,table,+,1.000,lamp\n", "t.csv:2: a condition row has 8"},
        {"1,if,7,table,+,1.000,dwell,3\n", "dwell holds an axis: '3'"},
        {"1,if,0,table,+,1.000,lamp,1\n", "event '0'"},
        {"1,if,7,table,+,1.000,spindle-stop,2\n", "takes no parameter"},
        {"1,if,7,table,+,1.000,fly,1\n", "unknown action 'fly'"},
        {"1,if,1,table,+,1.000,lamp,1\n1,if,2,table,+,1.000,lamp,1\n1,if,3,table,+,1.000,lamp,1\n"
         "1,if,4,table,+,1.000,lamp,1\n1,if,5,table,+,1.000,lamp,1\n1,if,6,table,+,1.000,lamp,1\n",
         "t.csv:7: card 1 has a sixth condition row"},
    };
    for (const auto& [rows, says] : cases) {
        INFO(rows);
        std::istringstream in(header + rows);
        ListingReader reader(in, "t.csv");
        std::string message = "no error";
        try {
            while (reader.next()) {
            }
        } catch (const DeckError& e) {
            message = e.what();
        }
        CHECK_THAT(message, Catch::Contains(says));
    }
}
