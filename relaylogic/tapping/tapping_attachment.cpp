// Control cabinet 52 with the spindle synchronisation of EP 0360190 (Mitsubishi): a
// tap card's cycle, from the tool call on bus 35 to the feed standing on its starting count
// again (relaylogic/tapping/tapping_units.hpp tells the sequence). An addition, not in the 1952 patent.
#include "relaylogic/control_cabinet.hpp"

#include <fmt/format.h>

namespace parsons::relaylogic {

using cardreader::Axis;

// Encoder 32's edges due by time t: in fast-forward in one jump a segment, at impulse level one
// by one. Nothing but interface 33 reads them, and it is read at the scans and samples only.
void ControlCabinet::spindle_edges(double t) {
    if (jumping_) {
        tapping_.jump_to(t);
    } else {
        tapping_.catch_up(t);
    }
}

// During a tap the counters of the feed axis count the way the drive turns: the NC sets
// reversing control 214 from the drive's sense (an addition; the 1952 motion column sets it
// once a card).
void ControlCabinet::tap_counting_sense(AxisCircuit& c, int direction) {
    if (c.direction != direction) {
        c.set_direction(direction > 0 ? cardreader::Motion::forward : cardreader::Motion::reverse);
    }
}

// A tap card (an addition after EP 0360190): no axis moves by the 1952 columns; at the end of
// its reading the tool call goes on bus 35.
void ControlCabinet::tap_card() {
    tap_card_ = true;
    if (!tapping_.present()) {
        machine_stop(StopReason::tap_refused, std::nullopt,
                     fmt::format("{}, column {}: a tap card (an addition after EP 0360190, "
                                 "Mitsubishi): profile {} has no spindle synchronisation; the "
                                 "built-in profile parsons-extended has it",
                                 card_name(), layout_.extension_column, profile_.name),
                     "card reader 134 check lamp (an addition)");
        return;
    }
    if (auto refusal = tapping_.refusal(orders_.tap, profile_)) {
        machine_stop(StopReason::tap_refused, orders_.tap.axis,
                     fmt::format("{}: {} (tap cards are an addition after EP 0360190, "
                                 "Mitsubishi)",
                                 card_name(), *refusal),
                     "spindle lamp (an addition)");
    }
}

void ControlCabinet::start_tool_call() {
    tapping_.open_hole(cards_read_, orders_.number, orders_.tap.tool);
    tapping_.begin(orders_.tap, now_);
    pc_scan();
}

// A scan of PC 130 and of the NC's side of the handshake.
void ControlCabinet::pc_scan() {
    if (tapping_.scan(now_)) {
        AxisCircuit& c = *circuits_.at(cardreader::axis_index(orders_.tap.axis));
        if (auto impulse = c.plant.advance_to(now_)) {
            on_impulse(c, *impulse);
        }
        tapping_.start(now_, c.absolute_counter.value(), c.plant.real_in());
        update_motor(c);
        schedule(now_ + profile_.spindle.sample_s, EventKind::spindle_sample);
        return;
    }
    if (tapping_.timed_out()) {
        const GearRatioMemory& m = tapping_.memory();
        machine_stop(StopReason::transfer_timeout, std::nullopt,
                     fmt::format("{}: PC 130 asked to transfer the gear ratio of tool {} at "
                                 "{:.2f} s and the NC answered ready, but the ratio never reached "
                                 "gear ratio data memory 12a; the NC gave up after "
                                 "transfer_timeout_s {:.1f} s (12a still holds {:.4f}; spindle "
                                 "synchronisation is an addition after EP 0360190, Mitsubishi)",
                                 card_name(), orders_.tap.tool, m.request_since_s(),
                                 profile_.spindle.transfer_timeout_s, m.ratio()),
                     "spindle lamp (an addition)");
        return;
    }
    schedule(now_ + profile_.spindle.pc_scan_s, EventKind::pc_scan);
}

// A sample of interface 33: the synchronous operation control sets the feed.
void ControlCabinet::spindle_sample() {
    AxisCircuit& c = *circuits_.at(cardreader::axis_index(orders_.tap.axis));
    if (auto impulse = c.plant.advance_to(now_)) {
        on_impulse(c, *impulse);
        if (stop_) {
            return;
        }
    }
    const bool done =
        tapping_.sample(now_, c.absolute_counter.value(), c.plant.real_in(), c.plant.at_rest());
    update_motor(c);
    if (!done) {
        schedule(now_ + profile_.spindle.sample_s, EventKind::spindle_sample);
        return;
    }
    c.set_powered(false);
    motion_end_s_ = now_;
    zeroize(); // the card's cycle ends: channel 304 indexes the next card
}

} // namespace parsons::relaylogic
