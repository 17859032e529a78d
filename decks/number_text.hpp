// Numbers in messages: the machine's own figures as fixed decimals, anything a person could
// not read that way (a chord of 1e300 inches, say) in engineering form, never 300 digits.
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <string>

namespace parsons::decks {

// fixed(2.5, 3) = "2.500"; fixed(7.92e305, 3) = "792.000e303"; fixed(NaN) = "nan".
inline std::string fixed(double v, int decimals = 3) {
    if (!std::isfinite(v) || std::abs(v) < 1e6) {
        return fmt::format("{:.{}f}", v, decimals);
    }
    // Engineering form: an exponent that is a multiple of three, 1 <= |mantissa| < 1000.
    int exponent = static_cast<int>(std::floor(std::log10(std::abs(v)) / 3)) * 3;
    double mantissa = v / std::pow(10.0, exponent);
    if (std::abs(mantissa) >= 999.9995) { // rounding would print 1000.000
        mantissa /= 1000;
        exponent += 3;
    }
    return fmt::format("{:.{}f}e{}", mantissa, decimals, exponent);
}

} // namespace parsons::decks
