// What a saved machine state holds, component by component (run --save-state, --resume).
//
// Every value that changes as the machine runs is written, doubles exactly (axes/state_json):
// a machine loaded from it goes on exactly as the one that wrote it would have, event for
// event. The signal values (every relay, switch and lamp by name) are written too, so that a
// trace of the resumed run starts from what the machine showed.
#include "axes/state_json.hpp"
#include "relaylogic/axis_circuit.hpp"
#include "relaylogic/counters.hpp"
#include "relaylogic/sequence_control.hpp"
#include "relaylogic/speed_switch.hpp"
#include "relaylogic/stepping_switch.hpp"
#include "relaylogic/storage.hpp"
#include "relaylogic/tracer.hpp"

namespace parsons::relaylogic {

using axes::exact;
using axes::member;
using axes::read;
using axes::StateError;
using nlohmann::json;

namespace {

int digit(const json& j, const char* key) {
    const int v = read<int>(j, key);
    if (v < 0 || v > 9) {
        throw StateError(std::string("'") + key + "' must be 0..9");
    }
    return v;
}

template <typename T, std::size_t N>
void load_each(std::array<T, N>& parts, const json& j, const char* key) {
    const json& list = member(j, key);
    if (!list.is_array() || list.size() != N) {
        throw StateError(std::string("'") + key + "' must list " + std::to_string(N));
    }
    for (std::size_t i = 0; i < N; ++i) {
        parts.at(i).load(list.at(i));
    }
}

template <typename T, std::size_t N>
json save_each(const std::array<T, N>& parts) {
    json list = json::array();
    for (const auto& p : parts) {
        list.push_back(p.save());
    }
    return list;
}

} // namespace

json SteppingSwitch::save() const {
    return json{{"position", position_}, {"last_step_s", exact(last_step_s_)},
                {"lost", lost_},         {"steps", steps_},
                {"skip_at", skip_at_},   {"turns", turns_}};
}

void SteppingSwitch::load(const json& j) {
    position_ = digit(j, "position");
    last_step_s_ = exact(member(j, "last_step_s"));
    lost_ = read<std::int64_t>(j, "lost");
    steps_ = read<std::int64_t>(j, "steps");
    skip_at_ = read<std::int64_t>(j, "skip_at");
    turns_ = j.contains("turns") ? read<std::int64_t>(j, "turns") : 0; // states saved before it: 0
}

json AbsoluteCounter::save() const {
    return json{{"switches_104_to_110", save_each(switches_)}};
}

void AbsoluteCounter::load(const json& j) {
    load_each(switches_, j, "switches_104_to_110");
}

json IncrementCounter::save() const {
    return json{{"switches_310_to_316", save_each(switches_)}};
}

void IncrementCounter::load(const json& j) {
    load_each(switches_, j, "switches_310_to_316");
}

json HoldingRelayBank::save() const {
    return json{{"closed", closed_}, {"stuck", stuck_}, {"dead", dead_}, {"refused", refused_}};
}

void HoldingRelayBank::load(const json& j) {
    auto mask = [&j](const char* key) {
        const int v = read<int>(j, key);
        if (v < 0 || v > 1023) {
            throw StateError(std::string("'") + key + "' must be a mask of relays 0..9");
        }
        return static_cast<std::uint16_t>(v);
    };
    closed_ = mask("closed");
    stuck_ = mask("stuck");
    dead_ = mask("dead");
    refused_ = read<std::int64_t>(j, "refused");
}

json AbsoluteStorage::save() const {
    return json{{"banks_350_to_356", save_each(banks_)}, {"numbers", numbers_}};
}

void AbsoluteStorage::load(const json& j) {
    load_each(banks_, j, "banks_350_to_356");
    numbers_ = read<std::vector<int>>(j, "numbers");
}

json IncrementalStorage::save() const {
    return json{{"banks_324_to_318", save_each(banks_)}};
}

void IncrementalStorage::load(const json& j) {
    load_each(banks_, j, "banks_324_to_318");
}

json SpeedSwitch::save() const {
    return json{{"position", position_},
                {"hold_until", exact(hold_until_)},
                {"left_equality", left_equality_},
                {"held", held_}};
}

void SpeedSwitch::load(const json& j) {
    position_ = read<int>(j, "position");
    if (position_ < 0 || position_ > 3) {
        throw StateError("speed switch position must be 0..3");
    }
    hold_until_ = exact(member(j, "hold_until"));
    left_equality_ = read<bool>(j, "left_equality");
    held_ = read<bool>(j, "held");
}

json SequenceSwitch::save() const {
    return json{{"contacts_closed", closed_}};
}

void SequenceSwitch::load(const json& j) {
    closed_ = read<std::array<bool, 5>>(j, "contacts_closed");
}

json SteppingShaft::save() const {
    return json{{"position", position_},
                {"pending", pending_},
                {"busy", busy_},
                {"last_impulse_t", exact(last_impulse_t_)}};
}

void SteppingShaft::load(const json& j) {
    position_ = read<int>(j, "position");
    if (position_ < 1 || position_ > 5) {
        throw StateError("stepping shaft position must be 1..5");
    }
    pending_ = read<int>(j, "pending");
    busy_ = read<bool>(j, "busy");
    // A state is captured at a card's feed, after channel 302: device 288 has no break and no
    // impulse is pending whose axis it would need.
    broken_ = 0;
    last_impulse_t_ = exact(member(j, "last_impulse_t"));
}

json AxisCircuit::save() const {
    json o{{"motion", order.motion == cardreader::Motion::forward ? "+" : "-"},
           {"start_speed", order.start_speed},
           {"stop", order.stop},
           {"check", order.check},
           {"sequence", order.sequence}};
    json slow = json::array();
    for (const auto& s : order.slow_down) {
        slow.push_back(s ? json(*s) : json(nullptr));
    }
    o["slow_down"] = slow;
    return json{{"plant", plant.save()},
                {"absolute_storage", absolute_storage.save()},
                {"incremental_storage", incremental_storage.save()},
                {"absolute_counter", absolute_counter.save()},
                {"increment_counter", increment_counter.save()},
                {"speed_switch", speed_switch.save()},
                {"sequence_switch", sequence_switch.save()},
                {"direction", direction},
                {"absolute_conducting", absolute_conducting},
                {"incremental_conducting", incremental_conducting},
                {"powered", powered},
                {"stopped", stopped},
                {"contact_set_a", contact_set_a},
                {"contact_set_b", contact_set_b},
                {"wrong_way", wrong_way},
                {"thousandths_uncounted", thousandths_uncounted},
                {"ordered", ordered},
                {"order", o}};
}

void AxisCircuit::load(const json& j) {
    plant.load(member(j, "plant"));
    absolute_storage.load(member(j, "absolute_storage"));
    incremental_storage.load(member(j, "incremental_storage"));
    absolute_counter.load(member(j, "absolute_counter"));
    increment_counter.load(member(j, "increment_counter"));
    speed_switch.load(member(j, "speed_switch"));
    sequence_switch.load(member(j, "sequence_switch"));
    direction = read<int>(j, "direction") >= 0 ? +1 : -1;
    absolute_conducting = read<bool>(j, "absolute_conducting");
    incremental_conducting = read<bool>(j, "incremental_conducting");
    powered = read<bool>(j, "powered");
    stopped = read<bool>(j, "stopped");
    contact_set_a = read<std::int64_t>(j, "contact_set_a");
    contact_set_b = read<std::int64_t>(j, "contact_set_b");
    // States saved before the tallies were kept have none.
    wrong_way = j.contains("wrong_way") ? read<std::int64_t>(j, "wrong_way") : 0;
    thousandths_uncounted =
        j.contains("thousandths_uncounted") ? read<std::int64_t>(j, "thousandths_uncounted") : 0;
    // States saved before the cards' orders were tallied: the counters' own count, as if every
    // card before had ended where it ordered.
    ordered = j.contains("ordered") ? read<std::int64_t>(j, "ordered")
                                    : absolute_counter.unwrapped_value();
    const json& o = member(j, "order");
    order.motion = read<std::string>(o, "motion") == "-" ? cardreader::Motion::reverse
                                                         : cardreader::Motion::forward;
    order.start_speed = read<int>(o, "start_speed");
    order.stop = read<cardreader::Thousandths>(o, "stop");
    order.check = read<cardreader::Thousandths>(o, "check");
    order.sequence = read<cardreader::SequencePattern>(o, "sequence");
    const json& slow = member(o, "slow_down");
    for (std::size_t i = 0; i < order.slow_down.size() && i < slow.size(); ++i) {
        order.slow_down.at(i) = slow.at(i).is_null()
                                    ? std::nullopt
                                    : std::optional(slow.at(i).get<cardreader::Thousandths>());
    }
}

json Tracer::save() const {
    json values = json::object();
    for (const SignalInfo& info : infos_) {
        values[info.scope + "." + info.name] = values_.at(info.id);
    }
    return values;
}

void Tracer::load(const json& j) {
    for (const SignalInfo& info : infos_) {
        values_.at(info.id) = read<std::uint32_t>(j, (info.scope + "." + info.name).c_str());
    }
}

} // namespace parsons::relaylogic
