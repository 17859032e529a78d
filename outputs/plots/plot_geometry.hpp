// The page geometry the chart of run --plot shares between its parts: the five lead-screw
// panels (plot_chart.cpp) and the lanes of the additions under them (plot_lanes.hpp: the
// press's, the spindle's) stand on one time axis, so they share its margins, its scale and its
// round ticks.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace parsons::cli::plot {

constexpr double kWidth = 1100;
constexpr double kLeft = 86;           // the plot area, px
constexpr double kRight = kWidth - 92; // leaves room for the speed scale

constexpr const char* kStopColour = "#d62728";
constexpr const char* kCardColour = "#9a9a9a";
constexpr const char* kGridColour = "#e4e4e4";
constexpr const char* kTextColour = "#222222";

// A linear map from data to page coordinates.
struct Scale {
    double d0, d1, p0, p1;
    double operator()(double v) const { return p0 + (v - d0) * (p1 - p0) / (d1 - d0); }
};

struct Ticks {
    std::vector<double> values;
    int decimals = 0;
};

// Round steps of 1, 2, 2.5 or 5 times a power of ten, about `target` of them over [lo, hi].
inline Ticks nice_ticks(double lo, double hi, int target) {
    Ticks ticks;
    const double raw = (hi - lo) / target;
    if (!(raw > 0) || !std::isfinite(raw)) {
        ticks.values.push_back(lo);
        return ticks;
    }
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = 10 * magnitude;
    double multiple = 10;
    for (double m : {1.0, 2.0, 2.5, 5.0}) {
        if (m * magnitude >= raw * 0.999) {
            step = m * magnitude;
            multiple = m;
            break;
        }
    }
    ticks.decimals =
        std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9))) + (multiple == 2.5);
    for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + step * 1e-9; k += 1) {
        const double v = k * step;
        ticks.values.push_back(std::fabs(v) < step * 1e-9 ? 0.0 : v);
    }
    return ticks;
}

} // namespace parsons::cli::plot
