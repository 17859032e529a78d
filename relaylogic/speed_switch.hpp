// Speed switch 236 (Fig. 10) with contact 238, stepping device 252, stepping relay 256, channel
// 257 and delay device 258.
//
// Positions off (contact 238), 1, 2, 3 (fastest to slowest), stepping round. The second brush
// bank's sensing circuit 250 sends 1, 2 or 3 impulses to stepping device 252 (speed column
// 0 / 0-1 / 0-1-2), so the switch leaves off for speed 1, 2 or 3. While it stands on a speed
// circuit (242, 244, 246), an equality of a comparer reaches stepping relay 256 over channel
// 257, and "the speed switch 236 steps to a new and slower speed each time the stepping relay
// 256 receives an impulse" (col. 10): one impulse, one step, whichever comparer sent it. The
// step from speed 3 to off (contact 238) is the stop. Delay device 258 "opens the circuit 257
// to the stepping relay 256 for a short period after an impulse is received": a timed hold and
// nothing else. An equality still standing when the hold runs out steps the switch again; that
// is what 258 is there to prevent, so its time must outlast an equality at the slowest speed
// (docs/design-rules.md rule 5; docs/machine-profile.md).
//
//   state    | 252 impulse | 256 impulse (channel 257 closed) | 258 after a step
//   off      | -> 1        | (no speed circuit: none reaches) |
//   1, 2     | -> next     | -> one slower                    | opens 257 for hold_s
//   3        | -> off      | -> off: contact 238, the stop    | opens 257 for hold_s
//
// An earlier reading, kept as an interpretation (profile option
// delay_258_waits_for_equality_to_leave): 258 holds 257 open until the hold time has passed
// AND the comparer has left the equality, so one equality can never step twice.
//
// Emulation note: stepping relay 256 and the switch act at the instant of the impulse; their
// few milliseconds are not modelled separately (the motor's own response is). Relay 256 is
// shown picked from the impulse until 258 closes channel 257 again.
#pragma once

#include "relaylogic/tracer.hpp"

namespace parsons::relaylogic {

class SpeedSwitch {
public:
    // waits_for_equality_to_leave: the interpretation above (false: the patent's timed hold).
    SpeedSwitch(Tracer& tracer, const std::string& scope, bool waits_for_equality_to_leave);

    int position() const { return position_; } // 0 = off, 1..3
    bool off() const { return position_ == 0; }

    // Stepping device 252: one impulse from the speed column.
    void step_from_card();
    // An equality passes channel 257 to stepping relay 256: the switch steps one speed slower
    // (from 3 to off, contact 238), and delay 258 opens channel 257 for hold_s.
    void impulse_256(double t, double hold_s);
    // Stepping relay 256 straight to off (the interpretation "an incremental equality stops
    // at any speed"): the switch is stepped round to contact 238 at once.
    void to_off(double t, double hold_s);

    // Delay device 258: may channel 257 pass an equality now?
    bool channel_257_open(double t) const {
        return t >= hold_until_ && (!waits_for_leave_ || left_equality_);
    }
    double hold_until() const { return hold_until_; }
    // Delay 258 holds channel 257 open and has not been seen to release yet.
    bool held() const { return held_; }
    // The comparer has been out of equality since the last step (the counter stepped).
    void equality_left(double t) {
        left_equality_ = true;
        release_if_due(t);
    }
    // The hold time of delay 258 has run out (the equality may still stand).
    void hold_expired(double t) { release_if_due(t); }
    // The state a saved machine keeps (relaylogic/machine_state.cpp).
    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    void show_position();
    void hold(double t, double hold_s);
    void release_if_due(double t) {
        if (held_ && channel_257_open(t)) {
            held_ = false;
            tracer_.set(delay_258_, 0);
            tracer_.set(relay_256_, 0);
        }
    }

    Tracer& tracer_;
    bool waits_for_leave_;
    int position_ = 0;
    double hold_until_ = 0;
    bool left_equality_ = true;
    bool held_ = false; // delay 258 holds channel 257 open (what sets: a step; clears: release)
    SignalId switch_signal_;
    SignalId contact_238_;
    SignalId channel_257_;
    SignalId relay_256_;
    SignalId delay_258_;
};

} // namespace parsons::relaylogic
