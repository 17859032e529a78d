// The spindle motor that turns cutter 184 (Fig. 1), as the condition cards' actions drive it (an
// addition after EP 0640901, Siemens).
//
// The 1952 machine only sets the spindle's direction from column 1 of each card (spindle
// control 165, relaylogic/control_cabinet.cpp) and says nothing of how long the motor takes.
// For the actions of a condition card the time matters, because the tripping unit ALE
// acknowledges an action only once it is done: a start runs the motor up to cutting speed in
// the profile's run-up time, a stop runs it down in the run-down time, and a reversal does
// both (plugging: run down, then up the other way).
//
// Emulation note: the speed in between is not modelled (only "at speed" or not); nothing in
// the emulator cuts differently while the spindle runs up.
#pragma once

#include "axes/machine_profile.hpp"

#include <algorithm>
#include <cstdint>

namespace parsons::axes {

enum class SpindleTurning : std::uint8_t { off, forward, reverse };

class SpindleMotor {
public:
    // Commands the motor at time t; returns when it stands at the commanded state (at speed,
    // or at rest).
    double command(SpindleTurning want, double t, const ActionTimes& times) {
        double ready = std::max(t, ready_s_);
        if (want != turning_) {
            if (turning_ != SpindleTurning::off) {
                ready += times.spindle_run_down_s;
            }
            if (want != SpindleTurning::off) {
                ready += times.spindle_run_up_s;
            }
        }
        turning_ = want;
        ready_s_ = ready;
        return ready;
    }
    SpindleTurning turning() const { return turning_; }
    double ready_s() const { return ready_s_; }
    void restore(SpindleTurning turning, double ready_s) {
        turning_ = turning;
        ready_s_ = ready_s;
    }

private:
    SpindleTurning turning_ = SpindleTurning::off;
    double ready_s_ = 0;
};

} // namespace parsons::axes
