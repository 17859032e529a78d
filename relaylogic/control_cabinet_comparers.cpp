// Control cabinet 52, the impulses and the comparers: each commutator 102 impulse steps the
// counters (duplicate contact sets A and B), the comparers 122' and 122'' are read, stepping
// relay 256 steps speed switch 236 through delay 258, and the motors follow the switches.
// Fast-forward (relaylogic/fast_forward.hpp) is the same rules jumped: it is planned here, next
// to the rules it jumps (plan_quiet_stretches, catch_up), and impulse level without an
// observer takes the impulses straight from the plants (run_impulses), reading the comparers,
// the limits and the queue only where the same plan says something can happen.
#include "relaylogic/control_cabinet.hpp"
#include "relaylogic/fast_forward.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cassert>
#include <limits>

namespace parsons::relaylogic {

using cardreader::Axis;
using cardreader::axis_name;

// What decides how far an axis can go on quietly now (relaylogic/fast_forward.hpp): the machine's
// stop, its faults on this axis, hundredths-only counting, the soft-limit watch.
QuietConditions ControlCabinet::quiet_conditions(AxisCircuit& c) {
    QuietConditions q;
    q.min_interval_s = 1.0 / profile_.max_stepping_rate_per_s;
    q.machine_stopped = stop_.has_value();
    q.watches = counter_watches_;
    q.counting_hundredths =
        profile_.count_hundredths_at_speed_1 && c.speed_switch.position() == 1 && !stop_;
    q.watching_soft_limits = c.powered && c.plant.profile().soft_limits;
    for (const Fault& f : faults_) {
        if (f.axis != c.axis) {
            continue;
        }
        if (f.kind == FaultKind::drop_impulse && f.n > c.contact_set_a &&
            (q.next_fault_impulse == 0 || f.n < q.next_fault_impulse)) {
            q.next_fault_impulse = f.n;
        }
        if (f.kind == FaultKind::skip_step && switch_numbered(c, f.numeral).skip_pending()) {
            q.faulty_switch_ahead = true;
        }
    }
    return q;
}

// Fast-forward: how far each moving axis can go on quietly, and when its next event that
// matters comes (the impulse that ends the stretch, or the end of its speed change).
void ControlCabinet::plan_quiet_stretches() {
    for (std::size_t i = 0; i < circuits_.size(); ++i) {
        AxisCircuit& c = *circuits_[i];
        quiet_.at(i) = 0;
        quiet_end_.at(i) = c.plant.next_event_time();
        if (!c.plant.next_event_is_impulse()) {
            continue;
        }
        const std::int64_t quiet = quiet_impulses(c, quiet_conditions(c));
        if (quiet > 0) {
            quiet_.at(i) = quiet;
            // The impulse that ends the stretch or, if the phase ends first, the phase's end.
            const double after = quiet == std::numeric_limits<std::int64_t>::max()
                                     ? axes::kNever
                                     : c.plant.impulse_time(quiet + 1);
            quiet_end_.at(i) = after != axes::kNever ? after : c.plant.phase_end_time();
        }
    }
    if (clock_ != nullptr) {
        clock_quiet_end_ = clock_->plan_quiet(*this); // the press's detector edges that only count
    }
}

// Fast-forward: every axis takes its quiet impulses due by time t, in one jump each.
void ControlCabinet::catch_up(double t) {
    for (std::size_t i = 0; i < circuits_.size(); ++i) {
        if (quiet_.at(i) == 0) {
            continue;
        }
        AxisCircuit& c = *circuits_[i];
        const std::int64_t n = std::min(quiet_.at(i), c.plant.impulses_by(t));
        if (n > 0) {
            for (Attachment* a : before_jump_) {
                a->before_jump(*this, c, t);
            }
            jump_quiet_impulses(c, n);
            quiet_.at(i) -= n;
        }
    }
}

// The counting of one impulse, for on_impulse() and count_quiet_impulse(): the counters count
// up or down as reversing control 214 set them (the motion column), whichever way the screw
// really turns: coast that runs on after the next card has set the other sense is counted the
// wrong way, as on the 1952 machine. `hundredths_only`: the patent's answer to stepping-rate
// loss (col. 8), a profile option. Returns whether switch 110 stepped; its wipers then break
// contact (delay 258 may release).
[[gnu::always_inline]] inline bool
ControlCabinet::count_impulse(AxisCircuit& c, const axes::Impulse& impulse, bool hundredths_only) {
    c.wrong_way += impulse.direction != c.direction ? 1 : 0;
    c.thousandths_uncounted += hundredths_only ? 1 : 0;
    const bool stepped =
        c.absolute_counter.impulse(c.direction, impulse.hundredths, impulse.tenths, impulse.inches,
                                   now_, min_interval_s_, !hundredths_only);
    if (!hundredths_only) {
        c.increment_counter.impulse(now_, min_interval_s_);
    } else if (impulse.hundredths) {
        c.increment_counter.hundredths_impulse(now_, min_interval_s_);
    }
    if (stepped) {
        c.speed_switch.equality_left(now_); // the wipers break contact as they step
    }
    return stepped;
}

// A quiet impulse: what on_impulse() does with it where nothing but counting can happen (no
// observer, no attachment that sees the count, no comparer conducting before or after it, no
// fault, travel limit or soft limit due, no hundredths-only counting: ask_quiet()). Both
// contact sets see it, it is counted, and the comparers stay open, so delay 258 may release.
template <bool Recording>
inline void ControlCabinet::count_quiet_impulse(AxisCircuit& c, const axes::Impulse& impulse) {
    ++c.contact_set_a;
    ++c.contact_set_b;
    if constexpr (Recording) {
        c.show_contacts(); // the contacts, then the switches they step, as on_impulse() has them
    }
    const bool stepped = count_impulse(c, impulse, false);
    // Every switch was ready (quiet_impulses() asks for that): switch 110 stepped.
    assert(stepped);
    if (!stepped && !stop_) {
        c.speed_switch.equality_left(now_); // the comparers are open
    }
}

// Impulse level with no observer: while only impulses come (no relay event is due), take them
// straight from the plants in time order, lowest axis first at the same instant as the main
// loop does, without looking at anything else. Back to the main loop as soon as an impulse
// does more than count.
//
// Each axis's impulses are still taken one by one, every switch stepping with its rate check
// and carries. What is not done at every impulse is asking what cannot have changed: the
// cabinet works out how many of the axis's coming impulses are quiet (no comparer can conduct,
// no fault, travel limit or soft limit is due: the quiet stretch that fast-forward jumps,
// relaylogic/fast_forward.hpp), and takes that many through count_quiet_impulse(), which counts
// and asks nothing; the impulse after them goes through on_impulse() again. Nothing else can
// change what the answer rests on meanwhile: a relay event, or an impulse of any axis that does
// more than count, sends the loop back to the main loop, which forgets every answer.
template <bool Recording>
void ControlCabinet::run_impulses() {
    double queued = queue_.empty() ? axes::kNever : queue_.top().t;
    if (clock_running()) {
        queued = std::min(queued, clock_->next_clock_event(*this)); // the press's edge first
    }
    // The axes with anything ahead, in order, and when each one's next event comes: one at
    // rest stays at rest until the main loop commands it (an impulse that commands a motor
    // does more than count), and only the axis that takes impulses moves its own next event.
    std::array<std::size_t, cardreader::kAxisCount> moving{};
    std::array<double, cardreader::kAxisCount> next{};
    std::size_t n = 0;
    for (std::size_t i = 0; i < circuits_.size(); ++i) {
        const double t = circuits_[i]->plant.next_event_time();
        if (t != axes::kNever) {
            moving.at(n) = i;
            next.at(n++) = t;
        }
    }
    std::array<QuietRun, cardreader::kAxisCount> runs{};
    while (n > 0) {
        std::size_t f = 0; // the first to come, the lowest axis at the same instant
        for (std::size_t k = 1; k < n; ++k) {
            f = next[k] < next[f] ? k : f;
        }
        // This axis goes on alone until another's impulse (a lower axis at the same instant
        // goes first) or a relay event comes.
        double before = axes::kNever; // strictly before
        double until = queued;        // at or before
        for (std::size_t k = 0; k < f; ++k) {
            before = std::min(before, next[k]);
        }
        for (std::size_t k = f + 1; k < n; ++k) {
            until = std::min(until, next[k]);
        }
        AxisCircuit& c = *circuits_[moving[f]];
        axes::LeadScrewAxis& plant = c.plant;
        if (interrupt_ != nullptr && *interrupt_ != 0) {
            return;
        }
        double t = next[f];
        std::int64_t quiet_left = runs[f].quiet; // a local: kept in a register
        while (plant.next_event_is_impulse()) {
            t = plant.next_event_time();
            // Recording, an instant another axis shares is the main loop's: advance() takes
            // every axis's impulse of that instant and reports one motion record for them.
            if (!(t < before && (Recording ? t < until : t <= until))) {
                break;
            }
            now_ = t;
            tracer_.set_time(t);
            if (quiet_left > 0) {
                --quiet_left;
                count_quiet_impulse<Recording>(c, plant.take_next_impulse());
                if (Recording && follows_motion_) {
                    report_motion(t);
                }
                continue;
            }
            const bool quiet = impulse_one_by_one<Recording>(c, runs[f]);
            if (Recording && follows_motion_) {
                report_motion(t);
            }
            if (!quiet) {
                return; // something happened: the main loop looks at everything again
            }
            quiet_left = runs[f].quiet;
        }
        runs[f].quiet = quiet_left;
        next[f] = plant.next_event_time();
        if (!plant.next_event_is_impulse() || t > queued || (Recording && t == until)) {
            return; // a speed change ends, or a relay event is due: the main loop
        }
    }
}

// An impulse of an axis outside a quiet stretch. First ask how many of its coming impulses are
// quiet (ask_quiet); the first of them goes through on_impulse() all the same when a comparer
// conducts before it (it leaves the equality: the comparers are read again), the rest through
// count_quiet_impulse(). Returns what on_impulse() returns.
template <bool Recording>
bool ControlCabinet::impulse_one_by_one(AxisCircuit& c, QuietRun& run) {
    ask_quiet(c, run);
    if (run.quiet > 0) {
        --run.quiet;
        if (!c.absolute_conducting && !c.incremental_conducting) {
            count_quiet_impulse<Recording>(c, c.plant.take_next_impulse());
            return true;
        }
    }
    return on_impulse(c, c.plant.take_next_impulse());
}

// How many of the axis's coming impulses are quiet. An axis whose next impulse is not quiet
// goes one by one through on_impulse(); it is asked again after a few of them, then after
// twice as many (a stretch that stays unquiet, such as impulses faster than the switches can
// step, is not asked at every impulse). Attachments that see each impulse counted are never
// passed by: with one, every impulse goes through on_impulse().
void ControlCabinet::ask_quiet(AxisCircuit& c, QuietRun& run) {
    if (!before_count_.empty() || !after_count_.empty()) {
        return;
    }
    if (run.ask_in > 0) {
        --run.ask_in;
        return;
    }
    run.quiet = quiet_impulses(c, quiet_conditions(c));
    if (run.quiet > 0) {
        run.wait = QuietRun::kFirstWait;
    } else {
        run.ask_in = run.wait;
        run.wait = std::min(2 * run.wait, QuietRun::kLongestWait);
    }
}

bool ControlCabinet::on_impulse(AxisCircuit& c, const axes::Impulse& impulse) {
    // Duplicate contact sets on commutator 102: both must see every impulse.
    ++c.contact_set_a;
    if (faults_.empty() || !fault_drops(c)) {
        ++c.contact_set_b;
    }
    c.show_contacts(); // the contacts, then the switches they step
    // The patent's answer to stepping-rate loss (col. 8), a profile option: while the speed
    // switch stands on speed 1, count only every hundredth until the first slow-down.
    for (Attachment* a : before_count_) {
        a->before_count(*this, c, impulse.direction);
    }
    const bool hundredths_only =
        profile_.count_hundredths_at_speed_1 && c.speed_switch.position() == 1 && !stop_;
    const bool stepped = count_impulse(c, impulse, hundredths_only);
    if (stop_) {
        c.compare();
        return true; // coasting after a stop: the counters still count
    }
    if (c.contact_set_a != c.contact_set_b) {
        missed_impulse(c);
        return false;
    }
    if (c.plant.beyond_limits()) {
        travel_limit(c);
        return false;
    }
    bool quiet = true;
    if (stepped) {
        for (Attachment* a : after_count_) {
            quiet = !a->after_count(*this, c) && quiet;
        }
    }
    c.compare();
    if (!c.absolute_conducting && !c.incremental_conducting) {
        c.speed_switch.equality_left(now_);
    } else if (watch_balance(c, "while it stood on off and its counters counted")) {
        return false; // balancing circuit 266 through contact 238 (a coast, a second match)
    } else {
        quiet = evaluate(c) && quiet;
    }
    // The soft-limit watch, after the comparers: an axis that stops here anyway is not tripped.
    if (c.powered && c.plant.profile().soft_limits && !stop_ &&
        soft_limit_trips(c.plant.profile(), c.plant.moving_direction(), c.plant.real_in(),
                         c.plant.speed_in_per_s())) {
        soft_limit_watch(c);
        return false;
    }
    return quiet;
}

bool ControlCabinet::fault_drops(const AxisCircuit& c) {
    for (std::size_t i = 0; i < faults_.size(); ++i) {
        const Fault& f = faults_[i];
        if (f.kind == FaultKind::drop_impulse && f.axis == c.axis && f.n == c.contact_set_a) {
            effects_.at(i).acted = true;
            effects_.at(i).effect =
                fmt::format("contact set B of the {} commutator 102 missed impulse {} ({})",
                            axis_name(c.axis), f.n, card_name());
            return true;
        }
    }
    return false;
}

void ControlCabinet::missed_impulse(AxisCircuit& c) {
    machine_stop(StopReason::missed_impulse, c.axis,
                 fmt::format("{}, {}: impulse {} of commutator 102 was seen by contact set A "
                             "but not by its duplicate set B",
                             card_name(), axis_name(c.axis), c.contact_set_a),
                 fmt::format("duplicate-contact lamp ({} commutator 102)", axis_name(c.axis)));
    c.compare();
}

void ControlCabinet::soft_limit_watch(AxisCircuit& c) {
    const auto& p = c.plant.profile();
    const bool up = c.plant.moving_direction() > 0;
    machine_stop(StopReason::soft_limit, c.axis,
                 fmt::format("{}, {}: at {:.4f} in, moving {} at {:.3f} in/min, the part could "
                             "no longer brake to rest inside its soft limit {:.3f} in (movement "
                             "range {:.3f} .. {:.3f} in): switched off (soft limits are an "
                             "addition of this emulator, after Mitsubishi's movement range)",
                             card_name(), axis_name(c.axis), c.plant.real_in(), up ? "up" : "down",
                             c.plant.speed_in_per_s() * 60, up ? p.soft_max_in : p.soft_min_in,
                             p.soft_min_in, p.soft_max_in),
                 fmt::format("soft-limit lamp ({}; an addition)", axis_name(c.axis)));
    c.compare();
}

void ControlCabinet::travel_limit(AxisCircuit& c) {
    const auto& p = c.plant.profile();
    machine_stop(StopReason::limit_switch, c.axis,
                 fmt::format("{}, {}: the part reached its travel limit at {:.4f} in (limit "
                             "switches at {:.3f} .. {:.3f} in; travel-limit switches are an "
                             "addition of this emulator: the patent shows none)",
                             card_name(), axis_name(c.axis), c.plant.real_in(), p.travel_min_in,
                             p.travel_max_in),
                 fmt::format("limit-switch lamp ({}; an addition)", axis_name(c.axis)));
    c.compare();
}

bool ControlCabinet::evaluate(AxisCircuit& c) {
    c.compare();
    const bool any = c.absolute_conducting || c.incremental_conducting;
    if (!any) {
        c.speed_switch.equality_left(now_);
    }
    if (!any || !live(c)) {
        return true;
    }
    if (!c.speed_switch.channel_257_open(now_)) {
        if (now_ < c.speed_switch.hold_until()) {
            schedule(c.speed_switch.hold_until(), EventKind::delay_258_release,
                     static_cast<int>(cardreader::axis_index(c.axis)));
        }
        return false;
    }
    // One impulse to stepping relay 256, one step of speed switch 236, whichever comparer sent
    // it: from speed 3 the step is to off (contact 238), the stop (col. 10-11).
    if (c.speed_switch.position() == 3 ||
        (profile_.incremental_equality_stops_at_any_speed && c.incremental_conducting)) {
        stop_axis(c);
        return false;
    }
    c.speed_switch.impulse_256(now_, profile_.delay_258_s);
    update_motor(c);
    // When delay 258 closes channel 257 again the comparer is read again: an equality that
    // still stands then steps the switch once more (a delay too short for the speed).
    schedule(c.speed_switch.hold_until(), EventKind::delay_258_release,
             static_cast<int>(cardreader::axis_index(c.axis)));
    return false;
}

void ControlCabinet::update_motor(AxisCircuit& c) {
    bool on = live(c);
    for (const Attachment* a : axis_holders_) {
        on = on && !a->holds_axis(c.axis); // e.g. a dwell opens the hold relay
    }
    count_due_impulse(c); // never let an impulse due now go uncounted
    for (Attachment* a : drivers_) {
        if (a->drive(*this, c, on)) {
            return; // e.g. a tap's follower drive, or speed 1 following the press
        }
    }
    c.plant.command(c.direction, on ? c.speed_switch.position() : 0);
    c.set_powered(on);
}

void ControlCabinet::update_motors() {
    bool cutting = false;
    for (auto& c : circuits_) {
        update_motor(*c);
        cutting = cutting || (c->powered && shaft_.position() == last_sequence_position_);
    }
    cutting = cutting && orders_.spindle != cardreader::Spindle::off;
    tracer_.set(cutting_, cutting ? 1 : 0);
    if (cutting && spindle_motor_.ready_s() > now_ && record_times_ && !timings_.empty() &&
        timings_.back().cut_unready_s < 0) {
        // Nothing in the patent holds the axes for the spindle (no interlock is shown): the
        // cutter cuts while its motor is still coming to speed, and the report says so.
        timings_.back().cut_unready_s = now_;
        timings_.back().spindle_ready_s = spindle_motor_.ready_s();
    }
}

// "The signal will cause the spindle to rotate in one direction if a "0" is punched and will
// cause the opposite direction of rotation if a "1" is punched" (col. 10). The patent gives the
// motor no time; a motor cannot change speed in an instant (rule 7), so it runs down and up
// again in the profile's times (rule 11).
void ControlCabinet::command_spindle() {
    using axes::SpindleTurning;
    const SpindleTurning want =
        orders_.spindle == cardreader::Spindle::forward   ? SpindleTurning::forward
        : orders_.spindle == cardreader::Spindle::reverse ? SpindleTurning::reverse
                                                          : SpindleTurning::off;
    spindle_motor_.command(want, now_, profile_.actions);
    show_spindle();
}

void ControlCabinet::show_spindle() {
    spindle_changing_ = spindle_motor_.ready_s() > now_;
    tracer_.set(spindle_motor_signal_,
                spindle_changing_ ? 3U : static_cast<std::uint32_t>(spindle_motor_.turning()));
}

template void ControlCabinet::run_impulses<false>();
template void ControlCabinet::run_impulses<true>();

} // namespace parsons::relaylogic
