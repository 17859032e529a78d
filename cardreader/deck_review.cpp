#include "cardreader/deck_review.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>

namespace parsons::cardreader {
namespace {

constexpr int kCounterModulus = 10000; // four decimal stepping switches wrap 9.999 -> 0.000

std::vector<Thousandths> punched_numbers(const AxisOrder& order) {
    std::vector<Thousandths> numbers;
    for (const auto& sd : order.slow_down) {
        if (sd) {
            numbers.push_back(*sd);
        }
    }
    numbers.push_back(order.stop);
    return numbers;
}

int digit(Thousandths n, int place) { // place 0 = thousandths .. 3 = inches
    for (int i = 0; i < place; ++i) {
        n = static_cast<Thousandths>(n / 10);
    }
    return n % 10;
}

// True if the counters, counting from `from` in the motion's direction, reach `value`
// strictly before they reach `stop`.
bool passed_before_stop(Thousandths value, Thousandths from, Thousandths stop, Motion motion) {
    return travel_in_motion(from, value, motion) < travel_in_motion(from, stop, motion);
}

} // namespace

Thousandths travel_in_motion(Thousandths from, Thousandths to, Motion motion) {
    const int d = motion == Motion::forward ? to - from : from - to;
    return static_cast<Thousandths>((d % kCounterModulus + kCounterModulus) % kCounterModulus);
}

namespace {

// The digits the shared banks close for the order's slow-downs and stop: one bit a digit, for
// bank 356 (thousandths, place 0) .. 350 (inches, place 3).
std::array<unsigned, 4> closed_digits(const AxisOrder& order) {
    std::array<unsigned, 4> closed{};
    for (Thousandths n : punched_numbers(order)) {
        for (std::size_t place = 0; place < 4; ++place) {
            closed.at(place) |= 1U << static_cast<unsigned>(digit(n, static_cast<int>(place)));
        }
    }
    return closed;
}

// Calls `each` with every number the banks compare equal at, ascending (inches digit slowest),
// until it returns false.
template <typename Each>
void for_each_match(const AxisOrder& order, Each each) {
    const auto closed = closed_digits(order);
    for (int a = 0; a < 10; ++a) {
        if ((closed[3] >> a & 1U) == 0) {
            continue;
        }
        for (int b = 0; b < 10; ++b) {
            if ((closed[2] >> b & 1U) == 0) {
                continue;
            }
            for (int c = 0; c < 10; ++c) {
                if ((closed[1] >> c & 1U) == 0) {
                    continue;
                }
                for (int d = 0; d < 10; ++d) {
                    if ((closed[0] >> d & 1U) != 0 &&
                        !each(static_cast<Thousandths>(a * 1000 + b * 100 + c * 10 + d))) {
                        return;
                    }
                }
            }
        }
    }
}

} // namespace

std::vector<Thousandths> shared_bank_matches(const AxisOrder& order) {
    // Bank 350 holds the inch digit, 352 tenths, 354 hundredths, 356 thousandths.
    std::vector<Thousandths> matches;
    for_each_match(order, [&matches](Thousandths m) {
        matches.push_back(m);
        return true;
    });
    return matches;
}

std::vector<Thousandths> spurious_matches_on_path(const AxisOrder& order, Thousandths from) {
    const auto punched = punched_numbers(order);
    std::vector<Thousandths> spurious;
    for_each_match(order, [&](Thousandths m) {
        const bool is_punched = std::find(punched.begin(), punched.end(), m) != punched.end();
        if (!is_punched && passed_before_stop(m, from, order.stop, order.motion)) {
            spurious.push_back(m);
        }
        return true;
    });
    return spurious;
}

bool spurious_match_on_path(const AxisOrder& order, Thousandths from) {
    const auto punched = punched_numbers(order);
    bool found = false;
    for_each_match(order, [&](Thousandths m) {
        found = std::find(punched.begin(), punched.end(), m) == punched.end() &&
                passed_before_stop(m, from, order.stop, order.motion);
        return !found;
    });
    return found;
}

void DeckReviewer::skip() {
    ++index_;
    conditions_.skip();
    sync_.skip();
    position_.fill(std::nullopt);
}

std::vector<ReviewNote> DeckReviewer::condition_notes(const CardOrders& orders) {
    std::vector<ReviewNote> notes;
    for (ConditionFinding& f : conditions_.card(index_, orders)) {
        notes.push_back({f.axis, std::move(f.message), f.card, f.column, f.deck_error});
    }
    for (SyncFinding& f : sync_.card(index_, orders)) {
        notes.push_back({f.axis, std::move(f.message), f.card, f.column, true});
    }
    for (TapFinding& f : tap_.card(index_, orders)) {
        notes.push_back({f.axis, std::move(f.message), f.card, f.column, true});
    }
    if (orders.kind == CardKind::segment && !segments_allowed_) {
        notes.push_back({std::nullopt,
                         fmt::format("a segment card (an addition after EP 0636958, Black & "
                                     "Decker): profile {} has no contouring (stepper axes and "
                                     "their interpolator); the built-in profile parsons-extended "
                                     "has it",
                                     segments_profile_),
                         index_, 76, true});
    }
    return notes;
}

std::vector<ReviewNote> DeckReviewer::finish() {
    std::vector<ReviewNote> notes;
    for (ConditionFinding& f : conditions_.finish()) {
        notes.push_back({f.axis, std::move(f.message), f.card, f.column, f.deck_error});
    }
    for (SyncFinding& f : sync_.finish()) {
        notes.push_back({f.axis, std::move(f.message), f.card, f.column, true});
    }
    return notes;
}

std::vector<ReviewNote> DeckReviewer::review(const CardOrders& orders) {
    ++index_;
    std::vector<ReviewNote> notes = condition_notes(orders);
    if (orders.kind != CardKind::motion) {
        return notes; // no axis moves by the 1952 columns on a condition, sync or tap card
    }
    for (Axis a : kAxes) {
        const AxisOrder& o = orders.axis(a);
        const std::optional<Thousandths> known_from = position_.at(axis_index(a));
        position_.at(axis_index(a)) = o.stop;
        const int slow_downs = static_cast<int>(o.slow_down[0].has_value()) +
                               static_cast<int>(o.slow_down[1].has_value());
        if (slow_downs != 3 - o.start_speed) {
            notes.push_back({a, fmt::format("start speed {} with {} slow-down(s) punched: a card "
                                            "punches 3 - start speed = {} of them, one for each "
                                            "step of speed switch 236 to speed 3",
                                            o.start_speed, slow_downs, 3 - o.start_speed)});
        }
        if (!known_from) {
            continue; // after an unreadable card the starting point is unknown
        }
        const Thousandths from = *known_from;
        for (std::size_t i = 0; i < 2; ++i) {
            const auto& sd = o.slow_down.at(i);
            if (sd && o.stop != from && !passed_before_stop(*sd, from, o.stop, o.motion)) {
                notes.push_back(
                    {a, fmt::format("{} slow-down {} is not on the way from the stop before, {}, "
                                    "to the stop {}",
                                    i == 0 ? "first" : "second", format_inches(*sd),
                                    format_inches(from), format_inches(o.stop))});
            }
        }
    }
    return notes;
}

} // namespace parsons::cardreader
