// Reading a deck's condition cards (an addition after EP 0640901, Siemens; docs/condition-cards.md)
// as the operator would before the deck goes into reader 134, card by card, with the card and
// column of every finding:
//
//  deck errors (`run` refuses the deck with exit 2 before any motion; `show` and `check` name
//  them and exit 2):
//   - a condition card under a profile without condition units (parsons-1952, parsons-safe);
//   - an event identifier given twice for one motion card (claim 3: one identifier, one
//     condition and its action);
//   - more conditions before one motion card than buffer PFR holds;
//   - a condition on an axis its motion card does not move (check 0.000): never met;
//   - a tool change to a tool the profile's changer does not hold;
//   - a condition card with no motion card after it (claim 4: they stand before it);
//   - a cancel (an addition) of an identifier no every-condition stands under;
//  an every-condition (an addition) keeps its identifier and its pair from card to card until a
//  cancel, and is not judged against a motion card that leaves its axis standing;
//  and a finding the machine will stop on (condition_not_met, `check` exits 3): the motion card
//  moves the axis, but its counter never steps onto the position in the condition's sense
//  (judged from the previous stop to this card's stop, as the counters count: modulo 10 in).
#pragma once

#include "cardreader/orders.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace parsons::cardreader {

struct ConditionFinding {
    std::int64_t card = 0; // deck position the finding is on
    int column = 0;        // the column to look at on that card
    std::optional<Axis> axis;
    std::string message;
    bool deck_error = true; // false: the deck runs, and the machine stops (condition_not_met)
};

// How many condition/action pairs buffer PFR holds (relaylogic/conditions/internal_buffer.hpp).
inline constexpr int kBufferPairs = 10;

class ConditionReview {
public:
    // allowed: the profile has condition units; profile: its name, for the message; tools:
    // the numbers of the tools its changer holds (empty: not judged).
    explicit ConditionReview(bool allowed = true, std::string profile = "parsons-extended",
                             std::vector<int> tools = {})
        : allowed_(allowed), profile_(std::move(profile)), tools_(std::move(tools)) {}
    // The next card of the deck (index 1-based).
    std::vector<ConditionFinding> card(std::int64_t index, const CardOrders& orders);
    // A card that could not be read: conditions before it are not judged against it.
    void skip() { pending_.clear(); }
    // The end of the deck.
    std::vector<ConditionFinding> finish();

private:
    struct Pending {
        std::int64_t card = 0;
        int slot = 0;
        ConditionOrder condition;
    };
    // A cancel: removes the every-condition of `event`; false if none stands.
    bool cancel(int event);
    // An identifier already pending or standing: the finding is added.
    bool duplicate(std::int64_t index, int slot, const ConditionOrder& c,
                   std::vector<ConditionFinding>& found) const;
    std::vector<Pending> pending_;
    // Every-conditions armed for a motion card already and standing for the next (an addition
    // beyond the seed's claims): they keep their pair of PFR and their identifier until a
    // cancel.
    std::vector<Pending> standing_;
    bool allowed_;
    std::string profile_;
    std::vector<int> tools_;
};

} // namespace parsons::cardreader
