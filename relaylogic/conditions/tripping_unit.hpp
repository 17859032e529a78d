// Tripping unit ALE of EP 0640901 (Siemens, claims 1 and 2): an addition, not in
// the 1952 patent. "The tripping unit (ALE) obtains a status signal from the monitoring unit
// (PRG) upon fulfilment of the condition and thereupon initiates the action"; "the
// performance of each action is acknowledged to the tripping unit (ALE) and when all the
// actions to be performed are acknowledged ... the processing of the next program record is
// enabled" (claim 2).
//
// One action relay per channel picks when PRG reports the channel's identifier and drops with
// the action's acknowledgement. The actions act on the plant:
//   spindle-forward / -reverse / -stop   spindle motor (axes/spindle_motor.hpp): run-up,
//                                        run-down, or both for a reversal
//   coolant-on / -off                    coolant valve, the profile's valve time
//   tool-change N                        tool changer (axes/tool_changer.hpp): tool N is in
//                                        the spindle (and its radius cuts) when acknowledged
//   dwell AXIS                           hold relay of that axis opens its motor circuit for
//                                        the profile's dwell; the axis coasts, then runs on
//   lamp N                               output lamp N lights; zeroizing puts it out
// How long each takes is the profile's (axes::ActionTimes); the cabinet queues the
// acknowledgement for then.
#pragma once

#include "axes/machine_profile.hpp"
#include "axes/spindle_motor.hpp"
#include "axes/tool_changer.hpp"
#include "cardreader/orders.hpp"
#include "relaylogic/conditions/internal_buffer.hpp"

namespace parsons::relaylogic {

class TrippingUnit {
public:
    TrippingUnit(Tracer& tracer, const axes::MachineProfile& profile);
    // Initiates the action of channel k at time t; returns when it will be done.
    double initiate(int k, const ActionEntry& action, double t);
    // The action of channel k is done: its relay drops, and what completes with it does.
    void acknowledge(int k, const ActionEntry& action);
    // Spindle control 165 at a motion card's relays pick (column 1) commands the motor too.
    void spindle_from_card(cardreader::Spindle spindle, double t);
    // The zeroizing circuit puts the output lamps out.
    void zeroize();
    bool held(cardreader::Axis axis) const {
        return (held_ >> cardreader::axis_index(axis) & 1U) != 0;
    }
    int tool_in_spindle() const { return changer_.in_spindle(); }
    axes::SpindleTurning spindle() const { return spindle_->turning(); }
    // The machine's one spindle motor, which column 1 commands through spindle control 165
    // (ControlCabinet::spindle_motor): the actions drive it too. Until then, a motor of the
    // unit's own (the units alone, in tests).
    void drive_spindle(axes::SpindleMotor& motor) { spindle_ = &motor; }
    // The action may not begin now: a tool change while the spindle motor is commanded to turn
    // (the changer takes no turning cutter; the cabinet stops the machine).
    bool refuses_now(const ActionEntry& action) const {
        return action.action == cardreader::ActionKind::tool_change &&
               spindle_->turning() != axes::SpindleTurning::off;
    }
    const axes::ToolChanger& changer() const { return changer_; }
    bool coolant() const { return coolant_; }
    unsigned lamps() const { return lamps_; } // bit n-1 for lamp n
    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    void show();

    Tracer& tracer_;
    const axes::MachineProfile& profile_;
    axes::SpindleMotor own_spindle_;
    axes::SpindleMotor* spindle_ = &own_spindle_;
    axes::ToolChanger changer_;
    bool coolant_ = false;
    unsigned held_ = 0;    // bit per axis: its hold relay is open (a dwell)
    unsigned lamps_ = 0;   // bit n-1: output lamp n lit
    unsigned running_ = 0; // bit k: channel k's action relay is picked
    std::array<SignalId, InternalBuffer::kChannels> action_relay_{};
    std::array<SignalId, cardreader::kAxisCount> hold_relay_{};
    SignalId spindle_motor_;
    SignalId coolant_valve_;
    SignalId tool_in_spindle_;
    SignalId tool_changing_;
    SignalId tool_waiting_;
    SignalId lamps_signal_;
};

} // namespace parsons::relaylogic
