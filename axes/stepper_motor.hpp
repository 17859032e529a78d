// A stepper motor driving one axis of the contouring attachment (an addition after EP 0636958,
// Black & Decker): each pulse turns it one step, steps_per_in steps to the inch of its slide.
// Nothing measures where it is: it is where its pulses put it, as long as it follows them.
//
// The seed: "these motors cannot be subjected to sharp changes in the speed of rotation, or of
// the control pulse period. In fact, an excessively rapid change gives rise to an inevitable loss
// of pitch, that is to say, the angular position assumed by the motor becomes indistinct".
// parsons' model of that (docs/contouring.md, "The motor"): a change of the pulse rate at one
// instant is followed at once if it is at most the pull-in rate J (steps/s); a larger jump
// throws the rotor out of step, and it slews to the new rate at its acceleration A
// (steps/s²), missing meanwhile the pulses it lags by: (|jump| - J)² / (2 A) steps, rounded to
// whole steps. The rotor falls behind the pulses when the rate jumps up (in the sense of
// travel) and runs past them when it jumps down. A ramp at most A (the interpolator's) is
// followed.
#pragma once

#include <cstdint>

namespace parsons::axes {

// Steps lost at one jump of the pulse rate (steps/s) by a motor of pull-in rate
// `pull_in` (steps/s) and rotor acceleration `acceleration` (steps/s²).
std::int64_t steps_lost(double jump, double pull_in, double acceleration);

class StepperMotor {
public:
    StepperMotor(double pull_in_steps_per_s, double acceleration_steps_per_s2)
        : pull_in_(pull_in_steps_per_s), acceleration_(acceleration_steps_per_s2) {}

    // The pulse rate changes at once to `rate` (steps/s; the sign is the sense): the steps it
    // loses (0 if it follows).
    std::int64_t jump_to(double rate);
    // The pulse rate reaches `rate` along a ramp the rotor follows.
    void ramp_to(double rate) { rate_ = rate; }

    double rate() const { return rate_; }
    // Where the rotor stands against the pulses it was given, steps (+ ahead, - behind).
    std::int64_t offset() const { return offset_; }
    // Steps lost in all (each counted once, whatever its sense).
    std::int64_t lost() const { return lost_; }
    void restore(std::int64_t offset, std::int64_t lost) {
        offset_ = offset;
        lost_ = lost;
        rate_ = 0;
    }

private:
    double pull_in_;
    double acceleration_;
    double rate_ = 0;
    std::int64_t offset_ = 0;
    std::int64_t lost_ = 0;
};

} // namespace parsons::axes
