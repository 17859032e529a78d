#include "cardreader/deck_review.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace parsons::cardreader {
namespace {

constexpr int kCounterModulus = 10000; // four decimal stepping switches wrap 9.999 -> 0.000
// A coast of a thousandth or more is counted by commutator 102: the counter ends past the stop.
constexpr double kCoastWarning_in = 0.001;

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
    return travel_in_motion(from, value, motion) < travel_in_motion(from, stop, motion);
}

// v^2 after `inches` of running toward `target` at `a`: it rises or falls by 2 a per inch, and
// no further than the target.
double approach_v2(double v2, double target, double a, double inches) {
    const double t2 = target * target;
    return v2 < t2 ? std::min(t2, v2 + 2 * a * inches) : std::max(t2, v2 - 2 * a * inches);
}

std::string axis_list(const std::vector<Axis>& axes) {
    std::string text;
    for (std::size_t i = 0; i < axes.size(); ++i) {
        text += (i == 0 ? "" : i + 1 == axes.size() ? " and " : ", ");
        text += axis_name(axes[i]);
    }
    return text.empty() ? "none" : text;
}

bool punched_at(SequencePattern pattern, int position) {
    return (pattern & (1U << static_cast<unsigned>(position - 1))) != 0;
}

// One way the card's sequence can run: which axes stopped, in order, and where it stalled.
struct SequenceRun {
    std::vector<Axis> stopped;
    int stall_at = 0; // 0: the shaft went home
};

// Replays stepping shaft 280 (docs/design-rules.md rule 8): at each position the axes punched there
// that have not stopped run; an axis whose travel is zero stops at once (together with any other
// such axis: unit 284 counts each), otherwise any running axis may stop first. Each stop is one
// impulse, one position. Every possible order is followed (at most 5! of them).
void replay(const CardOrders& orders, const std::array<std::optional<Thousandths>, 5>& travel,
            int position, SequenceRun run, std::vector<SequenceRun>& runs) {
    if (position > kSequencePositions) {
        runs.push_back(std::move(run));
        return;
    }
    std::vector<Axis> idle;
    std::vector<Axis> moving;
    for (Axis a : kAxes) {
        const bool stopped =
            std::find(run.stopped.begin(), run.stopped.end(), a) != run.stopped.end();
        if (!stopped && punched_at(orders.axis(a).sequence, position)) {
            (travel.at(axis_index(a)) == Thousandths{0} ? idle : moving).push_back(a);
        }
    }
    if (!idle.empty()) {
        run.stopped.insert(run.stopped.end(), idle.begin(), idle.end());
        replay(orders, travel, position + static_cast<int>(idle.size()), std::move(run), runs);
        return;
    }
    if (moving.empty()) {
        run.stall_at = position;
        runs.push_back(std::move(run));
        return;
    }
    for (Axis a : moving) {
        SequenceRun next = run;
        next.stopped.push_back(a);
        replay(orders, travel, position + 1, std::move(next), runs);
    }
}

} // namespace

Thousandths travel_in_motion(Thousandths from, Thousandths to, Motion motion) {
    const int d = motion == Motion::forward ? to - from : from - to;
    return static_cast<Thousandths>((d % kCounterModulus + kCounterModulus) % kCounterModulus);
}

double speed_at_stop(const AxisOrder& order, Thousandths from, const AxisDynamics& dynamics) {
    const Thousandths travel = travel_in_motion(from, order.stop, order.motion);
    std::vector<Thousandths> events; // distances from `from` of the slow-downs passed
    for (const auto& sd : order.slow_down) {
        if (sd && passed_before_stop(*sd, from, order.stop, order.motion)) {
            events.push_back(travel_in_motion(from, *sd, order.motion));
        }
    }
    std::sort(events.begin(), events.end());
    events.push_back(travel);
    double v2 = 0; // every axis starts a card at rest
    int speed = std::clamp(order.start_speed, 1, 3);
    int at = 0;
    for (Thousandths e : events) {
        v2 = approach_v2(v2, dynamics.speed_in_per_s.at(static_cast<std::size_t>(speed - 1)),
                         dynamics.acceleration_in_per_s2, (e - at) / 1000.0);
        at = e;
        speed = std::min(speed + 1, 3); // each slow-down steps switch 236 one speed slower
    }
    return std::sqrt(v2);
}

double coast_in(const AxisOrder& order, Thousandths from, const AxisDynamics& dynamics) {
    const double v = speed_at_stop(order, from, dynamics);
    return v * v / (2 * dynamics.braking_in_per_s2);
}

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
    ++index_;
    conditions_.skip();
    sync_.skip();
    previous_number_.reset();
    coast_.fill(0);
    position_.fill(std::nullopt);
}

std::vector<ReviewNote> DeckReviewer::condition_notes(const CardOrders& orders) {
    std::vector<ReviewNote> notes;
    for (ConditionFinding& f : conditions_.card(index_, orders, position_)) {
        notes.push_back({f.axis, std::move(f.message), true, f.card, f.column, f.deck_error});
    }
    for (SyncFinding& f : sync_.card(index_, orders)) {
        notes.push_back({f.axis, std::move(f.message), true, f.card, f.column, true});
    }
    for (TapFinding& f : tap_.card(index_, orders)) {
        notes.push_back({f.axis, std::move(f.message), true, f.card, f.column, true});
    }
    return notes;
}

std::vector<ReviewNote> DeckReviewer::finish() {
    std::vector<ReviewNote> notes;
    for (ConditionFinding& f : conditions_.finish()) {
        notes.push_back({f.axis, std::move(f.message), true, f.card, f.column, f.deck_error});
    }
    for (SyncFinding& f : sync_.finish()) {
        notes.push_back({f.axis, std::move(f.message), true, f.card, f.column, true});
    }
    return notes;
}

std::vector<ReviewNote> DeckReviewer::review(const CardOrders& orders) {
    ++index_;
    std::vector<ReviewNote> notes = condition_notes(orders);
    if (previous_number_) {
        const int expected = (*previous_number_ + 1) % kCounterModulus;
        if (orders.number != expected) {
            notes.push_back({std::nullopt,
                             fmt::format("card number {:04} follows {:04} (expected {:04}): the "
                                         "card-number check stops the machine before any axis "
                                         "moves",
                                         orders.number, *previous_number_, expected),
                             true});
        }
    }
    previous_number_ = orders.number;
    if (orders.kind != CardKind::motion) {
        return notes; // no axis moves by the 1952 columns on a condition, sync or tap card
    }

    std::array<std::optional<Thousandths>, kAxisCount> travel{};
    for (Axis a : kAxes) {
        const AxisOrder& o = orders.axis(a);
        auto note = [&](std::string message, bool stops = false) {
            notes.push_back({a, std::move(message), stops});
        };
        if (o.sequence == 0) {
            note("no sequence position punched: the axis never runs (sequence stall)");
        }
        const std::optional<Thousandths> known_from = position_.at(axis_index(a));
        position_.at(axis_index(a)) = o.stop;
        if (!known_from) {
            continue; // after an unreadable card the starting point is unknown
        }
        const Thousandths from = *known_from;
        const Thousandths moves = travel_in_motion(from, o.stop, o.motion);
        travel.at(axis_index(a)) = moves;
        double& coast_before = coast_.at(axis_index(a));
        if (coast_before > 0) {
            note(fmt::format("the previous card's stop coasts about {:.3f} in past {} (see its "
                             "warning): the counters count the coast, so this card's check {} "
                             "disagrees and the machine stops",
                             coast_before, format_inches(from), format_inches(o.check)),
                 true);
            coast_before = 0;
        }

        if (o.check != moves) {
            const auto other_way =
                static_cast<Thousandths>((kCounterModulus - moves) % kCounterModulus);
            note(fmt::format("check {} but the stop {} is {} from the previous stop {} counting {} "
                             "(the counters wrap at 9.999 / 0.000): the increment comparer will "
                             "disagree with the absolute one and the machine stops{}",
                             format_inches(o.check), format_inches(o.stop), format_inches(moves),
                             format_inches(from),
                             o.motion == Motion::forward ? "up (motion +)" : "down (motion -)",
                             o.check == other_way && moves != 0
                                 ? "; the check is the travel the other way round: is the motion "
                                   "column wrong?"
                                 : ""),
                 true);
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
        if (dynamics_ && moves != 0) {
            const AxisDynamics& dyn = dynamics_->at(axis_index(a));
            const double v = speed_at_stop(o, from, dyn);
            const double coast = coast_in(o, from, dyn);
            if (coast >= kCoastWarning_in) {
                note(
                    fmt::format("slow-down too close to the stop: it reaches the stop {} still at "
                                "{:.2f} in/min (speed 3 is {:.2f}) and coasts about {:.3f} in past "
                                "it (v^2/2a, braking {} in/s^2); the counters count the coast and "
                                "the next card's check will disagree",
                                format_inches(o.stop), v * 60, dyn.speed_in_per_s[2] * 60, coast,
                                dyn.braking_in_per_s2));
                coast_before = coast;
            }
        }
    }
    review_sequence(orders, travel, notes);
    return notes;
}

void DeckReviewer::review_sequence(const CardOrders& orders,
                                   const std::array<std::optional<Thousandths>, kAxisCount>& travel,
                                   std::vector<ReviewNote>& notes) const {
    // Axes punched together at one position only: only one of them can stop there.
    for (int p = 1; p <= kSequencePositions; ++p) {
        std::vector<Axis> only_here;
        for (Axis a : kAxes) {
            if (orders.axis(a).sequence ==
                    static_cast<SequencePattern>(1U << static_cast<unsigned>(p - 1)) &&
                travel.at(axis_index(a)) != Thousandths{0}) {
                only_here.push_back(a);
            }
        }
        if (only_here.size() >= 2) {
            notes.push_back({std::nullopt,
                             fmt::format("{} are punched at position {} only: the first of them to "
                                         "stop steps shaft 280 on to {}, and the others are left "
                                         "short of their stops (sequence stall)",
                                         axis_list(only_here), p, p + 1)});
        }
    }
    std::vector<SequenceRun> runs;
    replay(orders, travel, 1, SequenceRun{}, runs);
    const auto stalled = std::count_if(runs.begin(), runs.end(),
                                       [](const SequenceRun& r) { return r.stall_at != 0; });
    if (stalled == 0) {
        return;
    }
    const auto first = *std::find_if(runs.begin(), runs.end(),
                                     [](const SequenceRun& r) { return r.stall_at != 0; });
    std::vector<Axis> waiting;
    for (Axis a : kAxes) {
        if (std::find(first.stopped.begin(), first.stopped.end(), a) == first.stopped.end()) {
            waiting.push_back(a);
        }
    }
    const std::string after = first.stopped.empty()
                                  ? std::string{}
                                  : fmt::format("after {} stop{}, ", axis_list(first.stopped),
                                                first.stopped.size() == 1 ? "s" : "");
    const std::string what =
        fmt::format("{}position {} of stepping shaft 280 is answered by no running axis (still "
                    "waiting: {}): no impulse comes and the shaft never returns home",
                    after, first.stall_at, axis_list(waiting));
    if (stalled == static_cast<std::int64_t>(runs.size())) {
        notes.push_back({std::nullopt, "sequence stall: " + what, true});
    } else {
        notes.push_back({std::nullopt, "sequence may stall, depending on which axis stops "
                                       "first: if they stop in this order, " +
                                           what});
    }
}

} // namespace parsons::cardreader
