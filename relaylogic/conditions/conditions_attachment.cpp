// Condition cards (an addition after EP 0640901, Siemens) on the card cycle of control cabinet
// 52: converter UMS, buffer PFR, monitoring unit PRG and tripping unit ALE. Not in the 1952
// patent.
#include "relaylogic/conditions/conditions_attachment.hpp"

#include "relaylogic/control_cabinet.hpp"

#include "axes/state_json.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace parsons::relaylogic {

using cardreader::axis_name;
using cardreader::format_inches;

ConditionsAttachment::ConditionsAttachment(Tracer& tracer, const axes::MachineProfile& profile) {
    units_.install(tracer, profile);
}

// A condition card with no motion card after it: the deck ends.
void ConditionsAttachment::deck_ended(ControlCabinet& cab) {
    const int waiting = units_.first_waiting();
    if (waiting < 0) {
        return; // every-conditions standing after their motion cards end with the deck
    }
    const BufferPair& p = units_.buffer().pair(waiting);
    cab.machine_stop(StopReason::condition_refused, std::nullopt,
                     fmt::format("card {} (number {:04}): a condition card with no motion card "
                                 "after it: the deck ends (condition cards stand before the "
                                 "motion card they watch, EP 0640901 claim 4)",
                                 p.card, p.card_number),
                     "condition lamp (an addition)");
}

// A condition card: no axis moves; converter UMS enters its records into buffer PFR, and at
// the end of the card cycle channel 304 indexes the next card.
void ConditionsAttachment::read_card(ControlCabinet& cab) {
    used_ = true;
    if (auto refusal = units_.convert(cab.orders(), cab.cards_read())) {
        cab.machine_stop(StopReason::condition_refused, std::nullopt, *refusal,
                         "condition lamp (an addition)");
    }
}

void ConditionsAttachment::check_motion_card(ControlCabinet& cab) {
    units_.enter_motion(cab.orders().number); // converter UMS: the motion statement into PFR
    if (auto refusal = units_.refuse_unmoved(cab.orders(), cab.cards_read())) {
        cab.machine_stop(StopReason::condition_refused, std::nullopt, *refusal,
                         "condition lamp (an addition)");
    }
}

// One spindle motor: the actions spindle-forward, -reverse and -stop drive the motor column 1
// commands, so its time and the cabinet's signal cabinet.spindle_motor follow them too.
void ConditionsAttachment::start(ControlCabinet& cab) {
    units_.drive_spindle(cab.spindle_motor());
}

void ConditionsAttachment::relays_picked(ControlCabinet& cab) {
    units_.spindle_from_card(cab.orders().spindle, cab.now());
    units_.arm(cab.cards_read()); // PFR supplies each stored condition to PRG
}

// Monitoring unit PRG: the axis's counter stepped; each channel whose circuit closed reports its
// identifier, and tripping unit ALE initiates that channel's action (EP 0640901 claim 1).
bool ConditionsAttachment::after_count(ControlCabinet& cab, AxisCircuit& c) {
    if (!units_.watching(c.axis)) {
        return false;
    }
    const unsigned met = units_.on_counter_step(c.axis, c.absolute_counter.digits(), c.direction);
    for (int k = 0; k < InternalBuffer::kChannels; ++k) {
        if ((met >> k & 1U) == 0) {
            continue;
        }
        if (units_.ale().refuses_now(units_.buffer().pair(k).action)) {
            interlock(cab, k);
            return true;
        }
        const double done = units_.trip(k, cab.now());
        cab.show_spindle(); // a spindle action changes the one motor
        tell(cab, k, ConditionEventKind::met);
        tell(cab, k, ConditionEventKind::action_started);
        cab.schedule(*this, done, k); // the acknowledgement, when the action is done
        dwell_follows(cab, k);
    }
    return met != 0;
}

// A tool change tripped while the spindle motor is commanded to turn. The seed's tool change is
// made while the tool travels to the change position (claims 5 and 6), not while it cuts, and a
// changer cannot take a turning cutter: the machine stops before the changer moves, naming the
// condition card's action column and the column 1 that turns the spindle.
void ConditionsAttachment::interlock(ControlCabinet& cab, int channel) {
    const BufferPair& p = units_.buffer().pair(channel);
    const bool by_card = cab.orders().spindle != cardreader::Spindle::off;
    cab.machine_stop(
        StopReason::tool_change_interlock, std::nullopt,
        fmt::format("{}: event {} (card {}, column {}: tool change to tool {}) tripped as the {} "
                    "axis passed {}, but the spindle is commanded to turn ({}): the tool changer "
                    "takes no turning cutter, so it does not start and the machine stops (order "
                    "the spindle off, column 1 blank, on the card that takes the tool to the "
                    "change position; condition cards are an addition after EP 0640901, claims 5 "
                    "and 6)",
                    cab.card_name(), p.condition.event, p.card, slot_column(p, 8),
                    p.action.parameter, axis_name(p.condition.axis),
                    format_inches(p.condition.position),
                    by_card ? fmt::format("column 1 of card {} orders it {}", cab.cards_read(),
                                          cardreader::spindle_name(cab.orders().spindle))
                            : std::string("a spindle action of a condition card started it")),
        "tool changer interlock lamp (an addition)");
}

void ConditionsAttachment::on_event(ControlCabinet& cab, int channel) {
    acknowledge(cab, channel);
}

void ConditionsAttachment::acknowledge(ControlCabinet& cab, int channel) {
    units_.acknowledge(channel, cab.now());
    tell(cab, channel, ConditionEventKind::acknowledged);
    dwell_follows(cab, channel);
    if (zeroize_waiting_ && units_.all_acknowledged()) {
        zeroize_waiting_ = false;
        units_.set_waiting(false);
        cab.zeroize(); // claim 2: every action acknowledged, the next card may be processed
    }
}

// A dwell holds (or frees) its axis's motor circuit.
void ConditionsAttachment::dwell_follows(ControlCabinet& cab, int channel) {
    const ActionEntry& a = units_.buffer().pair(channel).action;
    if (a.action == cardreader::ActionKind::dwell) {
        cab.update_motor(*cab.circuits().at(static_cast<std::size_t>(a.parameter - 1)));
    }
}

void ConditionsAttachment::tell(ControlCabinet& cab, int channel, ConditionEventKind kind) {
    if (cab.observer() != nullptr) {
        cab.observer()->on_condition(
            cab.now(), units_.event(channel, kind, cab.cards_read(), cab.orders().number));
    }
}

// Members 282 came home. A condition still armed was never met on this card: the machine
// stops; and the zeroizing circuit waits until tripping unit ALE has every action
// acknowledged (EP 0640901 claim 2).
bool ConditionsAttachment::zeroizing_may_start(ControlCabinet& cab) {
    const int unmet = units_.first_unmet();
    if (unmet >= 0) {
        const BufferPair& p = units_.buffer().pair(unmet);
        const AxisCircuit& c = cab.circuit(p.condition.axis);
        const int reads = c.absolute_counter.value();
        cab.machine_stop(
            StopReason::condition_not_met, p.condition.axis,
            fmt::format("{}: event {} (condition card {}) was not met: the {} axis "
                        "never passed {} {} before the card's last axis stopped (its "
                        "counter reads {}; condition cards are an addition after "
                        "EP 0640901, Siemens)",
                        cab.card_name(), p.condition.event, p.card, axis_name(p.condition.axis),
                        format_inches(p.condition.position),
                        p.condition.sense == cardreader::PassingSense::either
                            ? std::string("in either sense")
                            : fmt::format("counting {}",
                                          p.condition.sense == cardreader::PassingSense::forward
                                              ? "up (forward)"
                                              : "down (reverse)"),
                        format_inches(static_cast<cardreader::Thousandths>(
                            ((reads % 10000) + 10000) % 10000))),
            "condition lamp (monitoring unit PRG; an addition)");
        return false;
    }
    if (!units_.all_acknowledged()) {
        zeroize_waiting_ = true;
        units_.set_waiting(true);
        return false;
    }
    return true;
}

void ConditionsAttachment::zeroized(ControlCabinet& cab) {
    const std::size_t first = actions_.size();
    for (int k = 0; k < InternalBuffer::kChannels; ++k) {
        const BufferPair& p = units_.buffer().pair(k);
        if (p.state == PairState::acknowledged) {
            actions_.push_back(ActionRecord{
                p.condition.event, p.card, cab.cards_read(), cab.orders().number, p.condition.axis,
                p.condition.position, p.action.action, p.action.parameter, p.tripped_s,
                p.acknowledged_s, cab.motion_end_s(), p.every, p.every ? p.firings + 1 : 0});
        }
    }
    // The card's actions in the order they were tripped (channel order at one instant).
    std::stable_sort(
        actions_.begin() + static_cast<std::ptrdiff_t>(first), actions_.end(),
        [](const ActionRecord& a, const ActionRecord& b) { return a.tripped_s < b.tripped_s; });
    units_.zeroize(); // channel 294 clears PFR and PRG too
}

void ConditionsAttachment::save(const ControlCabinet& /*cab*/, nlohmann::json& state) const {
    state["conditions"] = units_.save();
    state["conditions"]["used"] = used_;
    state["actions"] = actions_to_json(actions_);
}

void ConditionsAttachment::load(ControlCabinet& /*cab*/, const nlohmann::json& state) {
    const nlohmann::json& j =
        state.contains("conditions") ? state.at("conditions") : nlohmann::json();
    units_.load(j);
    // A state saved before the report knew whether the deck used it: shown, as it was then.
    used_ = j.is_null() || !j.contains("used") || axes::read<bool>(j, "used");
    actions_ = actions_from_json(state.contains("actions") ? state.at("actions")
                                                           : nlohmann::json::array());
}

void ConditionsAttachment::add_to(RunResult& result) const {
    result.conditions_used = used_;
    result.actions = actions_;
    result.tool_in_spindle = units_.ale().tool_in_spindle();
}

} // namespace parsons::relaylogic
