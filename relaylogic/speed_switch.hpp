// Speed switch 236 (Fig. 10) with stepping device 252, stepping relay 256 and delay device 258.
//
// Positions off (contact 238), 1, 2, 3 (fastest to slowest), stepping round. The second brush
// bank's sensing circuit 250 sends 1, 2 or 3 impulses to stepping device 252 (speed column
// 0 / 0-1 / 0-1-2), so the switch leaves off for speed 1, 2 or 3. While it stands on speed 1
// or 2, each equality of absolute comparer 122' reaches stepping relay 256 over channel 257
// and steps it one speed slower; an absolute equality on speed 3, or an incremental equality
// at any speed, sends it to off: the stop. Delay device 258 holds channel 257 open after each
// step for a short time AND until the comparer has left the equality that caused it, so one
// equality never steps the switch twice.
//
//   state    | 252 impulse | 256 (equality) | 258 after a step
//   off      | -> 1        | (motor is off)  |
//   1, 2     | -> next     | -> one slower   | blocks until hold time passed and equality left
//   3        | -> off      | -> off (stop)   |
//
// Emulation note: stepping relay 256 and the switch act at the instant of the equality; their
// few milliseconds are not modelled separately (the motor's own response is).
#pragma once

#include "relaylogic/tracer.hpp"

namespace parsons::relaylogic {

class SpeedSwitch {
public:
    SpeedSwitch(Tracer& tracer, const std::string& scope);

    int position() const { return position_; } // 0 = off, 1..3
    bool off() const { return position_ == 0; }

    // Stepping device 252: one impulse from the speed column.
    void step_from_card();
    // Stepping relay 256: one speed slower (from 1 or 2), and delay 258 starts holding.
    void step_slower(double t, double hold_s);
    // Stepping relay 256 to contact 238: off. Delay 258 holds as after any step.
    void to_off(double t, double hold_s);

    // Delay device 258: may channel 257 pass an equality now?
    bool channel_257_open(double t) const { return t >= hold_until_ && left_equality_; }
    double hold_until() const { return hold_until_; }
    // The comparer has been out of equality since the last step (the counter stepped).
    void equality_left(double t) {
        left_equality_ = true;
        if (t >= hold_until_) {
            tracer_.set(relay_256_, 0);
            tracer_.set(delay_258_, 0);
        }
    }
    // The hold time of delay 258 has run out (the equality may still stand).
    void hold_expired(double t);
    // Zeroizing: the delay device and the stepping relay reset for the next card.
    void reset();
    // The state a saved machine keeps (relaylogic/machine_state.cpp).
    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    void hold(double t, double hold_s);

    Tracer& tracer_;
    int position_ = 0;
    double hold_until_ = 0;
    bool left_equality_ = true;
    SignalId switch_signal_;
    SignalId relay_256_;
    SignalId delay_258_;
};

} // namespace parsons::relaylogic
