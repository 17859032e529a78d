#include "tests/random_decks.hpp"

#include "cardreader/deck_review.hpp"
#include "cardreader/hollerith.hpp"
#include "cardreader/layout.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <stdexcept>

namespace parsons::test {

using namespace parsons::cardreader;
using namespace parsons::relaylogic;

Case random_case(std::mt19937& rng, std::mt19937& crng, std::mt19937& srng, std::mt19937& trng) {
    auto tpick = [&trng](int lo, int hi) {
        return std::uniform_int_distribution<int>(lo, hi)(trng);
    };
    auto tchance = [&trng](double p) { return std::bernoulli_distribution(p)(trng); };
    auto treal = [&trng](double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(trng);
    };
    auto spick = [&srng](int lo, int hi) {
        return std::uniform_int_distribution<int>(lo, hi)(srng);
    };
    auto schance = [&srng](double p) { return std::bernoulli_distribution(p)(srng); };
    auto sreal = [&srng](double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(srng);
    };
    auto cpick = [&crng](int lo, int hi) {
        return std::uniform_int_distribution<int>(lo, hi)(crng);
    };
    auto cchance = [&crng](double p) { return std::bernoulli_distribution(p)(crng); };
    auto creal = [&crng](double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(crng);
    };
    auto pick = [&rng](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    auto chance = [&rng](double p) { return std::bernoulli_distribution(p)(rng); };
    auto real = [&rng](double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(rng);
    };
    Case c;
    auto& p = c.profile;
    const bool fast = chance(0.3);
    for (auto& a : p.axes) {
        if (fast) {
            const double scale = real(0.5, 3.0); // speed 1 up to 270 impulses a second
            for (double& s : a.speed_in_per_min) {
                s *= scale;
            }
        }
        if (chance(0.3)) {
            a.acceleration_in_per_s2 = real(0.05, 2.0);
            a.braking_in_per_s2 = real(0.05, 2.0);
        }
        if (chance(0.1)) {
            a.screw_error_in = {{0.0, real(-0.002, 0.002)},
                                {5.0, real(-0.002, 0.002)},
                                {10.0, real(-0.002, 0.002)}};
        }
        // The measuring chain of Fig. 3: backlash in nut 78, lead screw 22's error,
        // instrument shaft 74's error and cam 160.
        if (chance(0.2)) {
            a.backlash_in = real(0, 0.004);
        }
        if (chance(0.1)) {
            a.lead_error_in = {{0.0, real(-0.003, 0.003)},
                               {4.0, real(-0.003, 0.003)},
                               {10.0, real(-0.003, 0.003)}};
        }
        if (chance(0.1)) {
            a.instrument_error_in = {{0.0, real(-0.002, 0.002)}, {10.0, real(-0.002, 0.002)}};
            a.cam_160_in = {{1.0, real(-0.002, 0.002)}, {6.0, real(-0.002, 0.002)}};
        }
        if (chance(0.05)) {
            a.travel_min_in = real(-0.5, -0.001);
            a.travel_max_in = real(4.0, 10.5);
        }
        if (chance(0.1)) {
            a.soft_limits = true;
            a.soft_min_in = real(-0.4, -0.001);
            a.soft_max_in = real(1.0, 10.0);
        }
    }
    if (!fast && chance(0.3)) {
        p.max_stepping_rate_per_s = real(60, 300);
    }
    if (chance(0.15)) {
        p.delay_258_s = real(0.001, 0.02);
    }
    p.separate_registers = chance(0.2);
    p.count_hundredths_at_speed_1 = chance(0.15);
    p.ribbon_feed = chance(0.3); // Fig. 9: cards end to end, no feed gap
    c.medium = std::array{DeckFormat::cbn, DeckFormat::tape, DeckFormat::five}.at(
        static_cast<std::size_t>(pick(0, 2)));
    // The readings of the patent and the additions (MachineProfile's last group).
    p.incremental_equality_stops_at_any_speed = chance(0.2);
    p.delay_258_waits_for_equality_to_leave = chance(0.2);
    p.lamps_only_on_trip = chance(0.2);
    p.refuse_double_punch = chance(0.3);
    p.measuring_chain =
        chance(0.3) ? axes::MeasuringChain::screw_turns : axes::MeasuringChain::instrument_shaft_74;
    // Condition cards (an addition after EP 0640901): before some motion cards, conditions on
    // the path of a moving axis (met), anywhere (often never met) or on an idle axis.
    p.condition_cards = cchance(0.35);
    if (p.condition_cards) {
        p.actions.tool_change_s = creal(0.01, 30);
        p.actions.dwell_s = creal(0.01, 5);
        p.actions.spindle_run_up_s = creal(0.01, 5);
        c.medium = cchance(0.5) ? DeckFormat::cbn : DeckFormat::tape; // .five has no column 76
    }
    // Press synchronisation (an addition after EP 0436887): a press of any pace and temper,
    // sync cards before some motion cards, sometimes a loop back.
    p.press_sync = schance(0.3);
    if (p.press_sync) {
        axes::PressProfile& press = p.press;
        press.pulses_per_degree = spick(1, 8);
        // Its pulses within what the position register's switches follow.
        press.strokes_per_min = sreal(
            0.2, std::min(20.0, p.max_stepping_rate_per_s / (6.0 * press.pulses_per_degree) / 1.6));
        press.start_angle_deg = sreal(0, 359.9);
        press.reverse = schance(0.1);
        if (schance(0.5)) {
            press.pressing_from_deg = sreal(0, 200);
            press.pressing_to_deg = press.pressing_from_deg + sreal(1, 150);
            press.pressing_slowdown = sreal(0, 0.5);
        }
        press.drift_per_cycle = schance(0.3) ? sreal(-0.05, 0.05) : 0.0;
        press.variation = schance(0.3) ? sreal(0, 0.2) : 0.0;
        press.seed = static_cast<unsigned>(spick(1, 1000));
        if (schance(0.3)) {
            press.change_cycle = spick(1, 3);
            press.change_angle_deg = sreal(0, 359.9);
            press.change_factor = sreal(0.5, 1.2);
        }
        if (schance(0.15)) {
            press.stop_cycle = spick(1, 2);
            press.stop_angle_deg = sreal(0, 359.9);
        }
        p.speed_sample_s = sreal(0.005, 0.5);
        p.sync_drive.position_gain_per_s = schance(0.2) ? 0.0 : sreal(0.5, 10);
        // Mostly longer than a revolution (a card may wait that long for its angle).
        p.sync_timeout_s = schance(0.7)
                               ? std::min(3600.0, 72.0 / press.strokes_per_min + sreal(0, 30))
                               : sreal(2, 60);
        p.sync_drive.max_in_per_min = sreal(1, 8);
        p.sync_drive.acceleration_in_per_s2 = sreal(0.05, 3);
        c.medium = schance(0.5) ? DeckFormat::cbn : DeckFormat::tape; // .five has no column 76
    }

    // Spindle synchronisation (an addition after EP 0360190): a spindle of any temper, tap cards
    // before some motion cards, now and then a fault of PC 130's transfer. From `trng`, so the
    // decks above stay what they were.
    p.spindle_sync = tchance(0.3);
    if (p.spindle_sync) {
        axes::SpindleSyncProfile& sp = p.spindle;
        sp.encoder_pulses_per_rev = tpick(4, 40);
        sp.sample_s = treal(0.01, 0.2);
        if (tchance(0.3)) {
            sp.change_at_s = treal(0, 60);
            sp.change_factor = treal(0.3, 1.5);
        }
        // Within what interface 33's switches follow, and under half a turn a sample, at the
        // fastest the lasting change makes it (the profile's check).
        sp.max_rpm =
            treal(30, std::min(p.max_stepping_rate_per_s * 60.0 / sp.encoder_pulses_per_rev,
                               0.45 * 60.0 / sp.sample_s) /
                          std::max(1.0, sp.change_factor));
        sp.run_up_rpm_per_s = treal(20, 2000);
        sp.run_down_rpm_per_s = treal(20, 2000);
        sp.feed_gain_per_s = treal(0, 30);
        sp.ratio_source = tchance(0.5) ? axes::RatioSource::transferred : axes::RatioSource::stored;
        sp.head_change_s = treal(0.05, 10);
        sp.pc_scan_s = treal(0.005, 0.1);
        sp.transfer_timeout_s = treal(0.2, 5);
        p.sync_drive.max_in_per_min = treal(1, 8);
        p.sync_drive.acceleration_in_per_s2 = treal(0.05, 3);
        c.medium = tchance(0.5) ? DeckFormat::cbn : DeckFormat::tape; // .five has no column 76
    }

    // Half the decks are valid; the others have one mistake, on one card and axis.
    const int mistake = chance(0.5) ? 0 : pick(1, 7);
    const int cards = pick(1, 8);
    const int bad_card = pick(0, cards - 1);
    const auto bad_axis = kAxes.at(static_cast<std::size_t>(pick(0, 4)));
    std::array<int, 5> at{};
    // Numbered on from a random one, leaving room for every card the deck may take (a tap,
    // a sync and a condition card beside each motion card, and a loop card): 9999 is the last.
    int number = std::min(pick(0, 9990), 9999 - 4 * cards - 1);
    for (int n = 0; n < cards; ++n) {
        if (p.spindle_sync && tchance(0.5)) {
            CardOrders t;
            t.kind = CardKind::tap;
            t.number = number++;
            t.tap.tool = tchance(0.95) ? tpick(1, 3) : tpick(4, 99);
            if (t.tap.tool == 3 && t.number % 4 != 0) {
                t.tap.tool = 1; // tool 3's head holds a cutter: a tap card calling it is refused
            }
            t.tap.axis = kAxes.at(static_cast<std::size_t>(tpick(0, 4)));
            t.tap.motion = tchance(0.5) ? Motion::forward : Motion::reverse;
            t.tap.depth = static_cast<Thousandths>(tpick(1, tchance(0.8) ? 300 : 2000));
            t.tap.rpm = std::max(1, static_cast<int>(treal(0.2, 1.05) * p.spindle.max_rpm));
            const axes::SpindleHead* head = p.spindle.head(t.tap.tool);
            const double ratio = head != nullptr ? head->ratio : 0.5;
            // A feed between the drive's least and (now and then more than) its most.
            const double feed = treal(0.5, p.sync_drive.max_in_per_min * 1.05);
            t.tap.pitch =
                std::clamp(static_cast<int>(feed / (ratio * t.tap.rpm) * 100000), 1, kMaxPitch);
            c.cards.push_back(t);
        }
        const bool sync = p.press_sync && schance(0.6);
        const int sync_number = number;
        number += sync ? 1 : 0;
        const bool conditions = p.condition_cards && cchance(0.6);
        const int condition_number = number;
        number += conditions ? 1 : 0;
        const std::array<int, 5> before = at;
        CardOrders o;
        o.number = number++;
        if (mistake == 1 && n == bad_card) {
            o.number = pick(0, 9999); // out of order (most likely)
        }
        o.spindle = static_cast<Spindle>(pick(0, 2));
        for (Axis a : kAxes) {
            const bool bad = n == bad_card && a == bad_axis;
            AxisOrder& x = o.axis(a);
            int& from = at.at(axis_index(a));
            const int reach =
                std::array<int, 4>{5, 40, 400, 9999}.at(static_cast<std::size_t>(pick(0, 3)));
            const int to = std::clamp(from + pick(-reach, reach), 0, 9999);
            const int sign = to >= from ? +1 : -1;
            x.motion = (sign > 0) != (bad && mistake == 2) ? Motion::forward : Motion::reverse;
            // Speed 1 needs room for slow-downs 0.2 and 0.1 in before the stop; speed 2 for 0.1.
            const int length = std::abs(to - from);
            x.start_speed = length > 260 ? (fast ? 1 : pick(1, 3)) : length > 130 ? pick(2, 3) : 3;
            const bool close = bad && mistake == 3;
            for (int s = 0; s < 3 - x.start_speed; ++s) {
                const int before = close ? pick(1, 5) : (2 - s) * 100 + pick(-20, 20);
                x.slow_down.at(static_cast<std::size_t>(s)) =
                    static_cast<Thousandths>(std::clamp(to - sign * before, 0, 9999));
            }
            if (bad && mistake == 4) {
                x.slow_down.at(0) = static_cast<Thousandths>(pick(0, 9999)); // anywhere
            }
            x.stop = static_cast<Thousandths>(to);
            const int check = std::abs(to - from) + (bad && mistake == 5 ? pick(-3, 3) : 0);
            x.check = static_cast<Thousandths>(std::clamp(check, 0, 9999));
            const std::array<SequencePattern, 5> patent = {0b00011, 0b00011, 0b01100, 0b01100,
                                                           0b10000};
            x.sequence = bad && mistake == 6 ? static_cast<SequencePattern>(pick(0, 31))
                                             : patent.at(axis_index(a));
            if (!bad && !spurious_matches_on_path(x, static_cast<Thousandths>(from)).empty()) {
                x.start_speed = 3; // the generator's answer to the shared-bank hazard
                x.slow_down = {};
            }
            from = to;
        }
        if (sync) {
            CardOrders sc;
            sc.kind = CardKind::sync;
            sc.number = sync_number;
            sc.sync.position_sync = schance(0.6);
            sc.sync.angle_deg = spick(0, 359);
            if (!sc.sync.position_sync) {
                sc.sync.angle_deg = 0;
            }
            for (Axis a : kAxes) {
                const bool moving = before.at(axis_index(a)) != at.at(axis_index(a));
                if (moving && schance(0.5)) {
                    // Mostly as a careful programmer punches it: no faster, at the press's rated
                    // speed, than the 1952 speed the card starts the axis on (its slow-downs are
                    // planned for that); now and then up to twice as fast.
                    const double rated = p.press.strokes_per_min * 6.0 * p.press.pulses_per_degree;
                    const int k = o.axis(a).start_speed;
                    const double most = p.axes.at(axis_index(a))
                                            .speed_in_per_min.at(static_cast<std::size_t>(k - 1)) /
                                        60.0 / rated * 1e5 * (schance(0.15) ? 2.0 : 1.0);
                    const int top = std::max(1, static_cast<int>(most));
                    sc.sync.travel_per_pulse.at(axis_index(a)) = spick(std::max(1, top / 4), top);
                } else if (schance(0.03)) {
                    sc.sync.travel_per_pulse.at(axis_index(a)) = spick(20, 400);
                }
            }
            // Now and then switch 16A clears register 14 as the card is read (claim 5); a card
            // of the reset alone synchronises nothing.
            sc.sync.register_reset = schance(0.15);
            if (!sc.sync.synchronises() && !sc.sync.register_reset) {
                sc.sync.position_sync = true;
            }
            c.cards.push_back(sc);
        }
        if (conditions) {
            CardOrders cond;
            cond.kind = CardKind::condition;
            cond.number = condition_number;
            cond.condition_count = cpick(1, 3);
            std::vector<Axis> moving;
            for (Axis a : kAxes) {
                if (before.at(axis_index(a)) != at.at(axis_index(a))) {
                    moving.push_back(a);
                }
            }
            const bool valid = !moving.empty() && cchance(0.8);
            for (int k = 0; k < cond.condition_count; ++k) {
                ConditionOrder& x = cond.conditions.at(static_cast<std::size_t>(k));
                x.event = 10 * k + cpick(1, 9);
                x.axis = valid ? moving.at(static_cast<std::size_t>(
                                     cpick(0, static_cast<int>(moving.size()) - 1)))
                               : kAxes.at(static_cast<std::size_t>(cpick(0, 4)));
                const int i = static_cast<int>(axis_index(x.axis));
                const int from = before.at(i);
                const int to = at.at(i);
                // On the way, the start excluded (the counter must step onto it), in its sense.
                x.position = static_cast<Thousandths>(
                    valid ? (to > from ? cpick(from + 1, to) : cpick(to, from - 1))
                          : cpick(0, 9999));
                x.sense = valid && cchance(0.7)
                              ? (to > from ? PassingSense::forward : PassingSense::reverse)
                              : static_cast<PassingSense>(cpick(0, 2));
                x.action = static_cast<ActionKind>(cpick(1, kActionKinds));
                x.parameter = x.action == ActionKind::tool_change ? cpick(1, 3)
                              : x.action == ActionKind::dwell     ? cpick(1, 5)
                              : x.action == ActionKind::lamp      ? cpick(1, 9)
                                                                  : 0;
            }
            if (cchance(0.05)) {
                cond.conditions.at(0).event = cond.conditions.at(cond.condition_count - 1).event;
            }
            c.cards.push_back(cond);
        }
        // A tool change may not trip while the spindle turns (tool_change_interlock): most motion
        // cards a tool change waits on order it off, the others show the interlock.
        if (conditions && o.number % 6 != 0) {
            const CardOrders& cond = c.cards.back();
            for (int k = 0; k < cond.condition_count; ++k) {
                if (cond.conditions.at(static_cast<std::size_t>(k)).action ==
                    ActionKind::tool_change) {
                    o.spindle = Spindle::off;
                }
            }
        }
        c.cards.push_back(o);
        if (mistake == 7 && n == bad_card) {
            // A double punch in one digit column of a number field of the bad axis (fig8:
            // table columns 4-19, the other axes 14 columns further on per axis).
            const int first = bad_axis == Axis::table
                                  ? 4
                                  : 22 + 14 * (static_cast<int>(axis_index(bad_axis)) - 1);
            const int last = bad_axis == Axis::table ? 19 : first + 11;
            c.extra_punches.emplace_back(c.cards.size() - 1, pick(first, last), pick(0, 9));
        }
    }
    if (p.press_sync && !c.cards.empty() && schance(0.8)) {
        CardOrders loop;
        loop.kind = CardKind::sync;
        loop.number = number++;
        loop.sync.loop = true;
        loop.sync.loop_to = schance(0.9) ? c.cards.front().number : spick(0, 9999);
        loop.sync.loop_count = spick(2, 4);
        c.cards.push_back(loop);
    }
    if (chance(0.1)) { // a slip of the drive, often while the chain has backlash too
        const std::string axis(axis_name(kAxes.at(static_cast<std::size_t>(pick(0, 4)))));
        c.faults.push_back(
            parse_fault(fmt::format("slip:{}:{}:{}", axis, pick(1, 400), pick(1, 300))));
    }
    if (p.spindle_sync && tchance(0.2)) {
        c.faults.push_back(parse_fault(
            fmt::format("{}:{}", tchance(0.5) ? "stale-ratio" : "transfer-hang", tpick(1, 3))));
    }
    if (chance(0.25)) {
        const std::string axis(axis_name(kAxes.at(static_cast<std::size_t>(pick(0, 4)))));
        const std::array<std::string, 8> specs = {
            fmt::format("drop-impulse:{}:{}", axis, pick(1, 3000)),
            fmt::format("stuck-relay:{}:{}:{}", axis, 350 + 2 * pick(0, 3), pick(0, 9)),
            fmt::format("dead-relay:{}:{}:{}", axis, 318 + 2 * pick(0, 3), pick(0, 9)),
            fmt::format("skip-step:{}:{}:{}", axis, pick(0, 1) ? 110 : 312, pick(1, 500)),
            fmt::format("feed-twice:{}", pick(1, cards)),
            fmt::format("swap-cards:{}", pick(1, cards)),
            fmt::format("short-card:{}", pick(1, cards)),
            fmt::format("slip:{}:{}:{}", axis, pick(1, 3000), pick(1, 50))};
        c.faults.push_back(parse_fault(specs.at(static_cast<std::size_t>(pick(0, 7)))));
    }
    return c;
}

std::vector<Card> punched_cards(const Case& c) {
    std::vector<Card> punched;
    for (const auto& o : c.cards) {
        const EncodeResult e = encode(o, fig8_layout());
        if ((o.kind == CardKind::sync || o.kind == CardKind::tap) && !e) {
            // (a motion card may hold what its fields cannot; a sync or tap card may not)
            throw std::logic_error("random deck: a card its layout cannot hold: " +
                                   e.error.value_or(""));
        }
        punched.push_back(e.card);
    }
    for (const auto& [card, column, digit] : c.extra_punches) {
        punched.at(card).punch(column, digit_row(digit));
    }
    return punched;
}

} // namespace parsons::test
