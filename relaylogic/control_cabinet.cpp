#include "relaylogic/control_cabinet.hpp"

#include "relaylogic/card_reader.hpp"
#include "relaylogic/fast_forward.hpp"

#include "axes/state_json.hpp"
#include "cardreader/deck_error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace parsons::relaylogic {

using cardreader::Axis;
using cardreader::axis_name;
using cardreader::format_inches;

namespace {

std::string inches(int thousandths) {
    return format_inches(
        static_cast<cardreader::Thousandths>(((thousandths % 10000) + 10000) % 10000));
}

} // namespace

ControlCabinet::ControlCabinet(axes::MachineProfile profile, const cardreader::CardLayout& layout)
    : profile_(std::move(profile)), layout_(layout), shaft_(tracer_), balancing_(tracer_),
      min_interval_s_(1.0 / profile_.max_stepping_rate_per_s) {
    reader_card_ = tracer_.define("cabinet", "card_reader_134.card",
                                  "card in the reader (deck "
                                  "position)",
                                  "134", 32);
    reader_feeding_ =
        tracer_.define("cabinet", "card_reader_134.reading", "card reader cycle", "134", 1);
    // The card-number check: the patent names it (col. 8) but gives it no numeral.
    card_number_check_ = tracer_.define("cabinet", "card_number_check",
                                        "card-number check: the last card number accepted "
                                        "(no numeral in the patent)",
                                        "", 14);
    spindle_165_ = tracer_.define("cabinet", "spindle_control_165",
                                  "spindle (0 off, 1 forward, 2 "
                                  "reverse)",
                                  "165", 2);
    cutting_ = tracer_.define("cabinet", "spindle_control_165.cutting",
                              "cutting: last axis of the "
                              "sequence running",
                              "165", 1);
    zeroizing_ =
        tracer_.define("cabinet", "zeroizing_circuit_292", "zeroizing circuit 292-304", "292", 1);
    channel_294_ = tracer_.define("cabinet", "channel_294",
                                  "zeroizing: clearing channel 294 (absolute storage)", "294", 1);
    channel_298_ =
        tracer_.define("cabinet", "channel_298",
                       "zeroizing: channel 298 (incremental storage and counter)", "298", 1);
    channel_300_ = tracer_.define("cabinet", "channel_300",
                                  "zeroizing: channel 300 (sequence contacts open)", "300", 1);
    channel_302_ =
        tracer_.define("cabinet", "channel_302", "zeroizing: channel 302 (device 288)", "302", 1);
    channel_304_ =
        tracer_.define("cabinet", "channel_304",
                       "zeroizing: channel 304 (reader indexes the next card)", "304", 1);
    for (Axis a : cardreader::kAxes) {
        circuits_.push_back(std::make_unique<AxisCircuit>(tracer_, profile_, a));
        circuits_.back()->plant.measure_by(profile_.measuring_chain); // Fig. 3
    }
    conditions_.install(tracer_, profile_); // EP 0640901's units, if the profile has them
    sync_.install(tracer_, profile_);       // EP 0436887's press and units, likewise
    tapping_.install(tracer_, profile_);    // EP 0360190's spindle, PC 130 and 12a, likewise
}

void ControlCabinet::attach(MachineObserver* observer) {
    tracer_.attach(observer);
}

void ControlCabinet::schedule(double t, EventKind kind, int axis) {
    queue_.push(Event{t, seq_++, kind, axis, cards_read_});
    if (kind == EventKind::reference_block) {
        ++blocks_queued_;
    }
}

std::string ControlCabinet::card_name() const {
    return orders_.number >= 0 && card_
               ? fmt::format("card {} (number {:04})", cards_read_, orders_.number)
               : fmt::format("card {}", cards_read_);
}

RunResult ControlCabinet::run(cardreader::CardSource& deck) {
    deck_ = &deck;
    apply_faults(deck);
    if (tapping_.present()) {
        tapping_.inject(faults_);
        tapping_.keep_samples(record_tap_samples_);
    }
    MachineObserver* observer = tracer_.observer();
    if (resuming_ && sync_.present()) {
        resume_tape(deck_taken_);
    } else if (resuming_) {
        // The cards read before the saved one went through the reader already.
        for (std::int64_t i = 0; i < cards_read_; ++i) {
            if (!deck_->next()) {
                throw cardreader::DeckError(
                    fmt::format("the deck has {} cards; the saved state resumes after card {}", i,
                                cards_read_));
            }
        }
    }
    jumping_ =
        pace_ == Pace::fast_forward && (observer == nullptr || !observer->follows_impulses());
    const bool alone = !jumping_ && observer == nullptr;
    const bool follows_motion = observer != nullptr && observer->follows_motion();
    if (sync_.present()) {
        schedule_block();
    }
    schedule(now_, EventKind::feed);
    while (true) {
        if (interrupted()) {
            continue; // the machine stops; the loop lets the axes coast to rest
        }
        if (jumping_) {
            plan_quiet_stretches();
        }
        while (blocks_queued_ > 0 && !press_running() && !queue_.empty() &&
               queue_.top().kind == EventKind::reference_block) {
            queue_.pop(); // the deck is done: the reference blocks end with it, taking no time
            --blocks_queued_;
        }
        double t = queue_.empty() ? axes::kNever : queue_.top().t;
        for (std::size_t i = 0; i < circuits_.size(); ++i) {
            t = std::min(t, next_axis_event(i));
        }
        if (t == axes::kNever && unqueued_release_s_ > now_) {
            t = unqueued_release_s_; // the last release after a stop (release_after_stop)
        }
        if (press_running()) {
            // The press turns on whatever the cabinet does; when nothing else can happen and
            // nothing waits on it, the cabinet itself is idle (a sequence stall).
            if (idle()) {
                t = axes::kNever;
            } else {
                t = std::min(t, jumping_ ? press_quiet_end_ : sync_.press().next_event_time());
                if (unqueued_release_s_ > now_) {
                    // The last release after a stop (release_after_stop) is an instant of its
                    // own here too: a stall comes at it, whatever the press's pace.
                    t = std::min(t, unqueued_release_s_);
                }
            }
        }
        if (t == axes::kNever) {
            if (!deck_finished_ && !stop_) {
                sequence_stall();
                continue;
            }
            break;
        }
        now_ = t;
        tracer_.set_time(t);
        if (jumping_) {
            // The axes' quiet impulses first: a tap's reversal of control 214 is reported at the
            // first impulse of its jump, before this instant, so it must come before anything
            // reported at this instant (the spindle's edges below).
            catch_up(t);
        }
        if (tapping_.present()) {
            spindle_edges(t);
        }
        if (jumping_) {
            if (press_running()) {
                // The press's quiet edges before this instant, whatever the instant brings (at
                // impulse level each was an instant of its own).
                press_edges(std::nextafter(t, -axes::kNever));
            }
        }
        bool moved = false;
        for (std::size_t i = 0; i < circuits_.size(); ++i) {
            AxisCircuit& c = *circuits_[i];
            if (c.plant.next_event_time() <= t) {
                auto impulse = c.plant.advance_to(t);
                moved = true;
                if (impulse) {
                    on_impulse(c, *impulse);
                }
            }
        }
        if (press_running()) {
            press_edges(t);
        }
        if (moved && follows_motion) {
            std::array<double, 5> real{};
            for (std::size_t i = 0; i < circuits_.size(); ++i) {
                real.at(i) = circuits_[i]->plant.real_in_at(t);
            }
            tracer_.observer()->on_motion(t, real);
        }
        while (!queue_.empty() && queue_.top().t <= t) {
            const Event e = queue_.top();
            queue_.pop();
            handle(e);
        }
        if (alone) {
            run_impulses();
        }
    }
    for (const auto& c : circuits_) {
        c->plant.advance_to(now_);
    }
    if (tapping_.present()) {
        spindle_edges(now_);
    }
    report_faults();
    if (tracer_.observer() != nullptr) {
        tracer_.observer()->on_finish(now_);
    }
    return result();
}

HoldingRelayBank& ControlCabinet::bank_numbered(AxisCircuit& c, int numeral) {
    if (numeral >= 350) {
        return c.absolute_storage.bank((numeral - 350) / 2); // 350, 352, 354, 356
    }
    return c.incremental_storage.bank((324 - numeral) / 2); // 324, 322, 320, 318
}

SteppingSwitch& ControlCabinet::switch_numbered(AxisCircuit& c, int numeral) {
    if (numeral >= 310) {
        return c.increment_counter.stepping_switch(static_cast<std::size_t>((numeral - 310) / 2));
    }
    return c.absolute_counter.stepping_switch(static_cast<std::size_t>((numeral - 104) / 2));
}

void ControlCabinet::apply_faults(cardreader::CardSource& deck) {
    // A resumed machine has its faults in its state already (stuck relays, a slip under way)
    // and what they did so far; only the reader's faults are set up again.
    if (!resuming_) {
        effects_.clear();
    }
    std::vector<Fault> feed_faults;
    std::vector<std::size_t> feed_effects;
    for (std::size_t i = 0; i < faults_.size(); ++i) {
        const Fault& f = faults_[i];
        if (resuming_) {
            if (f.kind == FaultKind::feed_twice || f.kind == FaultKind::swap_cards ||
                f.kind == FaultKind::short_card) {
                feed_faults.push_back(f);
                feed_effects.push_back(i);
            }
            continue;
        }
        effects_.push_back(FaultEffect{f.spec, false, ""});
        AxisCircuit& c = *circuits_.at(cardreader::axis_index(f.axis));
        switch (f.kind) {
        case FaultKind::stuck_relay:
            bank_numbered(c, f.numeral).stick(f.digit);
            effects_.back().acted = true;
            effects_.back().effect = fmt::format("relay {} of {} bank {} was stuck closed from the "
                                                 "start",
                                                 f.digit, axis_name(f.axis), f.numeral);
            break;
        case FaultKind::dead_relay:
            bank_numbered(c, f.numeral).kill(f.digit);
            break;
        case FaultKind::skip_step:
            switch_numbered(c, f.numeral).skip_on_step(f.n);
            break;
        case FaultKind::slip:
            c.plant.slip_from(f.n, f.count);
            break;
        case FaultKind::feed_twice:
        case FaultKind::swap_cards:
        case FaultKind::short_card:
            feed_faults.push_back(f);
            feed_effects.push_back(effects_.size() - 1);
            break;
        case FaultKind::drop_impulse:
            break;
        case FaultKind::stale_ratio:
        case FaultKind::transfer_hang:
            break; // PC 130's (tapping units, when the profile has them)
        }
    }
    if (!feed_faults.empty()) {
        std::vector<FaultEffect*> targets;
        for (std::size_t i : feed_effects) {
            targets.push_back(&effects_.at(i));
        }
        faulty_feed_ = std::make_unique<FaultyFeed>(deck, feed_faults, targets);
        deck_ = faulty_feed_.get();
    }
}

// After the run: what the faults that act unseen did.
void ControlCabinet::report_faults() {
    for (std::size_t i = 0; i < faults_.size(); ++i) {
        const Fault& f = faults_[i];
        FaultEffect& e = effects_.at(i);
        AxisCircuit& c = *circuits_.at(cardreader::axis_index(f.axis));
        const std::string_view axis = axis_name(f.axis);
        if (f.kind == FaultKind::dead_relay && bank_numbered(c, f.numeral).refused_picks() > 0) {
            e.acted = true;
            e.effect = fmt::format("relay {} of {} bank {} failed to pick {} time{}", f.digit, axis,
                                   f.numeral, bank_numbered(c, f.numeral).refused_picks(),
                                   bank_numbered(c, f.numeral).refused_picks() == 1 ? "" : "s");
        } else if (f.kind == FaultKind::skip_step &&
                   !switch_numbered(c, f.numeral).skip_pending()) {
            e.acted = true;
            e.effect = fmt::format("{} stepping switch {} skipped a position on its step {}", axis,
                                   f.numeral, f.n);
        } else if (f.kind == FaultKind::slip && c.plant.slip_in() != 0) {
            e.acted = true;
            e.effect = slip_effect(f, c);
        }
        if (!e.acted && e.effect.empty()) {
            e.effect = "never came into play in this run";
        }
    }
}

// What a slip did depends on what the counters measure (docs/design-rules.md rule 3).
std::string ControlCabinet::slip_effect(const Fault& f, const AxisCircuit& c) const {
    const double slipped = std::abs(c.plant.slip_in());
    const std::int64_t thousandths = std::lround(slipped / axes::kInchesPerImpulse);
    const std::string what =
        fmt::format("the {} drive slipped for {:.3f} in of screw travel from its impulse {}",
                    axis_name(f.axis), slipped, f.n);
    if (c.plant.measuring_chain() == axes::MeasuringChain::screw_turns) {
        return fmt::format("{}: the counters counted {} impulse{} of screw turns the part never "
                           "made and it lags them by {:.3f} in, which no 1952 check can see "
                           "(screw-turn counting, a departure from the patent)",
                           what, thousandths, thousandths == 1 ? "" : "s", slipped);
    }
    return fmt::format("{}: the part stood while the screw turned; instrument shaft 74 follows "
                       "the part, so the counters did not count it and the axis ran on to the "
                       "real position its card asked for (Fig. 3, claims 8-10)",
                       what);
}

double ControlCabinet::next_axis_event(std::size_t i) const {
    return jumping_ ? quiet_end_.at(i) : circuits_[i]->plant.next_event_time();
}

// Fast-forward: how far each moving axis can go on quietly, and when its next event that
// matters comes (the impulse that ends the stretch, or the end of its speed change).
void ControlCabinet::plan_quiet_stretches() {
    QuietConditions q;
    q.min_interval_s = 1.0 / profile_.max_stepping_rate_per_s;
    q.machine_stopped = stop_.has_value();
    q.prg = conditions_.present() ? &conditions_.prg() : nullptr;
    for (std::size_t i = 0; i < circuits_.size(); ++i) {
        AxisCircuit& c = *circuits_[i];
        quiet_.at(i) = 0;
        quiet_end_.at(i) = c.plant.next_event_time();
        if (!c.plant.next_event_is_impulse()) {
            continue;
        }
        q.counting_hundredths =
            profile_.count_hundredths_at_speed_1 && c.speed_switch.position() == 1 && !stop_;
        q.watching_soft_limits = c.powered && c.plant.profile().soft_limits;
        q.next_fault_impulse = 0;
        q.faulty_switch_ahead = false;
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
        const std::int64_t quiet = quiet_impulses(c, q);
        if (quiet > 0) {
            quiet_.at(i) = quiet;
            // The impulse that ends the stretch or, if the phase ends first, the phase's end.
            const double after = quiet == std::numeric_limits<std::int64_t>::max()
                                     ? axes::kNever
                                     : c.plant.impulse_time(quiet + 1);
            quiet_end_.at(i) = after != axes::kNever ? after : c.plant.phase_end_time();
        }
    }
    // The press: every edge of this segment of constant crank speed only counts, but the one
    // that brings register 14 onto a held card's angle R.
    press_quiet_ = 0;
    if (press_running()) {
        const axes::Press& press = sync_.press();
        press_quiet_end_ = press.next_event_time();
        if (press.next_event_is_pulse()) {
            const std::int64_t in_segment = press.pulses_by(axes::kNever);
            const std::int64_t quiet = sync_.quiet_edges(in_segment);
            if (quiet > 0) {
                press_quiet_ = quiet;
                // The edge after the stretch, or the stretch's last edge when the segment ends
                // with it (the segment's end then comes up as the press's next event).
                press_quiet_end_ =
                    quiet < in_segment ? press.pulse_time(quiet + 1) : press.pulse_time(quiet);
            }
        }
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
            if (tapping_.present() && tapping_.feeding(c.axis) &&
                c.direction != c.plant.moving_direction()) {
                // Reversing control 214 follows the drive at the first impulse of the jump.
                tracer_.set_time(c.plant.impulse_time(1));
                tap_counting_sense(c, c.plant.moving_direction());
                tracer_.set_time(t);
            }
            jump_quiet_impulses(c, n);
            quiet_.at(i) -= n;
        }
    }
}

// Impulse level with no observer: while only impulses come (no relay event is due), take them
// straight from the plants in time order, lowest axis first at the same instant as the main
// loop does, without looking at anything else. Back to the main loop as soon as an impulse
// does more than count.
void ControlCabinet::run_impulses() {
    double queued = queue_.empty() ? axes::kNever : queue_.top().t;
    if (press_running()) {
        queued = std::min(queued, sync_.press().next_event_time()); // the press's edge first
    }
    const std::size_t n = circuits_.size();
    while (true) {
        std::size_t first = 0;
        double t = circuits_[0]->plant.next_event_time();
        for (std::size_t j = 1; j < n; ++j) {
            const double tj = circuits_[j]->plant.next_event_time();
            if (tj < t) {
                t = tj;
                first = j;
            }
        }
        // This axis goes on alone until another's impulse (a lower axis at the same instant
        // goes first) or a relay event comes.
        double before = axes::kNever; // strictly before
        double until = queued;        // at or before
        for (std::size_t j = 0; j < n; ++j) {
            const double tj = circuits_[j]->plant.next_event_time();
            if (j < first) {
                before = std::min(before, tj);
            } else if (j > first) {
                until = std::min(until, tj);
            }
        }
        AxisCircuit& c = *circuits_[first];
        axes::LeadScrewAxis& plant = c.plant;
        if (interrupt_ != nullptr && *interrupt_ != 0) {
            return;
        }
        while (plant.next_event_is_impulse()) {
            t = plant.next_event_time();
            if (!(t < before && t <= until)) {
                break;
            }
            now_ = t;
            tracer_.set_time(t);
            if (!on_impulse(c, plant.take_next_impulse())) {
                return; // something happened: the main loop looks at everything again
            }
        }
        if (!plant.next_event_is_impulse() || t > queued) {
            return; // a speed change ends, or a relay event is due: the main loop
        }
    }
}

void ControlCabinet::handle(const Event& e) {
    if (stop_ && e.kind != EventKind::feed) {
        return; // master switch open: the cabinet is dead
    }
    if (e.kind == EventKind::reference_block) {
        --blocks_queued_;
        reference_block(); // the blocks run on whatever card is in the reader
        return;
    }
    if (e.kind != EventKind::feed && e.card != cards_read_) {
        return; // an action of a card the zeroizing circuit has already cleared
    }
    switch (e.kind) {
    case EventKind::feed:
        feed();
        break;
    case EventKind::first_bank:
        first_bank();
        break;
    case EventKind::relays_pick:
        relays_pick();
        break;
    case EventKind::second_bank:
        for (std::size_t i = 0;
             i < circuits_.size() && !condition_card_ && !sync_card_ && !tap_card_; ++i) {
            for (int k = 0; k < circuits_[i]->order.start_speed; ++k) {
                schedule(now_ + k * profile_.stepping_switch_step_s, EventKind::speed_step_252,
                         static_cast<int>(i));
            }
        }
        break;
    case EventKind::speed_step_252: {
        AxisCircuit& c = *circuits_.at(static_cast<std::size_t>(e.axis));
        c.speed_switch.step_from_card();
        c.show_lamps();
        update_motor(c); // the motor runs at whatever speed the switch stands on
        break;
    }
    case EventKind::read_complete:
        read_complete();
        break;
    case EventKind::delay_258_release: {
        AxisCircuit& c = *circuits_.at(static_cast<std::size_t>(e.axis));
        c.speed_switch.hold_expired(now_);
        evaluate(c);
        break;
    }
    case EventKind::shaft_step:
        shaft_step();
        break;
    case EventKind::action_done:
        acknowledge(e.axis);
        break;
    case EventKind::reference_block:
        break; // taken above
    case EventKind::sync_release:
        sync_release();
        break;
    case EventKind::pc_scan:
        pc_scan();
        break;
    case EventKind::spindle_sample:
        spindle_sample();
        break;
    }
}

void ControlCabinet::feed() {
    if (stop_) {
        return;
    }
    if (keep_resume_point_) {
        resume_point_ = capture();
    }
    tracer_.set(zeroizing_, 0);
    for (SignalId channel :
         {channel_294_, channel_298_, channel_300_, channel_302_, channel_304_}) {
        tracer_.set(channel, 0);
    }
    card_ = next_card();
    condition_card_ = false;
    sync_card_ = false;
    tap_card_ = false;
    if (!card_ && sync_.present() && sync_.scp().pending()) {
        const SynchronisationProcessor& scp = sync_.scp();
        machine_stop(StopReason::sync_refused, std::nullopt,
                     fmt::format("card {} (number {:04}): a sync card with no motion card after "
                                 "it: the deck ends (its orders are for the motion card that "
                                 "follows it; sync cards are an addition after EP 0436887, "
                                 "Mitsubishi)",
                                 scp.pending_card(), scp.pending_number()),
                     "sync lamp (an addition)");
        return;
    }
    if (!card_ && conditions_.stored()) {
        const BufferPair& p =
            conditions_.buffer().pair(conditions_.buffer().first(PairState::stored));
        machine_stop(StopReason::condition_refused, std::nullopt,
                     fmt::format("card {} (number {:04}): a condition card with no motion card "
                                 "after it: the deck ends (condition cards stand before the "
                                 "motion card they watch, EP 0640901 claim 4)",
                                 p.card, p.card_number),
                     "condition lamp (an addition)");
        return;
    }
    if (!card_) {
        deck_finished_ = true;
        tracer_.set(reader_feeding_, 0);
        return;
    }
    ++cards_read_;
    if (record_times_) {
        timings_.push_back(CardTiming{cards_read_, -1, now_, now_});
    }
    orders_ = cardreader::CardOrders{};
    orders_.number = -1;
    tracer_.set(reader_card_, static_cast<std::uint32_t>(cards_read_));
    tracer_.set(reader_feeding_, 1);
    // Fig. 9: on a ribbon (or tape) the next card follows with no gap; it is sensed sooner.
    const double gap = profile_.ribbon_feed && cards_read_ > 1 ? profile_.feed_gap_s : 0.0;
    schedule(now_ + (profile_.first_bank_s - gap), EventKind::first_bank);
    schedule(now_ + (profile_.second_bank_s - gap), EventKind::second_bank);
    schedule(now_ + (profile_.reader_cycle_s - gap), EventKind::read_complete);
}

void ControlCabinet::first_bank() {
    SensedCard sensed = sense_card(*card_, layout_, profile_.refuse_double_punch);
    if (!sensed.decoded) {
        const auto& bad = *sensed.decoded.bad_punch;
        machine_stop(StopReason::bad_punch, std::nullopt,
                     fmt::format("card {}, column {}: {}: the reader stops the machine (bad-punch "
                                 "refusal, an addition of this emulator: a 1952 reader would "
                                 "sense the holes as they are)",
                                 cards_read_, bad.column, bad.what),
                     "card reader 134 check lamp (an addition)");
        return;
    }
    orders_ = sensed.decoded.orders;
    extra_relays_ = sensed.extra;
    if (record_times_) {
        timings_.back().number = orders_.number;
    }
    if (tracer_.observer() != nullptr) {
        tracer_.observer()->on_card(now_, cards_read_, orders_);
    }
    // The card-number check (col. 8, no numeral): each card must be the previous one + 1
    // (0000 follows 9999).
    if (previous_number_ && orders_.number != (*previous_number_ + 1) % 10000) {
        machine_stop(StopReason::out_of_order_card, std::nullopt,
                     fmt::format("{}: card number {:04} follows {:04} (expected {:04}); stopped "
                                 "before any axis moved",
                                 card_name(), orders_.number, *previous_number_,
                                 (*previous_number_ + 1) % 10000),
                     "card-number lamp");
        return;
    }
    previous_number_ = orders_.number;
    tracer_.set(card_number_check_, static_cast<std::uint32_t>(orders_.number));
    if (sync_.present() && tape_index_ < tape_numbers_.size()) {
        tape_numbers_.at(tape_index_) = orders_.number;
    }
    if (orders_.kind == cardreader::CardKind::condition) {
        condition_card();
        return;
    }
    if (orders_.kind == cardreader::CardKind::sync) {
        sync_card();
        return;
    }
    if (orders_.kind == cardreader::CardKind::tap) {
        tap_card();
        return;
    }
    if (sync_.present() && sync_.scp().pending()) {
        // Speed synchronisation of an axis this card does not move cannot be followed.
        const SynchronisationProcessor& scp = sync_.scp();
        for (Axis a : cardreader::kAxes) {
            if (scp.pending_order().travel_per_pulse.at(cardreader::axis_index(a)) &&
                orders_.axis(a).check == 0) {
                machine_stop(StopReason::sync_refused, a,
                             fmt::format("{}: sync card {} (number {:04}) orders speed "
                                         "synchronisation of the {} axis, which this card does "
                                         "not move (check 0) (sync cards are an addition after "
                                         "EP 0436887, Mitsubishi)",
                                         card_name(), scp.pending_card(), scp.pending_number(),
                                         axis_name(a)),
                             "sync lamp (an addition)");
                return;
            }
        }
    }
    if (auto refusal = conditions_.refuse_unmoved(orders_, cards_read_)) {
        machine_stop(StopReason::condition_refused, std::nullopt, *refusal,
                     "condition lamp (an addition)");
        return;
    }
    if (!move_within_soft_limits()) {
        return;
    }
    // The brushes have sensed the card; the holding relays pick a relay's operate time later.
    schedule(now_ + profile_.relay_operate_s, EventKind::relays_pick);
}

// The reader takes the next card: from the deck, or, after a loop card sent it back, again
// from the cards it has taken (press synchronisation keeps them, as a ribbon made into an
// endless loop keeps its cards).
std::optional<cardreader::Card> ControlCabinet::next_card() {
    if (!sync_.present()) {
        return deck_->next();
    }
    if (replay_ < tape_.size()) {
        tape_index_ = replay_++;
        return tape_.at(tape_index_);
    }
    std::optional<cardreader::Card> card = deck_->next();
    if (card) {
        ++deck_taken_;
        tape_.push_back(*card);
        tape_numbers_.push_back(-1); // known once the first bank has sensed it
        tape_index_ = tape_.size() - 1;
        replay_ = tape_.size();
    }
    return card;
}

// Resuming a run with press synchronisation: the cards the reader had taken from the deck are
// taken again, their numbers read, so that a loop card finds its way back.
void ControlCabinet::resume_tape(std::int64_t taken) {
    std::vector<cardreader::Card> saved_tape;
    for (std::int64_t i = 0; i < taken; ++i) {
        std::optional<cardreader::Card> card = deck_->next();
        if (!card) {
            throw cardreader::DeckError(fmt::format(
                "the deck has {} cards; the saved state resumes after card {}", i, taken));
        }
        const cardreader::DecodeResult decoded = cardreader::decode(*card, layout_);
        tape_.push_back(*card);
        tape_numbers_.push_back(decoded ? decoded.orders.number : -1);
    }
}

// A sync card (an addition after EP 0436887): no axis moves; its orders wait in readers 60 and
// 62 for the motion card after it, or, a loop card, it sends the reader back at the end of its
// card cycle.
void ControlCabinet::sync_card() {
    sync_card_ = true;
    if (!sync_.present()) {
        machine_stop(StopReason::sync_refused, std::nullopt,
                     fmt::format("{}, column {}: a sync card (an addition after EP 0436887, "
                                 "Mitsubishi): profile {} has no press synchronisation; the "
                                 "built-in profile parsons-extended has it",
                                 card_name(), layout_.extension_column, profile_.name),
                     "card reader 134 check lamp (an addition)");
        return;
    }
    if (orders_.sync.loop) {
        return; // at the end of its card cycle (read_complete)
    }
    SynchronisationProcessor& scp = sync_.scp();
    if (scp.pending()) {
        machine_stop(StopReason::sync_refused, std::nullopt,
                     fmt::format("{}: a second sync card before one motion card (card {}, "
                                 "number {:04}, waits already; sync cards are an addition after "
                                 "EP 0436887, Mitsubishi)",
                                 card_name(), scp.pending_card(), scp.pending_number()),
                     "sync lamp (an addition)");
        return;
    }
    scp.take(orders_.sync, cards_read_, orders_.number);
}

// The seed's M99: the reader goes back to the card numbered loop_to, loop_count times; the
// card-number check then expects that number next.
void ControlCabinet::loop_card() {
    const cardreader::SyncOrder& o = orders_.sync;
    ++cycles_;
    const auto it = loops_left_.find(tape_index_);
    const int left = it == loops_left_.end() ? o.loop_count : it->second;
    if (left <= 0) {
        loops_left_.erase(tape_index_); // done: armed again if the reader comes round again
        return;
    }
    std::optional<std::size_t> target;
    for (std::size_t j = tape_index_; j-- > 0;) {
        if (tape_numbers_.at(j) == o.loop_to) {
            target = j;
            break;
        }
    }
    if (!target) {
        machine_stop(StopReason::sync_refused, std::nullopt,
                     fmt::format("{}: a loop card to card number {:04}, which the deck does not "
                                 "hold before it (the seed's M99; sync cards are an addition "
                                 "after EP 0436887, Mitsubishi)",
                                 card_name(), o.loop_to),
                     "sync lamp (an addition)");
        return;
    }
    loops_left_[tape_index_] = left - 1;
    replay_ = *target;
    previous_number_ = (o.loop_to + 9999) % 10000;
    if (loop_backs_ > 0) {
        const double cycle = now_ - last_loop_back_s_;
        shortest_cycle_s_ = loop_backs_ == 1 ? cycle : std::min(shortest_cycle_s_, cycle);
        longest_cycle_s_ = loop_backs_ == 1 ? cycle : std::max(longest_cycle_s_, cycle);
    } else {
        first_loop_back_s_ = now_;
    }
    last_loop_back_s_ = now_;
    ++loop_backs_;
}

// Detector edges due by time t: in fast-forward the quiet ones in one jump, then the one due now.
void ControlCabinet::press_edges(double t) {
    axes::Press& press = sync_.press();
    if (jumping_ && press_quiet_ > 0) {
        const std::int64_t n = std::min(press_quiet_, press.pulses_by(t));
        if (n > 0) {
            const double at = press.pulse_time(n);
            const axes::DetectorEdge last = press.skip_pulses(n);
            sync_.on_edges(n, last, at);
            press_quiet_ -= n;
        }
    }
    if (press.next_event_time() <= t) {
        if (auto edge = press.advance_to(t)) {
            if (sync_.on_edge(*edge, t)) {
                // Detector 61 conducts; 60's hold relay drops a relay's time later.
                schedule(t + profile_.relay_operate_s, EventKind::sync_release);
            }
        }
    }
}

void ControlCabinet::schedule_block() {
    schedule(static_cast<double>(block_) * profile_.speed_sample_s, EventKind::reference_block);
}

// A reference block of Fig. 6: the speeds processor 63 computed last block go to the drives,
// speed register 11 is read, 63 computes the next; and the wait is timed (sync_timeout).
void ControlCabinet::reference_block() {
    if (deck_finished_ || stop_) {
        return;
    }
    SynchronisationProcessor& scp = sync_.scp();
    const int pulses = sync_.sample_speed();
    if (scp.reference_block(pulses, profile_.sync_drive.max_in_per_min / 60.0)) {
        for (auto& c : circuits_) {
            if (scp.speed_synced(c->axis)) {
                update_motor(*c);
            }
        }
    }
    const double timeout = profile_.sync_timeout_s;
    if (scp.holding() && now_ - scp.hold_since() >= timeout) {
        machine_stop(StopReason::sync_timeout, std::nullopt,
                     fmt::format("{}: the card waited {:.1f} s for crank 21 to reach {} deg and "
                                 "it did not (crank at {:.1f} deg{}); synchronisation control "
                                 "processor 17 gave up after sync_timeout_s {:.1f} s (press "
                                 "synchronisation is an addition after EP 0436887, Mitsubishi)",
                                 card_name(), now_ - scp.hold_since(),
                                 scp.target_pulses() / sync_.press().profile().pulses_per_degree,
                                 sync_.press().angle_deg(),
                                 sync_.press().stopped() ? ", motor 22 stopped" : "", timeout),
                     "sync lamp (an addition)");
        return;
    }
    if (!scp.holding() && now_ - sync_.last_edge_s() >= timeout) {
        for (const auto& c : circuits_) {
            if (c->powered && scp.speed_synced(c->axis)) {
                machine_stop(StopReason::sync_timeout, c->axis,
                             fmt::format("{}, {}: speed-synchronised, and detector 10 gave no "
                                         "pulse for {:.1f} s (crank at {:.1f} deg{}): the axis "
                                         "stands; synchronisation control processor 17 gave up "
                                         "after sync_timeout_s {:.1f} s (press synchronisation "
                                         "is an addition after EP 0436887, Mitsubishi)",
                                         card_name(), axis_name(c->axis),
                                         now_ - sync_.last_edge_s(), sync_.press().angle_deg(),
                                         sync_.press().stopped() ? ", motor 22 stopped" : "",
                                         timeout),
                             "sync lamp (an addition)");
                return;
            }
        }
    }
    ++block_;
    schedule_block();
}

void ControlCabinet::sync_release() {
    SynchronisationProcessor& scp = sync_.scp();
    if (!scp.holding()) {
        return;
    }
    waited_s_ += now_ - scp.hold_since();
    scp.release();
    update_motors();
    for (auto& c : circuits_) {
        evaluate(*c);
    }
}

// The cabinet waits on the press: a card held for its angle, or a speed-synchronised axis
// powered (its speed is the press's).
bool ControlCabinet::waiting_on_press() const {
    const SynchronisationProcessor& scp = sync_.scp();
    if (scp.holding()) {
        return true;
    }
    for (const auto& c : circuits_) {
        if (c->powered && scp.speed_synced(c->axis)) {
            return true;
        }
    }
    return false;
}

// Nothing can happen but the press turning and the reference blocks: no axis moves, no other
// event is queued, and nothing waits on the press.
bool ControlCabinet::idle() const {
    if (queue_.size() != static_cast<std::size_t>(blocks_queued_) || unqueued_release_s_ > now_) {
        return false;
    }
    for (std::size_t i = 0; i < circuits_.size(); ++i) {
        if (next_axis_event(i) != axes::kNever) {
            return false;
        }
    }
    return !waiting_on_press();
}

// A condition card (an addition after EP 0640901): no axis moves; converter UMS enters its
// records into buffer PFR, and at the end of the card cycle channel 304 indexes the next card.
void ControlCabinet::condition_card() {
    condition_card_ = true;
    if (!conditions_.present()) {
        machine_stop(StopReason::condition_refused, std::nullopt,
                     fmt::format("{}, column {}: a condition card (an addition after EP 0640901, "
                                 "Siemens): profile {} has no condition units; the built-in "
                                 "profile parsons-extended allows them",
                                 card_name(), layout_.extension_column, profile_.name),
                     "card reader 134 check lamp (an addition)");
        return;
    }
    if (auto refusal = conditions_.convert(orders_, cards_read_)) {
        machine_stop(StopReason::condition_refused, std::nullopt, *refusal,
                     "condition lamp (an addition)");
    }
}

// The movement range, judged on the card before anything moves: where would each axis end
// if it travels exactly its check in the sense of its motion column?
bool ControlCabinet::move_within_soft_limits() {
    for (const auto& c : circuits_) {
        const auto& p = c->plant.profile();
        if (!p.soft_limits) {
            continue;
        }
        const cardreader::AxisOrder& o = orders_.axis(c->axis);
        const double from = c->plant.real_in();
        const double move = (o.motion == cardreader::Motion::forward ? 1 : -1) * o.check / 1000.0;
        const double to = from + move;
        if (to > p.soft_max_in || to < p.soft_min_in) {
            machine_stop(StopReason::soft_limit, c->axis,
                         fmt::format("{}, {}: this card moves it {:+.3f} in, from {:.4f} to {:.4f} "
                                     "in, past its soft limit {:.3f} in (movement range {:.3f} .. "
                                     "{:.3f} in); stopped before any axis moved (soft limits are "
                                     "an addition of this emulator, after Mitsubishi's movement "
                                     "range)",
                                     card_name(), axis_name(c->axis), move, from, to,
                                     to > p.soft_max_in ? p.soft_max_in : p.soft_min_in,
                                     p.soft_min_in, p.soft_max_in),
                         fmt::format("soft-limit lamp ({}; an addition)", axis_name(c->axis)));
            return false;
        }
    }
    return true;
}

void ControlCabinet::relays_pick() {
    tracer_.set(spindle_165_, static_cast<std::uint32_t>(orders_.spindle));
    last_sequence_position_ = 0;
    for (auto& c : circuits_) {
        c->order = orders_.axis(c->axis);
        c->set_direction(c->order.motion);
        std::array<int, 3> numbers{};
        std::size_t count = 0;
        for (const auto& sd : c->order.slow_down) {
            if (sd) {
                numbers.at(count++) = *sd;
            }
        }
        numbers.at(count++) = c->order.stop;
        c->absolute_storage.store(std::span<const int>(numbers.data(), count));
        c->incremental_storage.store(c->order.check);
        // A double-punched digit column picks a second relay of its bank (parsons-1952).
        const auto& extra = extra_relays_.at(cardreader::axis_index(c->axis));
        for (std::size_t field = 0; field < kNumberFields; ++field) {
            for (std::size_t i = 0; i < 4; ++i) {
                const unsigned mask = extra.at(field).at(i);
                if (mask == 0) {
                    continue; // the common case: one punch a column
                }
                HoldingRelayBank& bank = field < 3
                                             ? c->absolute_storage.bank(static_cast<int>(i))
                                             : c->incremental_storage.bank(static_cast<int>(i));
                for (int d = 0; d < 10; ++d) {
                    if ((mask >> d & 1U) != 0) {
                        bank.pick(d);
                    }
                }
            }
        }
        c->sequence_switch.close_pattern(c->order.sequence);
        for (int p = 5; p >= 1; --p) {
            if (c->sequence_switch.closed(p)) {
                last_sequence_position_ = std::max(last_sequence_position_, p);
                break;
            }
        }
        c->compare();
    }
    if (conditions_.present()) {
        conditions_.spindle_from_card(orders_.spindle, now_);
        conditions_.arm(cards_read_); // PFR supplies each stored condition to PRG
    }
    if (sync_.present()) {
        sync_.scp().arm(); // a sync card's orders into readers 60 and 62
    }
}

void ControlCabinet::read_complete() {
    reading_complete_ = true;
    tracer_.set(reader_feeding_, 0);
    if (tap_card_) {
        reading_complete_ = false; // no axis moves by the 1952 columns
        start_tool_call();
        return;
    }
    if (condition_card_ || sync_card_) {
        reading_complete_ = false;
        if (sync_card_ && orders_.sync.loop) {
            loop_card();
            if (stop_) {
                return;
            }
        }
        tracer_.set(channel_304_, 1); // nothing to move: the reader indexes the next card
        schedule(now_, EventKind::feed);
        return;
    }
    if (sync_.present() && sync_.scp().hold_unless_at(sync_.position_register().value(), now_)) {
        return; // position reader 60 holds the card's motion until the crank reaches R
    }
    update_motors();
    for (auto& c : circuits_) {
        evaluate(*c);
    }
}

bool ControlCabinet::live(const AxisCircuit& c) const {
    return balancing_.master_switch_closed() && reading_complete_ && !c.stopped &&
           !c.speed_switch.off() && c.sequence_switch.closed(shaft_.position()) &&
           !(sync_.present() && sync_.scp().holding());
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
    if (tapping_.present() && tapping_.feeding(c.axis) && !stop_) {
        tap_counting_sense(c, impulse.direction);
    }
    const bool hundredths_only =
        profile_.count_hundredths_at_speed_1 && c.speed_switch.position() == 1 && !stop_;
    // The counters count up or down as reversing control 214 set them (the motion column),
    // whichever way the screw really turns: coast that runs on after the next card has set the
    // other sense is counted the wrong way, as on the 1952 machine.
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
    bool quiet = !(stepped && conditions_.watching(c.axis) && conditions_met(c));
    c.compare();
    if (!c.absolute_conducting && !c.incremental_conducting) {
        c.speed_switch.equality_left(now_);
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

// Monitoring unit PRG: the axis's counter stepped; each channel whose circuit closed reports its
// identifier, and tripping unit ALE initiates that channel's action (EP 0640901 claim 1).
bool ControlCabinet::conditions_met(AxisCircuit& c) {
    const unsigned met =
        conditions_.on_counter_step(c.axis, c.absolute_counter.digits(), c.direction);
    for (int k = 0; k < InternalBuffer::kChannels; ++k) {
        if ((met >> k & 1U) == 0) {
            continue;
        }
        const double done = conditions_.trip(k, now_);
        tell(k, ConditionEventKind::met);
        tell(k, ConditionEventKind::action_started);
        schedule(done, EventKind::action_done, k);
        const ActionEntry& a = conditions_.buffer().pair(k).action;
        if (a.action == cardreader::ActionKind::dwell) {
            update_motor(*circuits_.at(static_cast<std::size_t>(a.parameter - 1)));
        }
    }
    return met != 0;
}

void ControlCabinet::acknowledge(int channel) {
    conditions_.acknowledge(channel, now_);
    tell(channel, ConditionEventKind::acknowledged);
    const ActionEntry& a = conditions_.buffer().pair(channel).action;
    if (a.action == cardreader::ActionKind::dwell) {
        update_motor(*circuits_.at(static_cast<std::size_t>(a.parameter - 1)));
    }
    if (zeroize_waiting_ && conditions_.all_acknowledged()) {
        zeroize_waiting_ = false;
        conditions_.set_waiting(false);
        zeroize(); // claim 2: every action acknowledged, the next card may be processed
    }
}

void ControlCabinet::tell(int channel, ConditionEventKind kind) {
    if (tracer_.observer() != nullptr) {
        tracer_.observer()->on_condition(
            now_, conditions_.event(channel, kind, cards_read_, orders_.number));
    }
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
    machine_stop(StopReason::soft_limit, c.axis,
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

void ControlCabinet::stop_axis(AxisCircuit& c) {
    const bool absolute = c.absolute_conducting;
    const bool incremental = c.incremental_conducting;
    if (c.speed_switch.position() == 3) {
        c.speed_switch.impulse_256(now_, profile_.delay_258_s); // 3 -> off: contact 238
    } else {
        c.speed_switch.to_off(now_, profile_.delay_258_s); // the interpretation: from 1 or 2
    }
    release_after_stop(c);
    c.stopped = true;
    motion_end_s_ = now_;
    c.show_lamps();
    update_motor(c);
    if (!balancing_.check_at_stop(absolute, incremental)) {
        c.tripped = true;
        c.show_lamps();
        const std::string which = absolute ? "only the absolute comparer 122' conducted"
                                           : "only the incremental "
                                             "comparer 122'' conducted";
        machine_stop(StopReason::check_mismatch, c.axis,
                     fmt::format("{}, {}: at the stop {}: absolute counter {} (stop {}), "
                                 "increment counter {} (check {}); balancing circuit 266 opened "
                                 "master switch 204",
                                 card_name(), axis_name(c.axis), which,
                                 inches(c.absolute_counter.value()), inches(c.order.stop),
                                 inches(c.increment_counter.value()), inches(c.order.check)),
                     "");
        return;
    }
    shaft_.impulse(now_); // through contact 238, channel 274, circuit 276 to motor 278
    if (!shaft_.busy()) {
        shaft_.begin_step();
        schedule(now_ + profile_.sequence_shaft_step_s, EventKind::shaft_step);
    }
}

// Delay 258 holds channel 257 after the stop too. Its release drops relay 256 and the hold
// (trace signals), reads the comparers again and, if neither conducts, notes that the equality
// has left; none of it can act on the axis, which is not live (stopped) until zeroizing resets
// switch 236 and delay 258 (channel 300). So with no observer to see the relays drop the
// release is not queued: its sequence number is taken all the same (every other event keeps
// its order, the saved event_sequence its value), and the main loop still comes to its
// instant if nothing else is left to do, so the run ends at the same machine time.
void ControlCabinet::release_after_stop(const AxisCircuit& c) {
    if (tracer_.observer() != nullptr) {
        schedule(c.speed_switch.hold_until(), EventKind::delay_258_release,
                 static_cast<int>(cardreader::axis_index(c.axis)));
        return;
    }
    ++seq_;
    unqueued_release_s_ = std::max(unqueued_release_s_, c.speed_switch.hold_until());
}

void ControlCabinet::shaft_step() {
    if (shaft_.finish_step()) {
        shaft_home();
        return;
    }
    if (shaft_.pending() > 0) {
        shaft_.begin_step();
        schedule(now_ + profile_.sequence_shaft_step_s, EventKind::shaft_step);
    }
    update_motors();
    for (auto& c : circuits_) {
        evaluate(*c);
    }
}

// Members 282 home past contact 290. With condition cards (an addition), a condition still
// armed was never met on this card: the machine stops; and the zeroizing circuit waits until
// tripping unit ALE has every action acknowledged (EP 0640901 claim 2).
void ControlCabinet::shaft_home() {
    const int unmet = conditions_.first_unmet();
    if (unmet >= 0) {
        const BufferPair& p = conditions_.buffer().pair(unmet);
        const AxisCircuit& c = *circuits_.at(cardreader::axis_index(p.condition.axis));
        machine_stop(
            StopReason::condition_not_met, p.condition.axis,
            fmt::format("{}: event {} (condition card {}) was not met: the {} axis "
                        "never passed {} {} before the card's last axis stopped (its "
                        "counter reads {}; condition cards are an addition after "
                        "EP 0640901, Siemens)",
                        card_name(), p.condition.event, p.card, axis_name(p.condition.axis),
                        format_inches(p.condition.position),
                        p.condition.sense == cardreader::PassingSense::either
                            ? std::string("in either sense")
                            : fmt::format("counting {}",
                                          p.condition.sense == cardreader::PassingSense::forward
                                              ? "up (forward)"
                                              : "down (reverse)"),
                        inches(c.absolute_counter.value())),
            "condition lamp (monitoring unit PRG; an addition)");
        return;
    }
    if (!conditions_.all_acknowledged()) {
        zeroize_waiting_ = true;
        conditions_.set_waiting(true);
        return;
    }
    zeroize();
}

// Contact 290 closed circuit 292-294: the zeroizing circuit, one channel after the other, each
// signal set before the relays it acts on (col. 11). Emulation note: the speed switches stand
// on off already (every axis stopped); the cabinet resets their delay devices here.
void ControlCabinet::zeroize() {
    tracer_.set(zeroizing_, 1);
    tracer_.set(channel_294_, 1); // clears absolute storage 350-356 (122')
    for (auto& c : circuits_) {
        c->absolute_storage.clear();
    }
    tracer_.set(channel_298_, 1); // clears number and counter of the incremental comparer 122''
    for (auto& c : circuits_) {
        c->incremental_storage.clear();
        c->increment_counter.clear();
    }
    tracer_.set(channel_300_, 1); // opens every contact of the sequence switches 224
    for (auto& c : circuits_) {
        c->sequence_switch.open_all();
        c->speed_switch.reset();
        c->stopped = false;
        c->tripped = false;
        c->compare();
    }
    tracer_.set(channel_302_, 1); // resets device 288, closing circuit 274
    shaft_.reset();
    if (conditions_.present()) {
        const std::size_t first = actions_.size();
        for (int k = 0; k < InternalBuffer::kChannels; ++k) {
            const BufferPair& p = conditions_.buffer().pair(k);
            if (p.state == PairState::acknowledged) {
                actions_.push_back(
                    ActionRecord{p.condition.event, p.card, cards_read_, orders_.number,
                                 p.condition.axis, p.condition.position, p.action.action,
                                 p.action.parameter, p.tripped_s, p.acknowledged_s, motion_end_s_});
            }
        }
        // The card's actions in the order they were tripped (channel order at one instant).
        std::stable_sort(
            actions_.begin() + static_cast<std::ptrdiff_t>(first), actions_.end(),
            [](const ActionRecord& a, const ActionRecord& b) { return a.tripped_s < b.tripped_s; });
        conditions_.zeroize(); // channel 294 clears PFR and PRG too
    }
    if (sync_.present()) {
        sync_.scp().clear(); // and readers 60 and 62
    }
    tracer_.set(channel_304_, 1); // indexes card reader 134 to the next card
    reading_complete_ = false;
    update_motors();
    if (record_times_) {
        timings_.back().end_s = now_;
    }
    schedule(now_ + profile_.relay_release_s, EventKind::feed); // channel 304
}

void ControlCabinet::update_motor(AxisCircuit& c) {
    const bool on = live(c) && !conditions_.held(c.axis); // a dwell opens the hold relay
    if (auto impulse = c.plant.advance_to(now_)) {
        on_impulse(c, *impulse); // never let an impulse due now go uncounted
    }
    if (tapping_.present() && tapping_.feeding(c.axis) && !stop_) {
        // A tap: the synchronous operation control sets the follower drive.
        const FeedCommand f = tapping_.feed();
        c.plant.command_follow(f.direction, f.speed_in_per_s,
                               profile_.sync_drive.acceleration_in_per_s2);
        c.set_powered(true);
        return;
    }
    if (on && sync_.present() && c.speed_switch.position() == 1 &&
        sync_.scp().speed_synced(c.axis)) {
        // Speed synchronisation: speed 1 is the follower drive at processor 63's speed.
        c.plant.command_follow(c.direction, sync_.scp().output(c.axis),
                               profile_.sync_drive.acceleration_in_per_s2);
    } else {
        c.plant.command(c.direction, on ? c.speed_switch.position() : 0);
    }
    c.set_powered(on);
}

void ControlCabinet::update_motors() {
    bool cutting = false;
    for (auto& c : circuits_) {
        update_motor(*c);
        cutting = cutting || (c->powered && shaft_.position() == last_sequence_position_);
    }
    tracer_.set(cutting_, cutting && orders_.spindle != cardreader::Spindle::off ? 1 : 0);
}

void ControlCabinet::machine_stop(StopReason reason, std::optional<Axis> axis,
                                  const std::string& message, const std::string& lamp) {
    if (stop_) {
        return;
    }
    if (reason == StopReason::interrupted) {
        balancing_.open_by_operator();
    } else {
        balancing_.trip();
    }
    if (!lamp.empty()) {
        balancing_.light(lamp);
    }
    StopInfo info;
    info.reason = reason;
    info.card = cards_read_;
    info.card_number = orders_.number;
    info.axis = axis;
    info.message = message;
    info.lamps = balancing_.lamps();
    stop_ = info;
    if (record_times_ && !timings_.empty()) {
        timings_.back().end_s = now_;
    }
    queue_ = {};
    blocks_queued_ = 0;
    unqueued_release_s_ = -axes::kNever;
    if (tapping_.present()) {
        spindle_edges(now_);
        tapping_.halt(); // motor 27 runs down to rest; the feed is the 1952 motor's again
    }
    update_motors();
    if (tracer_.observer() != nullptr) {
        tracer_.observer()->on_stop(now_, info);
    }
}

void ControlCabinet::sequence_stall() {
    std::string waiting;
    for (const auto& c : circuits_) {
        if (!c->stopped) {
            waiting +=
                fmt::format("{}{} (pattern {})", waiting.empty() ? "" : ", ", axis_name(c->axis),
                            cardreader::format_sequence(c->sequence_switch.pattern()).empty()
                                ? std::string("none")
                                : cardreader::format_sequence(c->sequence_switch.pattern()));
        }
    }
    machine_stop(StopReason::sequence_stall, std::nullopt,
                 fmt::format("{}: sequence stall (an addition of this emulator: the 1952 "
                             "machine would stand idle for good): stepping shaft 280 stands at "
                             "position {} and no axis that has not stopped is enabled there; "
                             "waiting: {}",
                             card_name(), shaft_.position(), waiting),
                 "sequence lamp (stepping shaft 280; an addition)");
}

bool ControlCabinet::interrupted() {
    if (interrupt_ == nullptr || *interrupt_ == 0 || stop_) {
        return false;
    }
    machine_stop(StopReason::interrupted, std::nullopt,
                 fmt::format("{}: the operator stopped the run (signal) at {:.3f} s of machine "
                             "time",
                             card_name(), now_),
                 "");
    return true;
}

nlohmann::json ControlCabinet::capture() const {
    using axes::exact;
    nlohmann::json axes = nlohmann::json::object();
    for (const auto& c : circuits_) {
        axes[std::string(axis_name(c->axis))] = c->save();
    }
    nlohmann::json times = nlohmann::json::array();
    for (const CardTiming& ct : timings_) {
        times.push_back({ct.index, ct.number, exact(ct.start_s), exact(ct.end_s)});
    }
    nlohmann::json faults = nlohmann::json::array();
    for (const FaultEffect& e : effects_) {
        faults.push_back({{"fault", e.spec}, {"acted", e.acted}, {"effect", e.effect}});
    }
    return nlohmann::json{{"machine_seconds", exact(now_)},
                          {"event_sequence", seq_},
                          {"cards_read", cards_read_},
                          {"card_number_check", previous_number_ ? nlohmann::json(*previous_number_)
                                                                 : nlohmann::json(nullptr)},
                          {"last_card_number", orders_.number},
                          {"spindle", static_cast<int>(orders_.spindle)},
                          {"last_sequence_position", last_sequence_position_},
                          {"axes", axes},
                          {"stepping_shaft_280", shaft_.save()},
                          {"signals", tracer_.save()},
                          {"card_times", times},
                          {"faults", faults},
                          {"conditions", conditions_.save()},
                          {"actions", actions_to_json(actions_)},
                          {"sync", capture_sync()},
                          {"tapping", tapping_.present() ? tapping_.save() : nlohmann::json()}};
}

nlohmann::json ControlCabinet::capture_sync() const {
    if (!sync_.present()) {
        return nullptr;
    }
    using axes::exact;
    nlohmann::json loops = nlohmann::json::array();
    for (const auto& [index, left] : loops_left_) {
        loops.push_back({index, left});
    }
    return {{"units", sync_.save()},
            {"deck_cards_taken", deck_taken_},
            {"replay", replay_},
            {"tape_index", tape_index_},
            {"loops_left", loops},
            {"cycles", cycles_},
            {"loop_backs", loop_backs_},
            {"first_loop_back_s", exact(first_loop_back_s_)},
            {"last_loop_back_s", exact(last_loop_back_s_)},
            {"shortest_cycle_s", exact(shortest_cycle_s_)},
            {"longest_cycle_s", exact(longest_cycle_s_)},
            {"waited_s", exact(waited_s_)},
            {"reference_block", block_}};
}

void ControlCabinet::resume_sync(const nlohmann::json& j) {
    using axes::exact;
    using axes::member;
    using axes::read;
    if (!sync_.present()) {
        if (!j.is_null()) {
            throw axes::StateError("the saved machine has a press; this profile has none");
        }
        return;
    }
    if (j.is_null()) {
        throw axes::StateError("the saved machine has no press; this profile has one");
    }
    sync_.load(member(j, "units"));
    deck_taken_ = read<std::int64_t>(j, "deck_cards_taken");
    replay_ = read<std::size_t>(j, "replay");
    tape_index_ = read<std::size_t>(j, "tape_index");
    loops_left_.clear();
    for (const auto& l : member(j, "loops_left")) {
        loops_left_[l.at(0).get<std::size_t>()] = l.at(1).get<int>();
    }
    cycles_ = read<std::int64_t>(j, "cycles");
    loop_backs_ = read<std::int64_t>(j, "loop_backs");
    first_loop_back_s_ = exact(member(j, "first_loop_back_s"));
    last_loop_back_s_ = exact(member(j, "last_loop_back_s"));
    shortest_cycle_s_ = exact(member(j, "shortest_cycle_s"));
    longest_cycle_s_ = exact(member(j, "longest_cycle_s"));
    waited_s_ = exact(member(j, "waited_s"));
    block_ = read<std::int64_t>(j, "reference_block");
    if (deck_taken_ < 0 || replay_ > static_cast<std::size_t>(deck_taken_) || block_ < 1) {
        throw axes::StateError("sync: deck_cards_taken, replay and reference_block out of range");
    }
}

void ControlCabinet::resume(const nlohmann::json& j) {
    using axes::exact;
    using axes::member;
    using axes::read;
    now_ = exact(member(j, "machine_seconds"));
    seq_ = read<std::uint64_t>(j, "event_sequence");
    cards_read_ = read<std::int64_t>(j, "cards_read");
    const auto& number = member(j, "card_number_check");
    previous_number_ = number.is_null() ? std::nullopt : std::optional(number.get<int>());
    orders_ = cardreader::CardOrders{};
    orders_.number = read<int>(j, "last_card_number");
    orders_.spindle = static_cast<cardreader::Spindle>(read<int>(j, "spindle"));
    last_sequence_position_ = read<int>(j, "last_sequence_position");
    const auto& axes = member(j, "axes");
    for (auto& c : circuits_) {
        c->load(member(axes, std::string(axis_name(c->axis)).c_str()));
    }
    shaft_.load(member(j, "stepping_shaft_280"));
    tracer_.load(member(j, "signals"));
    timings_.clear();
    for (const auto& t : member(j, "card_times")) {
        timings_.push_back(CardTiming{t.at(0).get<std::int64_t>(), t.at(1).get<int>(),
                                      exact(t.at(2)), exact(t.at(3))});
    }
    conditions_.load(j.contains("conditions") ? j.at("conditions") : nlohmann::json());
    actions_ = actions_from_json(j.contains("actions") ? j.at("actions") : nlohmann::json::array());
    resume_sync(j.contains("sync") ? j.at("sync") : nlohmann::json());
    const bool saved_tapping = j.contains("tapping") && !j.at("tapping").is_null();
    if (saved_tapping != tapping_.present()) {
        throw axes::StateError(saved_tapping ? "the saved state has spindle synchronisation and "
                                               "this profile has none"
                                             : "this profile has spindle synchronisation and the "
                                               "saved state has none");
    }
    if (saved_tapping) {
        tapping_.load(j.at("tapping"));
    }
    effects_.clear();
    for (const auto& e : member(j, "faults")) {
        effects_.push_back(FaultEffect{read<std::string>(e, "fault"), read<bool>(e, "acted"),
                                       read<std::string>(e, "effect")});
    }
    if (cards_read_ < 0 || now_ < 0) {
        throw axes::StateError("cards_read and machine_seconds must not be negative");
    }
    reading_complete_ = false;
    deck_finished_ = false;
    stop_.reset();
    resuming_ = true;
}

RunResult ControlCabinet::result() const {
    RunResult r;
    r.completed = deck_finished_ && !stop_;
    r.cards_read = cards_read_;
    r.machine_seconds = now_;
    r.stop = stop_;
    r.cards = timings_;
    r.faults = effects_;
    r.actions = actions_;
    if (conditions_.present()) {
        r.tool_in_spindle = conditions_.ale().tool_in_spindle();
    }
    if (sync_.present()) {
        PressResult p;
        p.revolution = sync_.press().revolution();
        p.crank_angle_deg = sync_.press().angle_deg();
        p.position_register = sync_.position_register().value();
        p.press_stopped = sync_.press().stopped();
        p.cycles = cycles_;
        p.loop_backs = loop_backs_;
        if (loop_backs_ >= 2) {
            p.mean_cycle_s =
                (last_loop_back_s_ - first_loop_back_s_) / static_cast<double>(loop_backs_ - 1);
            p.shortest_cycle_s = shortest_cycle_s_;
            p.longest_cycle_s = longest_cycle_s_;
        }
        p.waited_s = waited_s_;
        r.press = p;
    }
    if (tapping_.present()) {
        TappingResult tr;
        tr.tool_on_spindle = tapping_.spindle().tool();
        tr.ratio_in_memory = tapping_.memory().ratio();
        tr.head_exchanges = tapping_.pc().exchanges();
        tr.transfers = tapping_.pc().transfers();
        tr.ratios_received = tapping_.memory().received();
        tr.holes = tapping_.holes();
        r.tapping = std::move(tr);
    }
    for (std::size_t i = 0; i < circuits_.size(); ++i) {
        const AxisCircuit& c = *circuits_[i];
        AxisResult& a = r.axes.at(i);
        a.counter_in = c.absolute_counter.value() / 1000.0;
        a.real_in = c.plant.real_in();
        // The counters read 0 .. 9.999 and wrap; the error counts the wraps (switch 104's turns),
        // so a part 10 inches from where the counters say is not reported as on the spot.
        a.error_in = a.real_in - static_cast<double>(c.absolute_counter.unwrapped_value()) / 1000.0;
        a.impulses = c.plant.impulses();
        a.lost_steps = c.absolute_counter.lost() + c.increment_counter.lost();
        if (orders_.number >= 0) {
            a.last_stop_in = c.order.stop / 1000.0;
        }
        a.slip_in = c.plant.slip_in();
        a.screw_in = c.plant.screw_in();
        for (std::size_t k = 0; k < 4; ++k) {
            a.skipped_steps += c.absolute_counter.stepping_switch(k).skipped() ? 1 : 0;
            a.skipped_steps += c.increment_counter.stepping_switch(k).skipped() ? 1 : 0;
        }
        if (c.axis == Axis::swivel || c.axis == Axis::tilt) {
            a.fixture_angle_deg = c.plant.fixture_angle_deg(c.axis == Axis::tilt);
        }
    }
    return r;
}

} // namespace parsons::relaylogic
