// Helpers for the condition-card tests (an addition after EP 0640901): a condition, a condition
// card of them, and a deck punched from orders.
#pragma once

#include "cardreader/layout.hpp"
#include "cardreader/orders.hpp"

#include <catch2/catch.hpp>

#include <initializer_list>
#include <vector>

namespace parsons::test {

inline cardreader::ConditionOrder cond(int event, cardreader::Axis axis, int position,
                                       cardreader::PassingSense sense,
                                       cardreader::ActionKind action, int parameter = 0) {
    return cardreader::ConditionOrder{event, axis,   static_cast<cardreader::Thousandths>(position),
                                      sense, action, parameter};
}

inline cardreader::CardOrders
condition_card(int number, std::initializer_list<cardreader::ConditionOrder> conditions) {
    cardreader::CardOrders c;
    c.kind = cardreader::CardKind::condition;
    c.number = number;
    for (const cardreader::ConditionOrder& x : conditions) {
        c.conditions.at(static_cast<std::size_t>(c.condition_count++)) = x;
    }
    return c;
}

inline std::vector<cardreader::Card> punched(const std::vector<cardreader::CardOrders>& cards) {
    std::vector<cardreader::Card> out;
    for (const auto& o : cards) {
        const auto e = cardreader::encode(o, cardreader::fig8_layout());
        REQUIRE(e);
        out.push_back(e.card);
    }
    return out;
}

} // namespace parsons::test
