#include "axes/stepper_motor.hpp"

#include <cmath>

namespace parsons::axes {

std::int64_t steps_lost(double jump, double pull_in, double acceleration) {
    const double excess = std::abs(jump) - pull_in;
    if (excess <= 0) {
        return 0;
    }
    return std::llround(excess * excess / (2.0 * acceleration));
}

std::int64_t StepperMotor::jump_to(double rate) {
    const double jump = rate - rate_;
    const std::int64_t n = steps_lost(jump, pull_in_, acceleration_);
    rate_ = rate;
    if (n != 0) {
        lost_ += n;
        offset_ += jump > 0 ? -n : n; // behind when it speeds up, past the pulses when it slows
    }
    return n;
}

} // namespace parsons::axes
