#include "outputs/report/figures.hpp"

#include <array>
#include <cmath>

namespace parsons::cli {

double decimals(double v, int places) {
    // Powers of ten up to 1e15 are exact doubles, so n / 10^places is the nearest double to the
    // decimal n·10^-places (a product by 10^-places, which is not exact, is not).
    static constexpr std::array<double, 16> kPowers{1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                                    1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
    if (!std::isfinite(v) || places < 0 || places >= static_cast<int>(kPowers.size())) {
        return v;
    }
    const double scale = kPowers[static_cast<std::size_t>(places)];
    const double scaled = v * scale;
    if (std::abs(scaled) >= 0x1p52) {
        return v; // already finer than the places asked for can change
    }
    const double r = std::round(scaled) / scale;
    return r == 0 ? 0.0 : r;
}

double counter_reading(double inches) {
    return decimals(inches, 3);
}
double fine_length(double inches) {
    return decimals(inches, 5);
}
double time_s(double seconds) {
    return decimals(seconds, 6);
}
double angle_deg(double degrees) {
    return decimals(degrees, 4);
}

} // namespace parsons::cli
