#include "relaylogic/control_cabinet.hpp"

#include "relaylogic/card_reader.hpp"
#include "relaylogic/fast_forward.hpp"

#include "axes/state_json.hpp"
#include "cardreader/deck_error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace parsons::relaylogic {

using cardreader::Axis;
using cardreader::axis_name;
using cardreader::format_inches;

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
    spindle_motor_signal_ = tracer_.define("cabinet", "spindle_motor",
                                           "spindle motor (0 at rest, 1 forward at speed, 2 "
                                           "reverse at speed, 3 running up, down or reversing)",
                                           "", 2);
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
        circuits_.back()->plant.measure_by(profile_.measuring_chain, // Fig. 3
                                           profile_.cam_160_on_instrument_shaft);
    }
    // The later systems the profile asks for (relaylogic/attachments.cpp), each defining its
    // signals after the cabinet's.
    attachments_ = make_attachments(tracer_, profile_);
    for (const auto& a : attachments_) {
        if (a->supplies_cards()) {
            supplier_ = a.get();
        }
        const Attachment::Hooks& hooks = a->hooks();
        auto keep = [&a](bool has, auto& list) {
            if (has) {
                list.push_back(a.get());
            }
        };
        keep(hooks.holding, holders_);
        keep(hooks.before_count, before_count_);
        keep(hooks.after_count, after_count_);
        keep(hooks.before_jump, before_jump_);
        keep(hooks.holds_axis, axis_holders_);
        keep(hooks.drive, drivers_);
        if (hooks.clock) {
            if (clock_ != nullptr) {
                throw std::logic_error("two attachments turn a clock; the cabinet turns one");
            }
            clock_ = a.get();
        }
        keep(hooks.plants, plants_);
        if (const CounterWatch* w = a->counter_watch()) {
            counter_watches_.push_back(w);
        }
    }
}

void ControlCabinet::attach(MachineObserver* observer) {
    tracer_.attach(observer);
}

void ControlCabinet::schedule(double t, EventKind kind, int axis) {
    queue_.push(Event{t, seq_++, kind, 0, false, axis, cards_read_});
}

void ControlCabinet::schedule(const Attachment& owner, double t, int code, bool standing) {
    std::size_t slot = 0;
    while (attachments_.at(slot).get() != &owner) {
        ++slot;
    }
    queue_.push(Event{t, seq_++, EventKind::attachment, static_cast<std::uint8_t>(slot), standing,
                      code, cards_read_});
    if (standing) {
        ++standing_queued_;
    }
}

void ControlCabinet::schedule_lasting(const Attachment& owner, double t, int code) {
    std::size_t slot = 0;
    while (attachments_.at(slot).get() != &owner) {
        ++slot;
    }
    Event e{t,    seq_++,     EventKind::attachment, static_cast<std::uint8_t>(slot), false,
            code, cards_read_};
    e.lasting = true;
    queue_.push(e);
}

std::string ControlCabinet::card_name() const {
    return orders_.number >= 0 && card_
               ? fmt::format("card {} (number {:04})", cards_read_, orders_.number)
               : fmt::format("card {}", cards_read_);
}

RunResult ControlCabinet::run(cardreader::CardSource& deck) {
    deck_ = &deck;
    apply_faults(deck);
    MachineObserver* observer = tracer_.observer();
    const bool deck_resumed =
        resuming_ && supplier_ != nullptr && supplier_->resume_deck(*this, *deck_);
    if (resuming_ && !deck_resumed) {
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
    // An observer that follows every change takes the impulses in bulk too where nothing but the
    // axes' own impulses can come between them: no attachment's plant or clock to report in
    // between (the spindle motor coming to speed is waited for).
    const bool recording = !jumping_ && observer != nullptr;
    follows_motion_ = observer != nullptr && observer->follows_motion();
    for (const auto& a : attachments_) {
        a->start(*this);
    }
    if (resuming_) {
        resume_holds();
    }
    if (follows_motion_) {
        observer->on_run_start(now_, real_positions(now_));
    }
    schedule(now_, EventKind::feed);
    while (true) {
        if (interrupted()) {
            continue; // the machine stops; the loop lets the axes coast to rest
        }
        mark(Phase::motion);
        if (jumping_) {
            plan_quiet_stretches();
        }
        const double t = next_event_time();
        if (t == axes::kNever) {
            if (!deck_finished_ && !stop_) {
                sequence_stall();
                continue;
            }
            break;
        }
        advance(t);
        while (!queue_.empty() && queue_.top().t <= t) {
            const Event e = queue_.top();
            queue_.pop();
            handle(e);
        }
        if (alone) {
            mark(Phase::motion);
            run_impulses<false>();
        } else if (recording && plants_.empty() && clock_ == nullptr && !spindle_changing_) {
            mark(Phase::motion);
            run_impulses<true>();
        }
    }
    mark(Phase::motion);
    for (const auto& c : circuits_) {
        c->plant.advance_to(now_);
    }
    for (Attachment* a : plants_) {
        a->advance_plants(*this, now_);
    }
    mark(Phase::report);
    report_faults();
    if (tracer_.observer() != nullptr) {
        tracer_.observer()->on_finish(now_);
    }
    return result();
}

// The next instant anything happens: a queued event, an axis's next event, the last release
// after a stop, or an attachment's clock; axes::kNever when nothing will.
inline double ControlCabinet::next_event_time() {
    while (standing_queued_ > 0 && !clock_running() && !queue_.empty() && queue_.top().standing) {
        queue_.pop(); // the deck is done: the clock's events end with it, taking no time
        --standing_queued_;
    }
    double t = queue_.empty() ? axes::kNever : queue_.top().t;
    for (std::size_t i = 0; i < circuits_.size(); ++i) {
        t = std::min(t, next_axis_event(i));
    }
    if (t == axes::kNever && unqueued_release_s_ > now_) {
        t = unqueued_release_s_; // the last release after a stop (release_after_stop)
    }
    if (spindle_changing_ && t != axes::kNever && spindle_motor_.ready_s() < t) {
        // The spindle motor comes to speed (or to rest): an instant of its own while the deck
        // goes on; it never keeps a finished run going.
        t = spindle_motor_.ready_s();
    }
    if (clock_running()) {
        // The press turns on whatever the cabinet does; when nothing else can happen and
        // nothing waits on it, the cabinet itself is idle (a sequence stall).
        if (idle()) {
            return axes::kNever;
        }
        t = std::min(t, jumping_ ? clock_quiet_end_ : clock_->next_clock_event(*this));
        if (unqueued_release_s_ > now_) {
            // The last release after a stop (release_after_stop) is an instant of its own
            // here too: a stall comes at it, whatever the clock's pace.
            t = std::min(t, unqueued_release_s_);
        }
    }
    return t;
}

// Machine time comes to t: the quiet impulses before it, the attachments' plants and clocks,
// then every axis's event due at t.
inline void ControlCabinet::advance(double t) {
    now_ = t;
    tracer_.set_time(t);
    if (jumping_) {
        // The axes' quiet impulses first: a tap's reversal of control 214 is reported at the
        // first impulse of its jump, before this instant, so it must come before anything
        // reported at this instant (the spindle's edges below).
        catch_up(t);
    }
    for (Attachment* a : plants_) {
        a->advance_plants(*this, t);
    }
    if (jumping_ && clock_running()) {
        // The clock's quiet edges before this instant, whatever the instant brings (at
        // impulse level each was an instant of its own).
        clock_->clock_edges_before(*this, t);
    }
    if (spindle_changing_ && spindle_motor_.ready_s() <= t) {
        // The spindle motor at speed (or at rest) is this instant's: whatever came before it
        // (an attachment's encoder edges, the clock's quiet edges) is reported first.
        show_spindle();
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
    if (clock_running()) {
        clock_->clock_edges_at(*this, t);
    }
    if (moved && follows_motion_) {
        report_motion(t);
    }
}

std::array<double, 5> ControlCabinet::real_positions(double t) const {
    std::array<double, 5> real{};
    for (std::size_t i = 0; i < circuits_.size(); ++i) {
        real.at(i) = circuits_[i]->plant.real_in_at(t);
    }
    return real;
}

void ControlCabinet::report_motion(double t) {
    tracer_.observer()->on_motion(t, real_positions(t));
}

// The phase of the card cycle an event belongs to, for the benchmark's clock.
Phase ControlCabinet::phase_of(EventKind kind) {
    switch (kind) {
    case EventKind::feed:
    case EventKind::first_bank:
    case EventKind::relays_pick:
    case EventKind::second_bank:
    case EventKind::speed_step_252:
    case EventKind::read_complete:
        return Phase::reader_relays;
    case EventKind::delay_258_release:
        return Phase::motion;
    case EventKind::shaft_step:
        return Phase::sequence;
    case EventKind::attachment:
        return Phase::attachments;
    }
    return Phase::motion;
}

void ControlCabinet::handle(const Event& e) {
    if (stop_ && e.kind != EventKind::feed) {
        return; // master switch open: the cabinet is dead
    }
    if (e.kind == EventKind::attachment && e.standing) {
        mark(Phase::attachments);
        --standing_queued_;
        attachments_.at(e.owner)->on_event(*this, e.axis); // on whatever card is in the reader
        return;
    }
    if (e.kind == EventKind::attachment && e.lasting) {
        mark(Phase::attachments);
        attachments_.at(e.owner)->on_event(*this, e.axis); // whatever card is in the reader
        return;
    }
    if (e.kind == EventKind::delay_258_release && e.card != cards_read_) {
        // Delay 258's hold after a stop runs out on a later card: zeroizing does not touch it.
        // It drops relay 256; what the new card's comparers do is that card's own event's.
        circuits_.at(static_cast<std::size_t>(e.axis))->speed_switch.hold_expired(now_);
        return;
    }
    if (e.kind != EventKind::feed && e.card != cards_read_) {
        return; // an action of a card the zeroizing circuit has already cleared
    }
    mark(phase_of(e.kind));
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
        second_bank();
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
    case EventKind::attachment:
        attachments_.at(e.owner)->on_event(*this, e.axis);
        break;
    }
}

// Nothing can happen but the clock turning and its standing events: no axis moves, no other
// event is queued, and nothing waits on the clock.
bool ControlCabinet::idle() const {
    if (queue_.size() != static_cast<std::size_t>(standing_queued_) || unqueued_release_s_ > now_) {
        return false;
    }
    for (std::size_t i = 0; i < circuits_.size(); ++i) {
        if (next_axis_event(i) != axes::kNever) {
            return false;
        }
    }
    return clock_ == nullptr || !clock_->waited_on(*this);
}

// A saved machine keeps no queue: a delay 258 still holding after its axis's stop (it outlasts
// zeroizing, release_after_stop) is queued again as it was, before anything scheduled since
// the save (its sequence number is the axis's place, below every later one; seq_ does not
// move: the stop took its number already), or noted as the last unqueued release.
void ControlCabinet::resume_holds() {
    for (std::size_t i = 0; i < circuits_.size(); ++i) {
        const SpeedSwitch& s = circuits_[i]->speed_switch;
        if (!s.held() || s.hold_until() <= now_) {
            continue;
        }
        if (tracer_.observer() != nullptr) {
            queue_.push(Event{s.hold_until(), i, EventKind::delay_258_release, 0, false,
                              static_cast<int>(i), -1});
        } else {
            unqueued_release_s_ = std::max(unqueued_release_s_, s.hold_until());
        }
    }
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

} // namespace parsons::relaylogic
