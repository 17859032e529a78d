// Reading a deck as a careful operator would before it goes into reader 134: the things the
// machine will stop on, or silently do wrong, that can be seen on the cards themselves.
//
//  - the shared-bank hazard: slow-downs and stop share the absolute storage banks 350-356
//    (Fig. 12), one bank of ten relays per digit, so the absolute comparer also conducts at
//    every number whose digits each stand on a closed relay (DESIGN.md 4.2);
//  - a check that is not |stop - previous stop| (the increment comparer 122'' disagrees);
//  - a card number that is not the previous one + 1 (the card-number check: no numeral);
//  - a start speed that does not match the slow-downs punched (3 - start speed of them);
//  - a slow-down the counters never pass before the stop, a motion against the stop;
//  - an axis with no sequence position (it never runs: a sequence stall).
// Emulation note: this is a static reading of the cards, not a run; the machine itself
// (relaylogic/) is what decides what happens.
#pragma once

#include "cardreader/orders.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace parsons::cardreader {

// Every number the shared absolute banks compare equal at for this axis's slow-downs and
// stop, ascending (includes the punched numbers themselves).
std::vector<Thousandths> shared_bank_matches(const AxisOrder& order);

// The matches that are not punched numbers and that the counters pass on the way from
// `from` to the stop in the motion's direction (start included, stop excluded).
std::vector<Thousandths> spurious_matches_on_path(const AxisOrder& order, Thousandths from);

struct ReviewNote {
    std::optional<Axis> axis; // none for whole-card notes (card number)
    std::string message;
};

// Reviews a deck card by card, remembering where each axis stands (every axis starts the
// deck at the reference zero) and the previous card number.
class DeckReviewer {
public:
    std::vector<ReviewNote> review(const CardOrders& orders);
    // A card that could not be read in full: its numbers are unknown, so the next card's
    // number and checks are not judged against a guess.
    void skip();

private:
    std::optional<int> previous_number_;
    std::array<std::optional<Thousandths>, kAxisCount> position_{
        Thousandths{0}, Thousandths{0}, Thousandths{0}, Thousandths{0}, Thousandths{0}};
};

} // namespace parsons::cardreader
