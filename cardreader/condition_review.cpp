#include "cardreader/condition_review.hpp"

#include "cardreader/condition_card.hpp"
#include "cardreader/deck_review.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace parsons::cardreader {
namespace {

constexpr int kExtensionColumn = 76;

int slot_column(int slot, int offset) {
    return 1 + slot * kConditionSlotColumns + offset;
}

} // namespace

std::vector<ConditionFinding> ConditionReview::card(std::int64_t index, const CardOrders& orders) {
    std::vector<ConditionFinding> found;
    if (orders.kind == CardKind::sync || orders.kind == CardKind::tap) {
        // A sync card moves nothing, and a tap card's feed is not a motion card's: the
        // conditions wait for the motion card.
        return found;
    }
    if (orders.kind == CardKind::condition) {
        if (!allowed_) {
            found.push_back({index, kExtensionColumn, std::nullopt,
                             fmt::format("a condition card (an addition after EP 0640901, "
                                         "Siemens): profile {} has no condition units; the "
                                         "built-in profile parsons-extended allows them "
                                         "(--profile parsons-extended)",
                                         profile_),
                             true});
        }
        for (int slot = 0; slot < orders.condition_count; ++slot) {
            const ConditionOrder& c = orders.conditions.at(static_cast<std::size_t>(slot));
            if (c.mode == ConditionMode::cancel) {
                if (!cancel(c.event)) {
                    found.push_back(
                        {index, slot_column(slot, kConditionModeOffset), std::nullopt,
                         fmt::format("condition {}: a cancel of event {}, but no every-condition "
                                     "with that identifier stands (every and cancel are an "
                                     "addition beyond EP 0640901's claims, after Siemens' "
                                     "WHENEVER/EVERY)",
                                     slot + 1, c.event),
                         true});
                }
                continue;
            }
            if (duplicate(index, slot, c, found)) {
                continue;
            }
            if (c.action == ActionKind::tool_change && !tools_.empty() &&
                std::find(tools_.begin(), tools_.end(), c.parameter) == tools_.end()) {
                std::string held;
                for (int t : tools_) {
                    held += fmt::format("{}{}", held.empty() ? "" : ", ", t);
                }
                found.push_back({index, slot_column(slot, 9), c.axis,
                                 fmt::format("condition {}: tool {} is not in the tool changer of "
                                             "profile {} (it holds tools {})",
                                             slot + 1, c.parameter, profile_, held),
                                 true});
            }
            if (static_cast<int>(pending_.size() + standing_.size()) == kBufferPairs) {
                found.push_back(
                    {index, slot_column(slot, 0), c.axis,
                     fmt::format("condition {}: more than {} conditions before one "
                                 "motion card: buffer PFR holds {} (condition cards are an "
                                 "addition after EP 0640901)",
                                 slot + 1, kBufferPairs, kBufferPairs),
                     true});
                continue;
            }
            pending_.push_back({index, slot, c});
        }
        return found;
    }
    for (const Pending& p : pending_) {
        const ConditionOrder& c = p.condition;
        const AxisOrder& o = orders.axis(c.axis);
        if (c.mode == ConditionMode::every) {
            standing_.push_back(p); // armed from this card on, met or not on each
            continue;
        }
        if (o.check == 0) {
            found.push_back({p.card, slot_column(p.slot, 2), c.axis,
                             fmt::format("condition {}: event {} watches the {} axis, which motion "
                                         "card {} does not move (check 0.000): it could never be "
                                         "met (condition cards are an addition after EP 0640901)",
                                         p.slot + 1, c.event, axis_name(c.axis), index),
                             true});
            continue;
        }
        // Whether the counter steps onto the position is the run's to find (monitoring unit
        // PRG in relaylogic/conditions/): `check` runs the deck and says condition_not_met.
    }
    pending_.clear();
    return found;
}

bool ConditionReview::cancel(int event) {
    for (auto* list : {&pending_, &standing_}) {
        const auto it = std::find_if(list->begin(), list->end(), [&](const Pending& p) {
            return p.condition.event == event && p.condition.mode == ConditionMode::every;
        });
        if (it != list->end()) {
            list->erase(it);
            return true;
        }
    }
    return false;
}

bool ConditionReview::duplicate(std::int64_t index, int slot, const ConditionOrder& c,
                                std::vector<ConditionFinding>& found) const {
    for (const auto* list : {&pending_, &standing_}) {
        for (const Pending& p : *list) {
            if (p.condition.event != c.event) {
                continue;
            }
            const bool standing = list == &standing_ || p.condition.mode == ConditionMode::every;
            found.push_back(
                {index, slot_column(slot, 0), c.axis,
                 standing
                     ? fmt::format("condition {}: event {} stands as an every-condition (card {}, "
                                   "condition {}) until it is cancelled: one identifier names one "
                                   "condition and its action (EP 0640901 claim 3; cancel it "
                                   "first)",
                                   slot + 1, c.event, p.card, p.slot + 1)
                     : fmt::format("condition {}: event {} is given twice for the same motion "
                                   "card (first on card {}, condition {}): one identifier "
                                   "names one condition and its action (EP 0640901 claim 3)",
                                   slot + 1, c.event, p.card, p.slot + 1),
                 true});
            return true;
        }
    }
    return false;
}

std::vector<ConditionFinding> ConditionReview::finish() {
    std::vector<ConditionFinding> found;
    if (!pending_.empty()) {
        const Pending& last = pending_.back();
        found.push_back({last.card, kExtensionColumn, std::nullopt,
                         fmt::format("a condition card with no motion card after it: the deck "
                                     "ends (condition cards stand before the motion card they "
                                     "watch, EP 0640901 claim 4)"),
                         true});
    }
    pending_.clear();
    return found;
}

} // namespace parsons::cardreader
