// Helpers for the condition-card tests (an addition after EP 0640901): a condition, a condition
// card of them, and a deck punched from orders.
#pragma once

#include "tests/card_support.hpp"
#include "tests/machine_support.hpp"

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

// A motion card: the table from `from` to `to` at speed 3, the other axes idle at 0; column 1
// as given (blank by default: a tool change may trip on it).
inline cardreader::CardOrders table_move(int number, int from, int to,
                                         cardreader::Spindle spindle = cardreader::Spindle::off) {
    cardreader::CardOrders c = idle_card(number, {from, 0, 0, 0, 0});
    c.spindle = spindle;
    c.axis(cardreader::Axis::table) = order(from, to, 3, {}, {}, 1);
    return c;
}

// Runs orders on the cabinet with each card's times recorded (profile parsons-extended unless
// given).
inline relaylogic::RunResult
run_conditions(const std::vector<cardreader::CardOrders>& cards, relaylogic::Pace pace,
               relaylogic::MachineObserver* observer = nullptr,
               const axes::MachineProfile& profile = axes::extended_profile()) {
    VectorDeck deck(punched(cards));
    relaylogic::ControlCabinet cabinet(profile, cardreader::fig8_layout());
    cabinet.set_pace(pace);
    cabinet.record_card_times(true);
    if (observer != nullptr) {
        cabinet.attach(observer);
    }
    return cabinet.run(deck);
}

} // namespace parsons::test
