// The conversions every deck generator makes: inches to the whole thousandths a card is
// punched in, and a speed-switch position to the lead screw's speed in the profile.
#pragma once

#include "axes/machine_profile.hpp"

#include <cmath>
#include <cstddef>

namespace parsons::decks {

// Inches to whole thousandths, rounded to the nearest (half away from zero).
inline int thousandths(double inches) {
    return static_cast<int>(std::lround(inches * 1000));
}

// The speed of speed-switch position 1 .. 3 (1 the fastest), in inches a second.
inline double speed_in_per_s(const axes::AxisProfile& axis, int position) {
    return axis.speed_in_per_min.at(static_cast<std::size_t>(position - 1)) / 60.0;
}

} // namespace parsons::decks
