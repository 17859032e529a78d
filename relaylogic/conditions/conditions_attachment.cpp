// Control cabinet 52 with the condition cards of EP 0640901 (Siemens): converter UMS, buffer
// PFR, monitoring unit PRG and tripping unit ALE on the card cycle. An addition, not in the
// 1952 patent.
#include "relaylogic/control_cabinet.hpp"

#include <fmt/format.h>

namespace parsons::relaylogic {

using cardreader::Axis;

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

} // namespace parsons::relaylogic
