#include "relaylogic/conditions/condition_units.hpp"

#include "axes/state_json.hpp"

#include <fmt/format.h>

namespace parsons::relaylogic {

nlohmann::json actions_to_json(const std::vector<ActionRecord>& actions) {
    using axes::exact;
    nlohmann::json list = nlohmann::json::array();
    for (const ActionRecord& a : actions) {
        list.push_back({a.event, a.condition_card, a.motion_card, a.motion_card_number,
                        static_cast<int>(a.axis), a.position, static_cast<int>(a.action),
                        a.parameter, exact(a.tripped_s), exact(a.acknowledged_s),
                        exact(a.motion_end_s)});
        if (a.every) { // an every-condition's firing: two more values
            list.back().push_back(true);
            list.back().push_back(a.firing);
        }
    }
    return list;
}

std::vector<ActionRecord> actions_from_json(const nlohmann::json& j) {
    using axes::exact;
    std::vector<ActionRecord> out;
    if (!j.is_array()) {
        throw axes::StateError("actions: expected an array");
    }
    for (const auto& e : j) {
        if (!e.is_array() || (e.size() != 11 && e.size() != 13)) {
            throw axes::StateError(
                "actions: each record has 11 values (13 for an every-condition)");
        }
        const int axis = e.at(4).get<int>();
        const int action = e.at(6).get<int>();
        if (axis < 0 || axis >= cardreader::kAxisCount || action < 1 ||
            action > cardreader::kActionKinds) {
            throw axes::StateError("actions: a value out of range");
        }
        out.push_back(ActionRecord{
            e.at(0).get<int>(), e.at(1).get<std::int64_t>(), e.at(2).get<std::int64_t>(),
            e.at(3).get<int>(), static_cast<cardreader::Axis>(axis),
            e.at(5).get<cardreader::Thousandths>(), static_cast<cardreader::ActionKind>(action),
            e.at(7).get<int>(), exact(e.at(8)), exact(e.at(9)), exact(e.at(10))});
        if (e.size() == 13) {
            out.back().every = e.at(11).get<bool>();
            out.back().firing = e.at(12).get<int>();
        }
    }
    return out;
}

void ConditionUnits::install(Tracer& tracer, const axes::MachineProfile& profile) {
    if (!profile.condition_cards) {
        return;
    }
    tracer_ = &tracer;
    buffer_ = std::make_unique<InternalBuffer>(tracer);
    prg_ = std::make_unique<MonitoringUnit>(tracer);
    ale_ = std::make_unique<TrippingUnit>(tracer, profile);
    waiting_ = tracer.define("conditions", "tripping_ale.waiting",
                             "tripping unit ALE holds the zeroizing circuit: an action of this "
                             "card is not yet acknowledged (EP 0640901 claim 2)",
                             "ALE", 1);
}

void ConditionUnits::set_waiting(bool waiting) {
    if (tracer_ != nullptr) {
        tracer_->set(waiting_, waiting ? 1 : 0);
    }
}

std::optional<std::string> ConditionUnits::convert(const cardreader::CardOrders& card,
                                                   std::int64_t index) {
    return convert_condition_card(card, index, *buffer_);
}

std::optional<std::string> ConditionUnits::refuse_unmoved(const cardreader::CardOrders& motion,
                                                          std::int64_t index) const {
    if (!buffer_) {
        return std::nullopt;
    }
    for (int k = 0; k < InternalBuffer::kChannels; ++k) {
        const BufferPair& p = buffer_->pair(k);
        // An every-condition need not be met on every card, so a card that leaves its axis
        // standing is no error for it.
        if (p.state == PairState::stored && !p.every && motion.axis(p.condition.axis).check == 0) {
            return fmt::format("card {}: event {} of condition card {} watches the {} axis, which "
                               "this motion card does not move (check 0.000): the condition "
                               "could never be met (condition cards are an addition after "
                               "EP 0640901, Siemens)",
                               index, p.condition.event, p.card,
                               cardreader::axis_name(p.condition.axis));
        }
    }
    return std::nullopt;
}

void ConditionUnits::arm(std::int64_t motion_card) {
    buffer_->set_motion(MotionEntry::supplied, buffer_->motion_card_number());
    for (int k = 0; k < InternalBuffer::kChannels; ++k) {
        BufferPair& p = buffer_->pair(k);
        if (p.state == PairState::stored) {
            p.motion_card = motion_card;
            prg_->arm(k, p.condition);
            buffer_->set_state(k, PairState::armed);
        }
    }
}

double ConditionUnits::trip(int k, double t) {
    BufferPair& p = buffer_->pair(k);
    prg_->report(p.condition.event);
    prg_->disarm(k);
    p.tripped_s = t;
    buffer_->set_state(k, PairState::tripped);
    return ale_->initiate(k, p.action, t);
}

void ConditionUnits::acknowledge(int k, double t) {
    BufferPair& p = buffer_->pair(k);
    p.acknowledged_s = t;
    ale_->acknowledge(k, p.action);
    buffer_->set_state(k, PairState::acknowledged);
}

int ConditionUnits::first_unmet() const {
    for (int k = 0; buffer_ && k < InternalBuffer::kChannels; ++k) {
        if (buffer_->pair(k).state == PairState::armed && !buffer_->pair(k).every) {
            return k;
        }
    }
    return -1;
}

int ConditionUnits::first_waiting() const {
    for (int k = 0; buffer_ && k < InternalBuffer::kChannels; ++k) {
        const BufferPair& p = buffer_->pair(k);
        if (p.state == PairState::stored && (!p.every || p.motion_card == 0)) {
            return k;
        }
    }
    return -1;
}

void ConditionUnits::zeroize() {
    if (!buffer_) {
        return;
    }
    // Pairs still stored belong to a motion card not yet read (none: conditions stand right
    // before their card), so zeroizing clears the armed and acknowledged ones.
    for (int k = 0; k < InternalBuffer::kChannels; ++k) {
        BufferPair& p = buffer_->pair(k);
        if (p.state == PairState::stored || p.state == PairState::empty) {
            continue;
        }
        if (p.every) { // stays: stored again for the next motion card, met or not on this one
            p.firings += p.state == PairState::acknowledged ? 1 : 0;
            p.tripped_s = -1;
            p.acknowledged_s = -1;
            buffer_->set_state(k, PairState::stored);
            continue;
        }
        buffer_->set_state(k, PairState::empty);
        p = BufferPair{};
    }
    buffer_->set_motion(MotionEntry::empty, -1);
    prg_->clear();
    ale_->zeroize();
}

ConditionEvent ConditionUnits::event(int k, ConditionEventKind kind, std::int64_t card,
                                     int card_number) const {
    const BufferPair& p = buffer_->pair(k);
    ConditionEvent e;
    e.kind = kind;
    e.event = p.condition.event;
    e.card = card;
    e.card_number = card_number;
    e.condition_card = p.card;
    e.axis = p.condition.axis;
    e.position = p.condition.position;
    e.sense = p.condition.sense;
    e.action = p.action.action;
    e.parameter = p.action.parameter;
    e.tool_in_spindle = ale_->tool_in_spindle();
    e.firing = p.every ? p.firings + 1 : 0;
    return e;
}

nlohmann::json ConditionUnits::save() const {
    if (!buffer_) {
        return nullptr;
    }
    return nlohmann::json{
        {"buffer_pfr", buffer_->save()},
        {"motion_pfr", {static_cast<int>(buffer_->motion()), buffer_->motion_card_number()}},
        {"monitoring_prg", prg_->save()},
        {"tripping_ale", ale_->save()}};
}

void ConditionUnits::load(const nlohmann::json& j) {
    if (!buffer_) {
        if (!j.is_null()) {
            throw axes::StateError("the state has condition units, but the profile allows no "
                                   "condition cards");
        }
        return;
    }
    if (j.is_null()) {
        return; // saved before any condition card: the units stand as built
    }
    buffer_->load(axes::member(j, "buffer_pfr"));
    if (j.contains("motion_pfr")) { // absent from states saved before it was kept: empty
        const nlohmann::json& m = j.at("motion_pfr");
        if (!m.is_array() || m.size() != 2 || !m.at(0).is_number_integer() ||
            !m.at(1).is_number_integer() || m.at(0).get<int>() < 0 || m.at(0).get<int>() > 2 ||
            m.at(1).get<int>() < -1 || m.at(1).get<int>() > 9999) {
            throw axes::StateError("conditions.motion_pfr: expected [state 0-2, card number]");
        }
        buffer_->set_motion(static_cast<MotionEntry>(m.at(0).get<int>()), m.at(1).get<int>());
    }
    prg_->load(axes::member(j, "monitoring_prg"));
    ale_->load(axes::member(j, "tripping_ale"));
}

} // namespace parsons::relaylogic
