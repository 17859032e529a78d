#include "cardreader/sync_review.hpp"

#include "cardreader/layout.hpp"

#include <fmt/format.h>

#include <cmath>

namespace parsons::cardreader {
namespace {

int sync_column(FieldKind kind, std::optional<Axis> axis = std::nullopt) {
    const LayoutField* f = fig8_layout().find_sync(kind, axis);
    return f ? f->first_column : 0;
}

int extension_column() {
    return fig8_layout().extension_column;
}

} // namespace

int PressLimits::max_travel_per_pulse() const {
    const double pulses = fastest_pulses_per_s();
    if (pulses <= 0) {
        return kMaxTravelPerPulse;
    }
    return static_cast<int>(std::floor(drive_max_in_per_min / 60.0 / pulses * 1e5 + 1e-9));
}

std::vector<SyncFinding> SyncReview::card(std::int64_t index, const CardOrders& orders) {
    std::vector<SyncFinding> found;
    if (orders.kind == CardKind::sync) {
        if (!allowed_) {
            found.push_back({index, extension_column(), std::nullopt,
                             fmt::format("a sync card (an addition after EP 0436887, Mitsubishi): "
                                         "profile {} has no press synchronisation; the built-in "
                                         "profile parsons-extended has it (--profile "
                                         "parsons-extended)",
                                         profile_)});
        }
        if (orders.sync.loop) {
            loop_card(index, orders, found);
        } else {
            sync_card(index, orders, found);
        }
    } else if (orders.kind == CardKind::motion) {
        motion_card(index, orders, found);
    }
    numbers_.insert(orders.number);
    return found;
}

void SyncReview::sync_card(std::int64_t index, const CardOrders& orders,
                           std::vector<SyncFinding>& found) {
    const SyncOrder& s = orders.sync;
    const double pulses = limits_.fastest_pulses_per_s();
    for (Axis a : kAxes) {
        const auto& f = s.travel_per_pulse.at(axis_index(a));
        if (!f || pulses <= 0) {
            continue;
        }
        const double needs_in_per_min = *f / 1e5 * pulses * 60.0;
        if (needs_in_per_min <= limits_.drive_max_in_per_min + 1e-9) {
            continue;
        }
        const std::string faster =
            limits_.fastest_factor > 1.0
                ? fmt::format(" x {:g} with its variation and change of speed",
                              limits_.fastest_factor)
                : std::string{};
        found.push_back({index, sync_column(FieldKind::travel_per_pulse, a), a,
                         fmt::format("{} travel per pulse {} in needs {:.1f} in/min at the press's "
                                     "fastest ({:g} strokes a minute{}, {} pulses a degree); the "
                                     "sync drive follows at most {:g} in/min: at most {} in per "
                                     "pulse",
                                     axis_name(a), format_travel_per_pulse(*f), needs_in_per_min,
                                     limits_.strokes_per_min, faster, limits_.pulses_per_degree,
                                     limits_.drive_max_in_per_min,
                                     format_travel_per_pulse(limits_.max_travel_per_pulse()))});
    }
    if (pending_) {
        found.push_back({index, extension_column(), std::nullopt,
                         fmt::format("a second sync card before one motion card (the first is "
                                     "card {}): the synchronisation of a motion card is punched "
                                     "on one sync card before it",
                                     pending_->card)});
        return; // the first still waits for its motion card
    }
    if (s.synchronises()) {
        pending_ = Pending{index, s}; // a card of the reset alone acts as it is read
    }
}

void SyncReview::loop_card(std::int64_t index, const CardOrders& orders,
                           std::vector<SyncFinding>& found) {
    if (pending_) {
        found.push_back({pending_->card, extension_column(), std::nullopt,
                         fmt::format("a sync card with no motion card after it: loop card {} "
                                     "comes next (a sync card stands before the motion card it "
                                     "synchronises)",
                                     index)});
        pending_.reset();
    }
    const int target = orders.sync.loop_to;
    if (numbers_.count(target) == 0) {
        found.push_back({index, sync_column(FieldKind::loop_target), std::nullopt,
                         fmt::format("a loop to card number {:04}, which the deck does not hold "
                                     "before this card (the loop goes back to a card already "
                                     "read)",
                                     target)});
    }
}

void SyncReview::motion_card(std::int64_t index, const CardOrders& orders,
                             std::vector<SyncFinding>& found) {
    if (!pending_) {
        return;
    }
    for (Axis a : kAxes) {
        const auto& f = pending_->order.travel_per_pulse.at(axis_index(a));
        if (f && orders.axis(a).check == 0) {
            found.push_back({pending_->card, sync_column(FieldKind::travel_per_pulse, a), a,
                             fmt::format("speed sync on the {} axis ({} in per pulse), which "
                                         "motion card {} does not move (check 0.000)",
                                         axis_name(a), format_travel_per_pulse(*f), index)});
        }
    }
    pending_.reset();
}

std::vector<SyncFinding> SyncReview::finish() {
    std::vector<SyncFinding> found;
    if (pending_) {
        found.push_back({pending_->card, extension_column(), std::nullopt,
                         "a sync card with no motion card after it: the deck ends (a sync card "
                         "stands before the motion card it synchronises)"});
    }
    pending_.reset();
    return found;
}

} // namespace parsons::cardreader
