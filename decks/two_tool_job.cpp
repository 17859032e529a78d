#include "decks/two_tool_job.hpp"

#include "decks/deck_limits.hpp"
#include "decks/move_planner.hpp"
#include "decks/units.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdint>

namespace parsons::decks {
namespace {

using cardreader::Axis;
using cardreader::CardOrders;
using Eigen::Vector2d;

constexpr cardreader::SequencePattern kFirst = 0b01000; // sequence position 4
constexpr cardreader::SequencePattern kLast = 0b10000;  // position 5: the cut (col. 11)

// One card of a pass, as a target in the common frame: which axis goes first, and whether a
// corner slowed it.
struct Move {
    int x = 0; // table, thousandths
    int y = 0; // cross slide
    bool table_first = false;
    bool corner = false;
};

// The moves of a template deck, carried into the frame whose work zero is `zero`.
std::vector<Move> moves_of(const TemplateDeck& d, const Vector2d& zero,
                           const axes::MachineProfile& profile) {
    const std::size_t approach = d.cards.size() + 1 - d.stations.size();
    const int dx = thousandths(zero.x() - d.work_zero_in.x());
    const int dy = thousandths(zero.y() - d.work_zero_in.y());
    std::vector<Move> moves;
    int px = 0; // where the template deck's own machine stood
    int py = 0;
    for (std::size_t j = 0; j < d.cards.size(); ++j) {
        const CardOrders& c = d.cards[j];
        const cardreader::AxisOrder& table = c.axis(Axis::table);
        const cardreader::AxisOrder& cross = c.axis(Axis::cross);
        Move m;
        m.table_first = table.sequence == kFirst;
        // A card planned as a plain move is what plan_move makes of it without the corner.
        const auto plain_table =
            plan_move({px, table.stop, 2, false, table.sequence}, profile.axes.at(0), profile);
        const auto plain_cross =
            plan_move({py, cross.stop, 1, false, cross.sequence}, profile.axes.at(1), profile);
        m.corner = !(plain_table == table && plain_cross == cross);
        if (j + 1 >= approach) { // a station card: quantised again from its cutter centre
            const Vector2d& centre = d.stations.at(j + 1 - approach).centre;
            assert(thousandths(centre.x() + d.work_zero_in.x()) == table.stop);
            assert(thousandths(centre.y() + d.work_zero_in.y()) == cross.stop);
            m.x = thousandths(centre.x() + zero.x());
            m.y = thousandths(centre.y() + zero.y());
        } else {
            m.x = table.stop + dx;
            m.y = cross.stop + dy;
        }
        px = table.stop;
        py = cross.stop;
        moves.push_back(m);
    }
    return moves;
}

// Punches the deck's cards one after the other, each move planned from where the machine
// stands, numbered consecutively from 1.
struct Punch {
    const axes::MachineProfile& profile;
    std::vector<CardOrders>& cards;
    int x = 0;
    int y = 0;

    CardOrders next_card() const {
        CardOrders c;
        c.number = static_cast<int>((cards.size() + 1) % 10000);
        return c;
    }
    // A card that would move nothing is left out. `spindle`: column 1 (the return to the change
    // position orders it off: the changer takes no turning cutter).
    void move(const Move& m, cardreader::Spindle spindle = cardreader::Spindle::forward) {
        if (m.x == x && m.y == y) {
            return;
        }
        CardOrders c = next_card();
        c.spindle = spindle;
        for (Axis a : cardreader::kAxes) {
            c.axis(a).start_speed = 3; // idle: stop at once where they stand (0), check 0
        }
        c.axis(Axis::vertical).sequence = 0b00001;
        c.axis(Axis::swivel).sequence = 0b00010;
        c.axis(Axis::tilt).sequence = 0b00100;
        c.axis(Axis::table) = plan_move({x, m.x, 2, m.corner, m.table_first ? kFirst : kLast},
                                        profile.axes.at(0), profile);
        c.axis(Axis::cross) = plan_move({y, m.y, 1, m.corner, m.table_first ? kLast : kFirst},
                                        profile.axes.at(1), profile);
        cards.push_back(c);
        x = m.x;
        y = m.y;
    }
    void condition(const cardreader::ConditionOrder& order) {
        CardOrders c = next_card();
        c.kind = cardreader::CardKind::condition;
        c.condition_count = 1;
        c.conditions.at(0) = order;
        cards.push_back(c);
    }
};

// How many cards the moves make from (x, y), where they leave the machine: a move that goes
// nowhere makes none (Punch::move).
std::int64_t count_cards(const std::vector<Move>& moves, int& x, int& y) {
    std::int64_t cards = 0;
    for (const Move& m : moves) {
        if (m.x != x || m.y != y) {
            ++cards;
            x = m.x;
            y = m.y;
        }
    }
    return cards;
}

// Refuses, before a card is punched, passes that together make more cards than a deck can
// number: pass 1, the lift, the condition card and the return move, pass 2.
void check_card_count(const TwoToolOptions& o, const std::vector<Move>& pass1,
                      const std::vector<Move>& pass2, int clearance) {
    int x = 0;
    int y = 0;
    const std::int64_t first = count_cards(pass1, x, y);
    const std::vector<Move> lift_and_return = {{x, clearance, true, false},
                                               {0, clearance, false, false}};
    const std::int64_t change = count_cards(lift_and_return, x, y) + 1; // and the condition card
    const std::int64_t second = count_cards(pass2, x, y);
    refuse_past_deck_limit(first + change + second,
                           o.pass.scallop_in > 0 ? fmt::format("--scallop {}", o.pass.scallop_in)
                                                 : fmt::format("--stations {}", o.pass.stations),
                           false,
                           fmt::format("pass 1 {}, the tool change {}, pass 2 {}",
                                       count_text(first), change, count_text(second)));
}

// When the axis passes each thousandth of its move (index: thousandths from the start; the
// last is the stop), from rest at t = 0. The speed switch starts on the start speed and steps
// one slower at each slow-down; the motor follows at the profile's acceleration.
std::vector<double> pass_times(const cardreader::AxisOrder& order, int from,
                               const axes::AxisProfile& axis) {
    const int travel = std::abs(static_cast<int>(order.stop) - from);
    std::vector<double> t_at(static_cast<std::size_t>(travel) + 1, 0.0);
    std::vector<int> slow_at; // distance from the start at which the switch steps slower
    for (const auto& s : order.slow_down) {
        if (s) {
            slow_at.push_back(std::abs(static_cast<int>(*s) - from));
        }
    }
    constexpr double kStep_s = 1e-4;
    int speed = order.start_speed;
    double v = 0;
    double x = 0; // inches from the start
    double t = 0;
    int next = 1;
    while (next <= travel) {
        const double target = speed_in_per_s(axis, std::min(speed, 3));
        const double dv = axis.acceleration_in_per_s2 * kStep_s;
        const double v1 = v < target ? std::min(target, v + dv) : std::max(target, v - dv);
        x += (v + v1) / 2 * kStep_s;
        v = v1;
        t += kStep_s;
        while (next <= travel && x >= next * 0.001) {
            t_at.at(static_cast<std::size_t>(next)) = t;
            if (std::find(slow_at.begin(), slow_at.end(), next) != slow_at.end()) {
                ++speed;
            }
            ++next;
        }
    }
    return t_at;
}

} // namespace

std::string_view variant_name(ChangeVariant v) {
    return v == ChangeVariant::tripped ? "tripped" : "boundary";
}

double time_to_stop_s(const cardreader::AxisOrder& order, int from, int position,
                      const axes::AxisProfile& axis) {
    const std::vector<double> t_at = pass_times(order, from, axis);
    const int k = std::clamp(std::abs(position - from), 0, static_cast<int>(t_at.size()) - 1);
    return t_at.back() - t_at.at(static_cast<std::size_t>(k));
}

TwoToolDeck make_two_tool_deck(const Airfoil& airfoil, const TwoToolOptions& o,
                               const axes::MachineProfile& profile) {
    if (o.pass.surface != Surface::upper || o.pass.female) {
        throw JobError("the two-tool job cuts the male template of the upper surface: the "
                       "cutter leaves its trailing edge by rising to the clearance height");
    }
    if (o.rough_tool == o.finish_tool) {
        throw JobError(
            fmt::format("tool {} for both passes: a two-tool job needs two tools", o.rough_tool));
    }
    const auto r1 = profile.tool_radius_in(o.rough_tool);
    const auto r2 = profile.tool_radius_in(o.finish_tool);
    for (const auto& [tool, radius] : {std::pair{o.rough_tool, r1}, std::pair{o.finish_tool, r2}}) {
        if (!radius) {
            throw JobError(fmt::format("the machine profile '{}' has no tool {} in its tool "
                                       "changer (profile key tools)",
                                       profile.name, tool));
        }
    }
    for (const auto& [tool, radius] : {std::pair{o.rough_tool, r1}, std::pair{o.finish_tool, r2}}) {
        if (!(*radius >= kLeastCutterRadiusIn)) {
            throw JobError(fmt::format("the machine profile '{}' gives tool {} a radius of {} in: "
                                       "a cutter radius under {:.3f} in is less than one impulse, "
                                       "the smallest move the machine makes",
                                       profile.name, tool, *radius, kLeastCutterRadiusIn));
        }
    }
    if (!(o.allowance_in >= 0) || o.allowance_in > 0.1) {
        throw JobError(fmt::format("allowance {} in: give 0 .. 0.1 in", o.allowance_in));
    }
    if (!(o.lead_fraction > 0 && o.lead_fraction < 1)) {
        throw JobError("the tripped change must begin less than its own length before the "
                       "table stops (lead fraction between 0 and 1)");
    }

    TwoToolDeck job;
    TemplateOptions pass1 = o.pass;
    pass1.cutter_radius_in = *r1 + o.allowance_in;
    TemplateOptions pass2 = o.pass;
    pass2.cutter_radius_in = *r2;
    job.passes.at(0) = {o.rough_tool,
                        *r1,
                        pass1.cutter_radius_in,
                        make_template_deck(airfoil, pass1, profile),
                        0,
                        0};
    job.passes.at(1) = {o.finish_tool,
                        *r2,
                        pass2.cutter_radius_in,
                        make_template_deck(airfoil, pass2, profile),
                        0,
                        0};
    job.work_zero_in = job.passes[0].deck.work_zero_in.cwiseMax(job.passes[1].deck.work_zero_in);

    // The clearance: margin/2 above every cutter centre of both passes; all in the counters.
    Vector2d hi(-1e9, -1e9);
    for (const TwoToolPass& p : job.passes) {
        for (const Station& s : p.deck.stations) {
            hi = hi.cwiseMax(s.centre + job.work_zero_in);
        }
    }
    job.clearance = thousandths(hi.y() + o.pass.margin_in / 2);
    if (thousandths(hi.x()) > cardreader::kMaxThousandths ||
        job.clearance > cardreader::kMaxThousandths) {
        throw JobError(fmt::format("the two passes and the clearance above them need {:.3f} x "
                                   "{:.3f} in of the counters' 9.999 in: use a shorter chord",
                                   hi.x(), job.clearance / 1000.0));
    }

    const std::vector<Move> pass1_moves = moves_of(job.passes[0].deck, job.work_zero_in, profile);
    const std::vector<Move> pass2_moves = moves_of(job.passes[1].deck, job.work_zero_in, profile);
    check_card_count(o, pass1_moves, pass2_moves, job.clearance);

    Punch punch{profile, job.cards};
    job.passes[0].first_card = 0;
    for (const Move& m : pass1_moves) {
        punch.move(m);
    }
    job.passes[0].card_count = job.cards.size();

    job.lift_card = job.cards.size();
    punch.move({punch.x, job.clearance, true, false});
    job.return_from = punch.x;
    job.condition_card = job.cards.size();
    punch.condition({}); // its position is set below, from the return move's own card
    job.return_card = job.cards.size();
    // The table last: its stop ends the card. The spindle runs down on the way (column 1 blank):
    // the change begins once it stands.
    punch.move({0, job.clearance, false, false}, cardreader::Spindle::off);

    const cardreader::AxisOrder& back = job.cards.at(job.return_card).axis(Axis::table);
    const std::vector<double> t_at = pass_times(back, job.return_from, profile.axes.at(0));
    job.return_move_s = t_at.back();
    job.trip_position = 0;
    if (o.variant == ChangeVariant::tripped) {
        // The position nearest the stop from which the table still needs the lead to stop.
        const double lead = o.lead_fraction * profile.actions.tool_change_s;
        const int travel = static_cast<int>(t_at.size()) - 1;
        // k: thousandths from the start; from the impulse before the stop back toward the
        // start, and at most back to the first impulse (a move shorter than the lead).
        int k = travel - 1;
        while (k > 1 && t_at.back() - t_at.at(static_cast<std::size_t>(k)) < lead) {
            --k;
        }
        job.trip_position = job.return_from - k;
        job.planned_lead_s = t_at.back() - t_at.at(static_cast<std::size_t>(k));
    }
    cardreader::ConditionOrder& c = job.cards.at(job.condition_card).conditions.at(0);
    c.event = 1;
    c.axis = Axis::table;
    c.position = static_cast<cardreader::Thousandths>(job.trip_position);
    c.sense = cardreader::PassingSense::reverse;
    c.action = cardreader::ActionKind::tool_change;
    c.parameter = o.finish_tool;

    job.passes[1].first_card = job.cards.size();
    for (const Move& m : pass2_moves) {
        punch.move(m);
    }
    job.passes[1].card_count = job.cards.size() - job.passes[1].first_card;
    return job;
}

} // namespace parsons::decks
