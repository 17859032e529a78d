// Punching orders through the keypunch (cardreader::encode with the Fig. 8 layout) in the card
// tests: one card, a deck, and the hole of one digit.
#pragma once

#include "cardreader/card.hpp"
#include "cardreader/layout.hpp"
#include "cardreader/orders.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <string>
#include <vector>

namespace parsons::test {

// The card the keypunch makes of `o`; the test fails, naming the refusal, if it refuses.
inline cardreader::Card punched(const cardreader::CardOrders& o) {
    const cardreader::EncodeResult e = cardreader::encode(o, cardreader::fig8_layout());
    INFO(e.error.value_or(""));
    REQUIRE(e);
    return e.card;
}

// Each of the orders punched, in order.
inline std::vector<cardreader::Card> punched(const std::vector<cardreader::CardOrders>& cards) {
    std::vector<cardreader::Card> out;
    for (const auto& o : cards) {
        out.push_back(punched(o));
    }
    return out;
}

// The hole of digit `d` (0 .. 9) in a column.
inline cardreader::ColumnWord digit(int d) {
    return cardreader::row_bit(cardreader::digit_row(d));
}

// One motion card's five listing rows: the table and cross from 0.000 to `stop` (check = the
// travel), the others idle.
inline std::string table_cross_rows(int card, const char* stop, const char* check) {
    std::string rows = fmt::format("{},0,table,+,3,,,{},{},1\n", card, stop, check);
    rows += fmt::format("{},0,cross,+,3,,,{},{},2\n", card, stop, check);
    for (const char* axis : {"vertical", "swivel", "tilt"}) {
        rows += fmt::format("{},0,{},+,3,,,0.000,0.000,3\n", card, axis);
    }
    return rows;
}

} // namespace parsons::test
