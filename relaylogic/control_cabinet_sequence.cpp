// Control cabinet 52, stops and the sequence: an axis stops from speed 3 (contact 238), the
// balancing circuit 266 checks the two comparers at the stop, each stop impulse steps shaft 280
// through circuit 276 and motor 278, and members 282 home past contact 290. A machine stop
// opens master switch 204 and lights its lamp.
#include "relaylogic/control_cabinet.hpp"

#include <fmt/format.h>

#include <algorithm>

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
    shaft_.impulse(now_, c.axis); // through contact 238, channel 274, circuit 276 to motor 278
    if (!shaft_.busy()) {
        shaft_.begin_step();
        schedule(now_ + profile_.sequence_shaft_step_s, EventKind::shaft_step);
    }
}

// "The latter [balancing circuit 266] is also connected by circuit 268 with the absolute and
// incremental comparers 122' and 122'' and the contact 238 at the "off" position of the speed
// switch contactor 236. If the absolute and incremental comparers are out of comparison, the
// resulting unbalance causes the vacuum tube circuit 266 to activate the error checking circuit
// and energize the electromagnet 265 and open the master switch" (col. 13). Contact 238 is
// closed whenever 236 stands on off: from zeroizing until the second bank steps the switch
// (the card being read), and from an axis's stop until zeroizing (docs/design-rules.md rule 6).
bool ControlCabinet::watch_balance(AxisCircuit& c, std::string_view when) {
    if (stop_ || !c.speed_switch.off() || c.absolute_conducting == c.incremental_conducting ||
        !balancing_.master_switch_closed()) {
        return false;
    }
    const bool absolute = c.absolute_conducting;
    balancing_.check_at_stop(absolute, c.incremental_conducting);
    c.tripped = true;
    c.show_lamps();
    machine_stop(StopReason::check_mismatch, c.axis,
                 fmt::format("{}, {}: {}, with speed switch 236 on off (contact 238), only the {} "
                             "conducted: absolute counter {} (stop {}), increment counter {} "
                             "(check {}); balancing circuit 266 opened master switch 204",
                             card_name(), axis_name(c.axis), when,
                             absolute ? "absolute comparer 122'" : "incremental comparer 122''",
                             inches(c.absolute_counter.value()), inches(c.order.stop),
                             inches(c.increment_counter.value()), inches(c.order.check)),
                 "");
    return true;
}

// Delay 258 holds channel 257 after the stop too. Its release drops relay 256 and the hold
// (trace signals), reads the comparers again and, if neither conducts, notes that the equality
// has left; none of it can act on the axis, which is not live (stopped) until channel 302, and
// on a later card a standing equality is that card's own evaluate's (it schedules its own
// release while 258 still holds 257). So with no observer to see the relays drop the
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
    evaluate_all();
}

// Members 282 home past contact 290: the zeroizing circuit, unless an attachment stops the
// machine or holds zeroizing (condition cards: an action not yet acknowledged, EP 0640901
// claim 2).
void ControlCabinet::shaft_home() {
    for (const auto& a : attachments_) {
        if (!a->zeroizing_may_start(*this)) {
            return;
        }
    }
    zeroize();
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
    info.lamps = panel_lamps();
    stop_ = info;
    if (record_times_ && !timings_.empty()) {
        timings_.back().end_s = now_;
    }
    queue_ = {};
    standing_queued_ = 0;
    unqueued_release_s_ = -axes::kNever;
    for (const auto& a : attachments_) {
        a->machine_stopped(*this); // e.g. the spindle's motor 27 runs down to rest
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

} // namespace parsons::relaylogic
