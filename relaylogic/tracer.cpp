#include "relaylogic/tracer.hpp"

namespace parsons::relaylogic {

std::string_view stop_reason_name(StopReason r) {
    switch (r) {
    case StopReason::out_of_order_card:
        return "out_of_order_card";
    case StopReason::check_mismatch:
        return "check_mismatch";
    case StopReason::missed_impulse:
        return "missed_impulse";
    case StopReason::sequence_stall:
        return "sequence_stall";
    case StopReason::bad_punch:
        return "bad_punch";
    case StopReason::soft_limit:
        return "soft_limit";
    case StopReason::limit_switch:
        return "limit_switch";
    case StopReason::condition_not_met:
        return "condition_not_met";
    case StopReason::condition_refused:
        return "condition_refused";
    case StopReason::tool_change_interlock:
        return "tool_change_interlock";
    case StopReason::sync_timeout:
        return "sync_timeout";
    case StopReason::sync_refused:
        return "sync_refused";
    case StopReason::transfer_timeout:
        return "transfer_timeout";
    case StopReason::tap_refused:
        return "tap_refused";
    case StopReason::segment_refused:
        return "segment_refused";
    case StopReason::interrupted:
        return "interrupted";
    }
    return "check_mismatch";
}

std::string_view condition_event_name(ConditionEventKind k) {
    switch (k) {
    case ConditionEventKind::met:
        return "condition_met";
    case ConditionEventKind::action_started:
        return "action_started";
    case ConditionEventKind::acknowledged:
        return "action_acknowledged";
    }
    return "condition_met";
}

SignalId Tracer::define(std::string scope, std::string name, std::string component,
                        std::string numeral, int width, std::uint32_t initial) {
    SignalInfo info;
    info.id = static_cast<SignalId>(infos_.size());
    info.scope = std::move(scope);
    info.name = std::move(name);
    info.component = std::move(component);
    info.numeral = std::move(numeral);
    info.width = width;
    infos_.push_back(std::move(info));
    values_.push_back(initial);
    return infos_.back().id;
}

void Tracer::attach(MachineObserver* observer) {
    observer_ = observer;
    log_ = observer != nullptr ? observer->change_log() : nullptr;
    if (observer_ == nullptr) {
        return;
    }
    for (const SignalInfo& info : infos_) {
        observer_->on_signal_defined(info, values_.at(info.id));
    }
    observer_->on_start();
}

void Tracer::report(SignalId id, std::uint32_t value) {
    std::uint32_t& old = values_.at(id);
    if (log_ != nullptr) {
        old = value;
        log_->append(now_, id, value);
        return;
    }
    observer_->on_signal(now_, id, old, value);
    old = value;
}

} // namespace parsons::relaylogic
