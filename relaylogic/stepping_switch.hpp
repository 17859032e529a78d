// A ten-position rotary stepping switch: the decimal hardware of counters 104-110 (Fig. 12)
// and 310-316 (Fig. 11), and of speed switch 236's stepping.
//
// Positions 0..9; a step past 9 returns to 0 and gives a carry (the tenth step, which steps
// the next switch over channel 333), a step back past 0 returns to 9 with a borrow. A real
// switch takes time to step: an impulse that comes sooner than 1 / (maximum stepping rate)
// after the last step it took finds the wiper still moving and is lost. That is the silent
// error docs/design-rules.md rule 4 asks us to expose: the switch is behind the lead screw.
#pragma once

#include <nlohmann/json.hpp>

#include <limits>

namespace parsons::relaylogic {

class SteppingSwitch {
public:
    struct Step {
        bool taken = false; // false: the impulse was lost (switch still moving)
        bool carry = false; // taken and passed 9 -> 0 (or 0 -> 9 going back)
    };

    int position() const { return position_; }
    std::int64_t lost() const { return lost_; }
    // Net whole turns of the wiper: +1 each time it passes 9 -> 0, -1 each 0 -> 9. Not a part
    // of the 1952 switch: the emulator keeps it so that a report can tell a counter that
    // wrapped round from one that is 10 inches out (counters 104-110 read 0 .. 9.999 only).
    std::int64_t turns() const { return turns_; }

    Step step(int direction, double t, double min_interval_s) {
        if (t - last_step_s_ < min_interval_s) {
            ++lost_;
            return {};
        }
        last_step_s_ = t;
        Step s{true, move(direction)};
        if (++steps_ == skip_at_) {
            s.carry = move(direction) || s.carry; // the fault: the wiper skips a position
        }
        return s;
    }

    // Fault: on its nth step (from 1) the wiper moves two positions.
    void skip_on_step(std::int64_t n) { skip_at_ = n; }
    bool skip_pending() const { return skip_at_ > steps_; }
    bool skipped() const { return skip_at_ > 0 && skip_at_ <= steps_; }

    // Homing (zeroizing): the wiper runs back to 0.
    void home() { position_ = 0; }
    void set(int position) { position_ = position; }

    // Fast-forward: after a stretch of impulses that all found the switch ready, it stands on
    // `position`, and took its last step at time `last_step_s`.
    double last_step_s() const { return last_step_s_; }
    void jump(int position, double last_step_s, std::int64_t turns = 0) {
        position_ = position;
        last_step_s_ = last_step_s;
        turns_ += turns;
    }

    // The state a saved machine keeps (relaylogic/machine_state.cpp).
    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    // One position; true if it passed 9 -> 0 (or 0 -> 9 going back).
    bool move(int direction) {
        if (direction >= 0) {
            const bool carry = position_ == 9;
            position_ = carry ? 0 : position_ + 1;
            turns_ += carry ? 1 : 0;
            return carry;
        }
        const bool carry = position_ == 0;
        position_ = carry ? 9 : position_ - 1;
        turns_ -= carry ? 1 : 0;
        return carry;
    }

    int position_ = 0;
    std::int64_t steps_ = 0;   // steps taken (counted only for a skip fault's sake)
    std::int64_t skip_at_ = 0; // 0: no fault
    double last_step_s_ = -std::numeric_limits<double>::infinity();
    std::int64_t lost_ = 0;
    std::int64_t turns_ = 0; // net wraps (see turns())
};

} // namespace parsons::relaylogic
