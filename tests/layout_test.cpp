#include "cardreader/layout.hpp"

#include "tests/card_support.hpp"
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>

#include <set>

using namespace parsons::cardreader;

using parsons::test::punched;

namespace {

CardOrders patent_card() {
    CardOrders o;
    o.number = 1;
    o.spindle = Spindle::forward;
    for (Axis a : kAxes) {
        o.axis(a).stop = 1000;
        o.axis(a).check = 1000;
        o.axis(a).start_speed = 3;
        o.axis(a).sequence = 0b10000;
    }
    AxisOrder& table = o.axis(Axis::table);
    table.start_speed = 1;
    table.slow_down = {Thousandths{8785}, Thousandths{8885}};
    table.stop = 8985;
    table.check = 8985;
    table.sequence = 0b00011;
    return o;
}

BadPunch bad_punch_of(const Card& card) {
    auto r = decode(card, fig8_layout());
    REQUIRE_FALSE(r);
    return *r.bad_punch;
}

} // namespace

TEST_CASE("Layout fig8: every column but 76 belongs to exactly one field", "[layout]") {
    const CardLayout& layout = fig8_layout();
    std::set<int> used;
    for (const LayoutField& f : layout.fields) {
        for (int c = f.first_column; c <= f.last_column(); ++c) {
            CHECK(used.insert(c).second);
        }
    }
    for (int c = 1; c <= 80; ++c) {
        CHECK(used.count(c) == (c == 76 ? 0u : 1u));
    }
    CHECK(layout.find(FieldKind::slow_down_2, Axis::table) != nullptr);
    CHECK(layout.find(FieldKind::slow_down_2, Axis::cross) == nullptr);
    CHECK(layout.sequence_first_column == std::array<int, 5>{2, 20, 34, 48, 62});
}

TEST_CASE("Layout fig8: the table's 8.785 / 8.885 / 8.985 punch one digit per column",
          "[layout][fig8]") {
    Card card = punched(patent_card());
    auto digit_in = [&](int col) {
        for (int d = 0; d <= 9; ++d) {
            if (card.column(col) & row_bit(digit_row(d))) {
                return d;
            }
        }
        return -1;
    };
    CHECK(std::vector<int>{digit_in(4), digit_in(5), digit_in(6), digit_in(7)} ==
          std::vector<int>{8, 7, 8, 5});
    CHECK(std::vector<int>{digit_in(12), digit_in(13), digit_in(14), digit_in(15)} ==
          std::vector<int>{8, 9, 8, 5});
    CHECK(card.column(1) == row_bit(Row::r0));                       // spindle forward
    CHECK(card.column(2) == (row_bit(Row::r0) | row_bit(Row::r12))); // motion + sequence 1
    CHECK(card.column(3) == (row_bit(Row::r0) | row_bit(Row::r12))); // speed 1 + sequence 2
    CHECK(card.punched(66, Row::r12));                               // tilt at position 5
    CHECK(decode(card, fig8_layout()).orders == patent_card());
}

TEST_CASE("Layout fig8: speed column 0 / 0-1 / 0-1-2 reads as start speed 1 / 2 / 3",
          "[layout][fig10]") {
    auto [rows, speed] = GENERATE(table<ColumnWord, int>({
        {row_bit(Row::r0), 1},
        {static_cast<ColumnWord>(row_bit(Row::r0) | row_bit(Row::r1)), 2},
        {static_cast<ColumnWord>(row_bit(Row::r0) | row_bit(Row::r1) | row_bit(Row::r2)), 3},
    }));
    Card card = punched(patent_card());
    card.set_column(21, rows); // cross start speed
    auto r = decode(card, fig8_layout());
    REQUIRE(r);
    CHECK(r.orders.axis(Axis::cross).start_speed == speed);
}

TEST_CASE("Layout fig8: random orders survive encode then decode", "[layout]") {
    std::mt19937 rng(1958);
    for (int i = 0; i < 500; ++i) {
        CardOrders o = parsons::test::random_orders(rng, fig8_layout());
        auto r = decode(punched(o), fig8_layout());
        REQUIRE(r);
        CHECK(r.orders == o);
    }
}

TEST_CASE("Layout fig8: a double punch in a digit column names the column", "[layout][bad-input]") {
    Card card = punched(patent_card());
    card.punch(13, Row::r5); // table stop 8.985: column 13 now holds 9 and 5
    BadPunch bad = bad_punch_of(card);
    CHECK(bad.column == 13);
    CHECK(bad.what == "double punch (rows 5 and 9) in table stop");
}

TEST_CASE("Layout fig8: a blank digit inside a number names the column", "[layout][bad-input]") {
    Card card = punched(patent_card());
    card.set_column(17, 0); // table check 8.985 -> 8 _ 8 5
    BadPunch bad = bad_punch_of(card);
    CHECK(bad.column == 17);
    CHECK(bad.what == "blank digit inside the number in table check");
}

TEST_CASE("Layout fig8: a punch where none belongs names column and field", "[layout][bad-input]") {
    Card card = punched(patent_card());
    card.punch(30, Row::r11);
    CHECK(bad_punch_of(card).what == "punch in row 11 where none belongs (in cross check)");
    CHECK(bad_punch_of(card).column == 30);
    Card unused = punched(patent_card());
    unused.punch(76, Row::r5); // rows 1-4 mark condition, sync, tap and segment cards
    CHECK(bad_punch_of(unused).what ==
          "punch in row 5 where none belongs (in column 76, which layout fig8 leaves unused)");
    Card twelve = punched(patent_card());
    twelve.punch(25, Row::r12); // cross sequence marks are columns 20-24 only
    CHECK(bad_punch_of(twelve).column == 25);
}

TEST_CASE("Layout fig8: missing motion and missing speed are named", "[layout][bad-input]") {
    Card card = punched(patent_card());
    card.set_column(34, 0); // vertical motion
    CHECK(bad_punch_of(card).column == 34);
    CHECK(bad_punch_of(card).what == "missing vertical motion (row 0 = forward, row 1 = reverse)");
    Card speed = punched(patent_card());
    speed.set_column(49, row_bit(Row::r12)); // swivel speed: only the sequence mark left
    CHECK(bad_punch_of(speed).what ==
          "missing swivel start speed (0, 0-1 or 0-1-2 for speed 1, 2 or 3)");
    Card odd = punched(patent_card());
    odd.set_column(63, row_bit(Row::r1)); // tilt speed punched 1 alone
    CHECK(bad_punch_of(odd).what == "tilt start speed punched in rows 1: expected 0, 0-1 or 0-1-2");
}

TEST_CASE("Layout fig8: a blank stop is refused, a blank slow-down means none",
          "[layout][bad-input]") {
    Card card = punched(patent_card());
    for (int c = 40; c <= 43; ++c) {
        card.set_column(c, 0);
    }
    CHECK(bad_punch_of(card).what == "vertical stop is blank (it is always punched)");
    CardOrders o = patent_card();
    o.axis(Axis::table).slow_down[1].reset();
    auto r = decode(punched(o), fig8_layout());
    REQUIRE(r);
    CHECK_FALSE(r.orders.axis(Axis::table).slow_down[1]);
}

TEST_CASE("Layout fig8: the first bad punch from the left is the one reported",
          "[layout][bad-input]") {
    Card card = punched(patent_card());
    card.punch(70, Row::r11);
    card.punch(13, Row::r5);
    CHECK(bad_punch_of(card).column == 13);
}

TEST_CASE("Layout fig8: orders the card cannot hold are refused by the keypunch", "[layout]") {
    CardOrders o = patent_card();
    o.axis(Axis::swivel).slow_down[1] = 100;
    auto r = encode(o, fig8_layout());
    REQUIRE_FALSE(r);
    CHECK(*r.error == "layout fig8 has no second slow-down field for the swivel axis");
}

TEST_CASE("Layout fig8: of several blank digits in one field, the first blank column is named, "
          "the one the operator meets first",
          "[layout][bad-input][mutation]") {
    // Table check 8.985 in columns 16-19.
    Card two = punched(patent_card());
    two.set_column(17, 0);
    two.set_column(18, 0); // 8 _ _ 5
    CHECK(bad_punch_of(two).column == 17);
    CHECK(bad_punch_of(two).what == "blank digit inside the number in table check");
    Card apart = punched(patent_card());
    apart.set_column(16, 0);
    apart.set_column(19, 0); // _ 9 8 _
    CHECK(bad_punch_of(apart).column == 16);
    Card three = punched(patent_card());
    for (int col : {17, 18, 19}) {
        three.set_column(col, 0); // 8 _ _ _
    }
    CHECK(bad_punch_of(three).column == 17);
}
