#include "cardreader/deck_review.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>

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

std::string list_inches(const std::vector<Thousandths>& values) {
    std::string text;
    const std::size_t shown = std::min<std::size_t>(values.size(), 6);
    for (std::size_t i = 0; i < shown; ++i) {
        text += (i == 0 ? "" : ", ") + format_inches(values[i]);
    }
    if (values.size() > shown) {
        text += fmt::format(" and {} more", values.size() - shown);
    }
    return text;
}

// True if the counters, counting from `from` in the motion's direction, reach `value`
// strictly before they reach `stop`.
bool passed_before_stop(Thousandths value, Thousandths from, Thousandths stop, Motion motion) {
    auto distance = [motion, from](Thousandths to) {
        int d = motion == Motion::forward ? to - from : from - to;
        return (d % kCounterModulus + kCounterModulus) % kCounterModulus;
    };
    return distance(value) < distance(stop);
}

} // namespace

std::vector<Thousandths> shared_bank_matches(const AxisOrder& order) {
    // Bank 350 holds the inch digit, 352 tenths, 354 hundredths, 356 thousandths.
    std::array<std::set<int>, 4> closed;
    for (Thousandths n : punched_numbers(order)) {
        for (int place = 0; place < 4; ++place) {
            closed.at(static_cast<std::size_t>(place)).insert(digit(n, place));
        }
    }
    std::vector<Thousandths> matches;
    for (int a : closed[3]) {
        for (int b : closed[2]) {
            for (int c : closed[1]) {
                for (int d : closed[0]) {
                    matches.push_back(static_cast<Thousandths>(a * 1000 + b * 100 + c * 10 + d));
                }
            }
        }
    }
    std::sort(matches.begin(), matches.end());
    return matches;
}

std::vector<Thousandths> spurious_matches_on_path(const AxisOrder& order, Thousandths from) {
    const auto punched = punched_numbers(order);
    std::vector<Thousandths> spurious;
    for (Thousandths m : shared_bank_matches(order)) {
        const bool is_punched = std::find(punched.begin(), punched.end(), m) != punched.end();
        if (!is_punched && passed_before_stop(m, from, order.stop, order.motion)) {
            spurious.push_back(m);
        }
    }
    return spurious;
}

void DeckReviewer::skip() {
    previous_number_.reset();
    position_.fill(std::nullopt);
}

std::vector<ReviewNote> DeckReviewer::review(const CardOrders& orders) {
    std::vector<ReviewNote> notes;
    if (previous_number_) {
        const int expected = (*previous_number_ + 1) % kCounterModulus;
        if (orders.number != expected) {
            notes.push_back(
                {std::nullopt, fmt::format("card number {:04} follows {:04} (expected {:04}): the "
                                           "card-number check stops the machine before any axis "
                                           "moves",
                                           orders.number, *previous_number_, expected)});
        }
    }
    previous_number_ = orders.number;

    for (Axis a : kAxes) {
        const AxisOrder& o = orders.axis(a);
        auto note = [&](std::string message) { notes.push_back({a, std::move(message)}); };
        if (o.sequence == 0) {
            note("no sequence position punched: the axis never runs (sequence stall)");
        }
        const std::optional<Thousandths> known_from = position_.at(axis_index(a));
        position_.at(axis_index(a)) = o.stop;
        if (!known_from) {
            continue; // after an unreadable card the starting point is unknown
        }
        const Thousandths from = *known_from;
        const int travel = o.stop > from ? o.stop - from : from - o.stop;

        if (o.check != travel) {
            note(fmt::format("check {} but the stop moves {} from the previous stop {} (check = "
                             "|stop - previous stop|): the increment comparer will disagree with "
                             "the absolute one and the machine stops",
                             format_inches(o.check),
                             format_inches(static_cast<Thousandths>(travel)), format_inches(from)));
        }
        if ((o.motion == Motion::forward && o.stop < from) ||
            (o.motion == Motion::reverse && o.stop > from)) {
            note(fmt::format("motion {} but the stop {} is {} the previous stop {}: the counters "
                             "count the long way round through {}",
                             o.motion == Motion::forward ? "+ (forward)" : "- (reverse)",
                             format_inches(o.stop), o.motion == Motion::forward ? "below" : "above",
                             format_inches(from),
                             o.motion == Motion::forward ? "9.999 to 0.000" : "0.000 to 9.999"));
        }
        const int slow_downs = static_cast<int>(o.slow_down[0].has_value()) +
                               static_cast<int>(o.slow_down[1].has_value());
        if (slow_downs != 3 - o.start_speed) {
            note(fmt::format("start speed {} with {} slow-down(s) punched (a card punches 3 - "
                             "start speed = {}): speed switch 236 will not stand on speed 3 at "
                             "the stop",
                             o.start_speed, slow_downs, 3 - o.start_speed));
        }
        for (std::size_t i = 0; i < 2; ++i) {
            const auto& sd = o.slow_down.at(i);
            if (sd && o.stop != from && !passed_before_stop(*sd, from, o.stop, o.motion)) {
                note(fmt::format("{} slow-down {} is not on the way from {} to the stop {}: the "
                                 "counters never reach it before the stop",
                                 i == 0 ? "first" : "second", format_inches(*sd),
                                 format_inches(from), format_inches(o.stop)));
            }
        }
        const auto spurious = spurious_matches_on_path(o, from);
        if (!spurious.empty()) {
            note(fmt::format("shared-bank hazard: the absolute banks 350-356 also compare equal "
                             "at {} on the way from {} to {} (slow-downs and stop differ in more "
                             "than one digit)",
                             list_inches(spurious), format_inches(from), format_inches(o.stop)));
        }
    }
    return notes;
}

} // namespace parsons::cardreader
