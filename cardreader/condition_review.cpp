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
            bool duplicate = false;
            for (const Pending& p : pending_) {
                if (p.condition.event == c.event) {
                    duplicate = true;
                    found.push_back(
                        {index, slot_column(slot, 0), c.axis,
                         fmt::format("condition {}: event {} is given twice for the same motion "
                                     "card (first on card {}, condition {}): one identifier "
                                     "names one condition and its action (EP 0640901 claim 3)",
                                     slot + 1, c.event, p.card, p.slot + 1),
                         true});
                    break;
                }
            }
            if (duplicate) {
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
            if (static_cast<int>(pending_.size()) == kBufferPairs) {
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
