// Spindle synchronisation (an addition after EP 0360190, Mitsubishi) on the card cycle of
// control cabinet 52: a tap card's cycle, from the tool call on bus 35 to the feed standing on
// its starting count again (relaylogic/tapping/tapping_units.hpp tells the sequence). Not in
// the 1952 patent.
#include "relaylogic/tapping/tapping_attachment.hpp"

#include "relaylogic/control_cabinet.hpp"

#include "axes/state_json.hpp"

#include <fmt/format.h>

namespace parsons::relaylogic {

TappingAttachment::TappingAttachment(Tracer& tracer, const axes::MachineProfile& profile) {
    units_.install(tracer, profile);
}

void TappingAttachment::start(ControlCabinet& cab) {
    units_.inject(cab.faults()); // --fault stale-ratio, transfer-hang: PC 130's
    units_.keep_samples(cab.keeps_tap_samples());
}

// Encoder 32's edges due by time t: in fast-forward in one jump a segment, at impulse level one
// by one. Nothing but interface 33 reads them, and it is read at the scans and samples only.
void TappingAttachment::advance_plants(ControlCabinet& cab, double t) {
    if (cab.jumping()) {
        units_.jump_to(t);
    } else {
        units_.catch_up(t);
    }
}

// During a tap the counters of the feed axis count the way the drive turns: the NC sets
// reversing control 214 from the drive's sense (an addition; the 1952 motion column sets it
// once a card).
void TappingAttachment::counting_sense(AxisCircuit& c, int direction) {
    if (c.direction != direction) {
        c.set_direction(direction > 0 ? cardreader::Motion::forward : cardreader::Motion::reverse);
    }
}

void TappingAttachment::before_count(ControlCabinet& cab, AxisCircuit& c, int direction) {
    if (units_.feeding(c.axis) && !cab.stopped()) {
        counting_sense(c, direction);
    }
}

// Fast-forward: reversing control 214 follows the drive at the first impulse of the jump.
void TappingAttachment::before_jump(ControlCabinet& cab, AxisCircuit& c, double t) {
    if (units_.feeding(c.axis) && c.direction != c.plant.moving_direction()) {
        cab.tracer().set_time(c.plant.impulse_time(1));
        counting_sense(c, c.plant.moving_direction());
        cab.tracer().set_time(t);
    }
}

// A tap: the synchronous operation control sets the follower drive.
bool TappingAttachment::drive(ControlCabinet& cab, AxisCircuit& c, bool /*on*/) {
    if (!units_.feeding(c.axis) || cab.stopped()) {
        return false;
    }
    const FeedCommand f = units_.feed();
    c.plant.command_follow(f.direction, f.speed_in_per_s,
                           cab.profile().sync_drive.acceleration_in_per_s2);
    c.set_powered(true);
    return true;
}

void TappingAttachment::machine_stopped(ControlCabinet& cab) {
    advance_plants(cab, cab.now());
    units_.halt(); // motor 27 runs down to rest; the feed is the 1952 motor's again
}

// A tap card: no axis moves by the 1952 columns; at the end of its reading the tool call goes
// on bus 35.
void TappingAttachment::read_card(ControlCabinet& cab) {
    used_ = true;
    const cardreader::CardOrders& orders = cab.orders();
    if (auto refusal = units_.refusal(orders.tap, cab.profile())) {
        cab.machine_stop(StopReason::tap_refused, orders.tap.axis,
                         fmt::format("{}: {} (tap cards are an addition after EP 0360190, "
                                     "Mitsubishi)",
                                     cab.card_name(), *refusal),
                         "spindle lamp (an addition)");
    }
}

// The end of the tap card's reading: the tool call. The attachment ends the card (zeroizing).
bool TappingAttachment::card_read(ControlCabinet& cab) {
    const cardreader::CardOrders& orders = cab.orders();
    units_.open_hole(cab.cards_read(), orders.number, orders.tap.tool);
    units_.begin(orders.tap, cab.now());
    pc_scan(cab);
    return false;
}

void TappingAttachment::on_event(ControlCabinet& cab, int code) {
    if (code == pc_scan_event) {
        pc_scan(cab);
    } else if (code == reversal_event) {
        advance_plants(cab, cab.now());
        units_.reverse(cab.now());
    } else {
        spindle_sample(cab);
    }
}

// A scan of PC 130 and of the NC's side of the handshake.
void TappingAttachment::pc_scan(ControlCabinet& cab) {
    const axes::MachineProfile& profile = cab.profile();
    const cardreader::TapOrder& tap = cab.orders().tap;
    if (units_.scan(cab.now())) {
        AxisCircuit& c = cab.circuit(tap.axis);
        cab.count_due_impulse(c);
        units_.start(cab.now(), c.absolute_counter.value(), c.plant.real_in());
        cab.update_motor(c);
        cab.schedule(*this, cab.now() + profile.spindle.sample_s, spindle_sample_event);
        return;
    }
    if (units_.timed_out()) {
        const GearRatioMemory& m = units_.memory();
        cab.machine_stop(StopReason::transfer_timeout, std::nullopt,
                         fmt::format("{}: PC 130 asked to transfer the gear ratio of tool {} at "
                                     "{:.2f} s and the NC answered ready, but the ratio never "
                                     "reached gear ratio data memory 12a; the NC gave up after "
                                     "transfer_timeout_s {:.1f} s (12a still holds {:.4f}; "
                                     "spindle synchronisation is an addition after EP 0360190, "
                                     "Mitsubishi)",
                                     cab.card_name(), tap.tool, m.request_since_s(),
                                     profile.spindle.transfer_timeout_s, m.ratio()),
                         "spindle lamp (an addition)");
        return;
    }
    cab.schedule(*this, cab.now() + profile.spindle.pc_scan_s, pc_scan_event);
}

// A sample of interface 33: the synchronous operation control sets the feed.
void TappingAttachment::spindle_sample(ControlCabinet& cab) {
    AxisCircuit& c = cab.circuit(cab.orders().tap.axis);
    if (cab.count_due_impulse(c) && cab.stopped()) {
        return;
    }
    const bool done =
        units_.sample(cab.now(), c.absolute_counter.value(), c.plant.real_in(), c.plant.at_rest());
    if (const auto at = units_.take_reversal()) {
        cab.schedule(*this, *at, reversal_event);
    }
    cab.update_motor(c);
    if (!done) {
        cab.schedule(*this, cab.now() + cab.profile().spindle.sample_s, spindle_sample_event);
        return;
    }
    c.set_powered(false);
    cab.motion_ended();
    cab.zeroize(); // the card's cycle ends: channel 304 indexes the next card
}

void TappingAttachment::save(const ControlCabinet& /*cab*/, nlohmann::json& state) const {
    state["tapping"] = units_.save();
    state["tapping"]["used"] = used_;
}

void TappingAttachment::load(ControlCabinet& /*cab*/, const nlohmann::json& state) {
    if (!state.contains("tapping") || state.at("tapping").is_null()) {
        throw axes::StateError("this profile has spindle synchronisation and the saved state "
                               "has none");
    }
    const nlohmann::json& j = state.at("tapping");
    units_.load(j);
    // A state saved before the report knew whether the deck used it: shown, as it was then.
    used_ = !j.contains("used") || axes::read<bool>(j, "used");
}

void TappingAttachment::add_to(RunResult& result) const {
    TappingResult tr;
    tr.used = used_;
    tr.tool_on_spindle = units_.spindle().tool();
    tr.ratio_in_memory = units_.memory().ratio();
    tr.head_exchanges = units_.pc().exchanges();
    tr.transfers = units_.pc().transfers();
    tr.ratios_received = units_.memory().received();
    tr.holes = units_.holes();
    tr.encoder_pulses_per_rev = units_.profile().spindle.encoder_pulses_per_rev;
    result.tapping = std::move(tr);
}

} // namespace parsons::relaylogic

namespace parsons::relaylogic {

// PC 130's faults came into play when their exchange or transfer came: stale-ratio:N when head
// exchange N was made (and S2 answered that no ratio need change, so none was transferred),
// transfer-hang:N when transfer N began. The holes the effect names are those the thread proof
// judges by the same fact: tapped with a ratio in memory 12a that is not their head's.
void TappingAttachment::fault_effect(const ControlCabinet& cab, const Fault& f,
                                     FaultEffect& e) const {
    const ProgrammableController& pc = units_.pc();
    if (f.kind == FaultKind::stale_ratio &&
        cab.profile().spindle.ratio_source == axes::RatioSource::transferred &&
        pc.exchanges() >= f.n) {
        std::string cards;
        int stale = 0;
        for (const HoleRecord& h : units_.holes()) {
            if (h.tool != 0 && h.ratio_used != h.head_ratio) {
                cards += fmt::format("{}{:04}", stale++ == 0 ? "" : ", ", h.number);
            }
        }
        e.acted = true;
        e.effect =
            stale == 0
                ? fmt::format("head exchange {} transferred no gear ratio to memory 12a; no hole "
                              "was tapped with the stale ratio",
                              f.n)
                : fmt::format("head exchange {} transferred no gear ratio to memory 12a: {} "
                              "hole{} tapped with a ratio not its head's (card{} {})",
                              f.n, stale, stale == 1 ? "" : "s", stale == 1 ? "" : "s", cards);
    } else if (f.kind == FaultKind::transfer_hang && pc.transfers() >= f.n) {
        e.acted = true;
        e.effect =
            fmt::format("gear ratio transfer {} never completed: the ratio never reached "
                        "memory 12a{}",
                        f.n,
                        cab.stop_info() && cab.stop_info()->reason == StopReason::transfer_timeout
                            ? ", and the NC stopped the machine (transfer_timeout)"
                            : "");
    }
}

} // namespace parsons::relaylogic
