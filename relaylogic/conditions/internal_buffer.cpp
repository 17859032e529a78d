#include "relaylogic/conditions/internal_buffer.hpp"

#include "axes/state_json.hpp"
#include "cardreader/condition_card.hpp"

#include <fmt/format.h>

namespace parsons::relaylogic {

InternalBuffer::InternalBuffer(Tracer& tracer) : tracer_(tracer) {
    for (int k = 0; k < kChannels; ++k) {
        const auto i = static_cast<std::size_t>(k);
        event_signal_.at(i) =
            tracer.define("conditions", fmt::format("buffer_pfr.pair_{}.event", k),
                          fmt::format("internal buffer PFR, pair {}: the event identifier of its "
                                      "condition and action entries (EP 0640901 claim 3)",
                                      k),
                          "PFR", 7);
        state_signal_.at(i) =
            tracer.define("conditions", fmt::format("buffer_pfr.pair_{}.state", k),
                          fmt::format("internal buffer PFR, pair {}: 0 empty, 1 stored, 2 armed, "
                                      "3 tripped, 4 acknowledged",
                                      k),
                          "PFR", 3);
    }
    motion_state_ = tracer.define("conditions", "buffer_pfr.motion.state",
                                  "internal buffer PFR, motion entry: 0 empty, 1 entered by "
                                  "converter UMS, 2 supplied to the axes (EP 0640901 claim 1)",
                                  "PFR", 2);
    motion_card_ = tracer.define("conditions", "buffer_pfr.motion.card",
                                 "internal buffer PFR, motion entry: the number of the motion "
                                 "card whose statement it holds",
                                 "PFR", 14);
}

void InternalBuffer::set_motion(MotionEntry state, int card_number) {
    motion_ = state;
    motion_number_ = card_number;
    tracer_.set(motion_state_, static_cast<std::uint32_t>(state));
    tracer_.set(motion_card_, card_number < 0 ? 0U : static_cast<std::uint32_t>(card_number));
}

void InternalBuffer::set_state(int k, PairState s) {
    BufferPair& p = pair(k);
    p.state = s;
    tracer_.set(state_signal_.at(static_cast<std::size_t>(k)), static_cast<std::uint32_t>(s));
    tracer_.set(event_signal_.at(static_cast<std::size_t>(k)),
                s == PairState::empty ? 0U : static_cast<std::uint32_t>(p.condition.event));
}

int InternalBuffer::free_pair() const {
    return first(PairState::empty);
}

int InternalBuffer::pair_with_event(int event) const {
    for (int k = 0; k < kChannels; ++k) {
        if (pair(k).state != PairState::empty && pair(k).condition.event == event) {
            return k;
        }
    }
    return -1;
}

int InternalBuffer::first(PairState s) const {
    for (int k = 0; k < kChannels; ++k) {
        if (pair(k).state == s) {
            return k;
        }
    }
    return -1;
}

void InternalBuffer::clear() {
    for (int k = 0; k < kChannels; ++k) {
        if (pair(k).state != PairState::empty) {
            set_state(k, PairState::empty);
            pair(k) = BufferPair{};
        }
    }
}

nlohmann::json InternalBuffer::save() const {
    using axes::exact;
    nlohmann::json list = nlohmann::json::array();
    for (const BufferPair& p : pairs_) {
        list.push_back({{"state", static_cast<int>(p.state)},
                        {"event", p.condition.event},
                        {"axis", static_cast<int>(p.condition.axis)},
                        {"position", p.condition.position},
                        {"sense", static_cast<int>(p.condition.sense)},
                        {"action", static_cast<int>(p.action.action)},
                        {"parameter", p.action.parameter},
                        {"card", p.card},
                        {"card_number", p.card_number},
                        {"slot", p.slot},
                        {"motion_card", p.motion_card},
                        {"tripped_s", exact(p.tripped_s)},
                        {"acknowledged_s", exact(p.acknowledged_s)}});
        if (p.every) { // only then, so that states of decks without one stay as they were
            list.back()["every"] = true;
            list.back()["firings"] = p.firings;
        }
    }
    return list;
}

void InternalBuffer::load(const nlohmann::json& j) {
    using axes::exact;
    using axes::read;
    if (!j.is_array() || j.size() != static_cast<std::size_t>(kChannels)) {
        throw axes::StateError(fmt::format("buffer_pfr: expected {} pairs", kChannels));
    }
    for (int k = 0; k < kChannels; ++k) {
        const nlohmann::json& e = j.at(static_cast<std::size_t>(k));
        BufferPair p;
        const int state = read<int>(e, "state");
        const int axis = read<int>(e, "axis");
        const int sense = read<int>(e, "sense");
        const int action = read<int>(e, "action");
        if (state < 0 || state > 4 || axis < 0 || axis >= cardreader::kAxisCount || sense < 0 ||
            sense > 2 || action < 1 || action > cardreader::kActionKinds) {
            throw axes::StateError(fmt::format("buffer_pfr[{}]: a value out of range", k));
        }
        p.condition.event = read<int>(e, "event");
        p.condition.axis = static_cast<cardreader::Axis>(axis);
        p.condition.position = read<cardreader::Thousandths>(e, "position");
        p.condition.sense = static_cast<cardreader::PassingSense>(sense);
        p.action.event = p.condition.event;
        p.action.action = static_cast<cardreader::ActionKind>(action);
        p.action.parameter = read<int>(e, "parameter");
        p.card = read<std::int64_t>(e, "card");
        p.card_number = read<int>(e, "card_number");
        p.slot = e.contains("slot") ? read<int>(e, "slot") : 0; // absent from older states
        if (p.slot < 0 || p.slot >= cardreader::kConditionsPerCard) {
            throw axes::StateError(fmt::format("buffer_pfr[{}]: slot out of range", k));
        }
        p.motion_card = read<std::int64_t>(e, "motion_card");
        p.tripped_s = exact(axes::member(e, "tripped_s"));
        p.acknowledged_s = exact(axes::member(e, "acknowledged_s"));
        p.every = e.contains("every") && read<bool>(e, "every");
        p.firings = e.contains("firings") ? read<int>(e, "firings") : 0;
        if (p.firings < 0) {
            throw axes::StateError(fmt::format("buffer_pfr[{}]: firings out of range", k));
        }
        pair(k) = p;
        set_state(k, static_cast<PairState>(state));
    }
}

std::optional<std::string> convert_condition_card(const cardreader::CardOrders& card,
                                                  std::int64_t index, InternalBuffer& buffer) {
    for (int i = 0; i < card.condition_count; ++i) {
        const cardreader::ConditionOrder& c = card.conditions.at(static_cast<std::size_t>(i));
        const int column = 1 + i * cardreader::kConditionSlotColumns;
        const int other = buffer.pair_with_event(c.event);
        if (c.mode == cardreader::ConditionMode::cancel) {
            if (other < 0 || !buffer.pair(other).every) {
                return fmt::format("card {}, column {}: a cancel of event {}, but no "
                                   "every-condition with that identifier stands in buffer PFR "
                                   "(every and cancel are an addition beyond EP 0640901's claims, "
                                   "after Siemens' WHENEVER/EVERY)",
                                   index, column + cardreader::kConditionModeOffset, c.event);
            }
            buffer.set_state(other, PairState::empty);
            buffer.pair(other) = BufferPair{};
            continue;
        }
        if (other >= 0 && buffer.pair(other).every) {
            const BufferPair& o = buffer.pair(other);
            return fmt::format("card {}, column {}: event {} stands as an every-condition (card "
                               "{}, condition {}) until it is cancelled: an identifier names one "
                               "condition and its action (EP 0640901 claim 3; cancel it first, "
                               "a slot with the event and 2 in its mode column)",
                               index, column, c.event, o.card, o.slot + 1);
        }
        if (other >= 0) {
            const BufferPair& o = buffer.pair(other);
            return fmt::format("card {}, column {}: event {} is already stored for the same "
                               "motion card (card {}{}): an identifier names one condition and "
                               "its action (EP 0640901 claim 3; condition cards are an addition)",
                               index, column, c.event, o.card,
                               o.card == index ? ", an earlier condition" : "");
        }
        const int k = buffer.free_pair();
        if (k < 0) {
            return fmt::format("card {}, column {}: internal buffer PFR is full ({} conditions "
                               "before one motion card at most; condition cards are an addition "
                               "after EP 0640901, Siemens)",
                               index, column, InternalBuffer::kChannels);
        }
        BufferPair& p = buffer.pair(k);
        p = BufferPair{};
        p.condition = ConditionEntry{c.event, c.axis, c.position, c.sense};
        p.action = ActionEntry{c.event, c.action, c.parameter};
        p.card = index;
        p.card_number = card.number;
        p.slot = i;
        p.every = c.mode == cardreader::ConditionMode::every;
        buffer.set_state(k, PairState::stored);
    }
    return std::nullopt;
}

} // namespace parsons::relaylogic
