#include "relaylogic/conditions/tripping_unit.hpp"

#include "axes/state_json.hpp"

#include <fmt/format.h>

namespace parsons::relaylogic {

using axes::SpindleTurning;
using cardreader::ActionKind;

TrippingUnit::TrippingUnit(Tracer& tracer, const axes::MachineProfile& profile)
    : tracer_(tracer), profile_(profile), changer_(profile.first_tool) {
    for (int k = 0; k < InternalBuffer::kChannels; ++k) {
        action_relay_.at(static_cast<std::size_t>(k)) = tracer.define(
            "conditions", fmt::format("tripping_ale.channel_{}.action", k),
            fmt::format("tripping unit ALE, channel {}: action relay (picked from the status "
                        "signal until the action is acknowledged)",
                        k),
            "ALE", 1);
    }
    for (cardreader::Axis a : cardreader::kAxes) {
        hold_relay_.at(cardreader::axis_index(a)) = tracer.define(
            "conditions", fmt::format("tripping_ale.hold_{}", cardreader::axis_name(a)),
            fmt::format("hold relay of the {} motor: open during a dwell",
                        cardreader::axis_name(a)),
            "ALE", 1);
    }
    spindle_motor_ = tracer.define("conditions", "spindle_motor",
                                   "spindle motor as the actions drive it (0 off, 1 forward, 2 "
                                   "reverse)",
                                   "", 2);
    coolant_valve_ = tracer.define("conditions", "coolant_valve", "coolant valve open", "", 1);
    tool_in_spindle_ = tracer.define("conditions", "tool_changer.in_spindle",
                                     "tool changer: the tool in the spindle", "", 7,
                                     static_cast<std::uint32_t>(profile.first_tool));
    tool_changing_ = tracer.define(
        "conditions", "tool_changer.changing",
        "tool changer: the tool being put in, or next to be (0 when no change is ordered)", "", 7);
    tool_waiting_ = tracer.define("conditions", "tool_changer.waiting",
                                  "tool changer: changes ordered behind the one under way "
                                  "(each waits for the changer)",
                                  "", 4);
    lamps_signal_ =
        tracer.define("conditions", "output_lamps",
                      "output lamps 1-9 lit by lamp actions (bit n-1 for lamp n)", "", 9);
}

double TrippingUnit::initiate(int k, const ActionEntry& a, double t) {
    const auto& times = profile_.actions;
    double done = t;
    switch (a.action) {
    case ActionKind::spindle_forward:
        done = spindle_->command(SpindleTurning::forward, t, times);
        break;
    case ActionKind::spindle_reverse:
        done = spindle_->command(SpindleTurning::reverse, t, times);
        break;
    case ActionKind::spindle_stop:
        done = spindle_->command(SpindleTurning::off, t, times);
        break;
    case ActionKind::coolant_on:
    case ActionKind::coolant_off:
        coolant_ = a.action == ActionKind::coolant_on;
        done = t + times.coolant_valve_s;
        break;
    case ActionKind::tool_change:
        // The changer takes no turning cutter: a change ordered while the spindle runs down
        // begins when it stands (one ordered while it turns never trips: refuses_now).
        done = changer_.change(a.parameter, t, spindle_->ready_s(), times);
        break;
    case ActionKind::dwell:
        held_ |= 1U << (a.parameter - 1);
        done = t + times.dwell_s;
        break;
    case ActionKind::lamp:
        lamps_ |= 1U << (a.parameter - 1);
        done = t + times.lamp_s;
        break;
    }
    running_ |= 1U << k;
    tracer_.set(action_relay_.at(static_cast<std::size_t>(k)), 1);
    show();
    return done;
}

void TrippingUnit::acknowledge(int k, const ActionEntry& a) {
    if (a.action == ActionKind::tool_change) {
        changer_.complete(a.parameter);
    } else if (a.action == ActionKind::dwell) {
        held_ &= ~(1U << (a.parameter - 1));
    }
    running_ &= ~(1U << k);
    tracer_.set(action_relay_.at(static_cast<std::size_t>(k)), 0);
    show();
}

// On the machine the cabinet has commanded the one motor already (ControlCabinet::
// command_spindle): the same order again changes nothing. The units alone (tests) command their
// own.
void TrippingUnit::spindle_from_card(cardreader::Spindle spindle, double t) {
    spindle_->command(spindle == cardreader::Spindle::forward   ? SpindleTurning::forward
                      : spindle == cardreader::Spindle::reverse ? SpindleTurning::reverse
                                                                : SpindleTurning::off,
                      t, profile_.actions);
    show();
}

void TrippingUnit::zeroize() {
    lamps_ = 0;
    show();
}

void TrippingUnit::show() {
    tracer_.set(spindle_motor_, static_cast<std::uint32_t>(spindle_->turning()));
    tracer_.set(coolant_valve_, coolant_ ? 1 : 0);
    tracer_.set(tool_in_spindle_, static_cast<std::uint32_t>(changer_.in_spindle()));
    tracer_.set(tool_changing_, static_cast<std::uint32_t>(changer_.changing_to()));
    tracer_.set(tool_waiting_, static_cast<std::uint32_t>(changer_.waiting()));
    tracer_.set(lamps_signal_, lamps_);
    for (std::size_t a = 0; a < hold_relay_.size(); ++a) {
        tracer_.set(hold_relay_.at(a), held_ >> a & 1U);
    }
}

nlohmann::json TrippingUnit::save() const {
    nlohmann::json changes = nlohmann::json::array();
    for (const axes::ToolChange& c : changer_.changes()) {
        changes.push_back({c.tool, axes::exact(c.start_s), axes::exact(c.done_s)});
    }
    return nlohmann::json{{"spindle", static_cast<int>(spindle_->turning())},
                          {"spindle_ready_s", axes::exact(spindle_->ready_s())},
                          {"tool_in_spindle", changer_.in_spindle()},
                          {"tool_changing_to", changer_.changing_to()},
                          {"tool_changes", changes},
                          {"coolant", coolant_},
                          {"held", held_},
                          {"lamps", lamps_},
                          {"running", running_}};
}

void TrippingUnit::load(const nlohmann::json& j) {
    using axes::read;
    const int spindle = read<int>(j, "spindle");
    if (spindle < 0 || spindle > 2) {
        throw axes::StateError("tripping_ale.spindle: expected 0, 1 or 2");
    }
    spindle_->restore(static_cast<SpindleTurning>(spindle),
                      axes::exact(axes::member(j, "spindle_ready_s")));
    std::deque<axes::ToolChange> changes;
    if (j.contains("tool_changes")) {
        for (const nlohmann::json& c : axes::member(j, "tool_changes")) {
            if (!c.is_array() || c.size() != 3 || !c.at(0).is_number_integer() ||
                c.at(0).get<int>() < 1 || c.at(0).get<int>() > 99) {
                throw axes::StateError(
                    "tripping_ale.tool_changes: expected [tool 1-99, start, done]");
            }
            changes.push_back(
                axes::ToolChange{c.at(0).get<int>(), axes::exact(c.at(1)), axes::exact(c.at(2))});
        }
    } else if (const int to = read<int>(j, "tool_changing_to"); to != 0) {
        changes.push_back(axes::ToolChange{to, -1, -1}); // a state saved before the queue
    }
    changer_.restore(read<int>(j, "tool_in_spindle"), std::move(changes));
    coolant_ = read<bool>(j, "coolant");
    held_ = read<unsigned>(j, "held") & 0x1FU;
    lamps_ = read<unsigned>(j, "lamps") & 0x1FFU;
    running_ = read<unsigned>(j, "running") & 0x3FFU;
    for (int k = 0; k < InternalBuffer::kChannels; ++k) {
        tracer_.set(action_relay_.at(static_cast<std::size_t>(k)), running_ >> k & 1U);
    }
    show();
}

} // namespace parsons::relaylogic
