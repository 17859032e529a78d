#include "axes/lead_screw_axis.hpp"

#include <algorithm>
#include <cmath>

namespace parsons::axes {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Time to cover distance D > 0 from speed u with acceleration a, or kNever.
double time_to_cover(double D, double u, double a) {
    if (D <= 0) {
        return 0; // on the boundary already: the crossing is now
    }
    if (a == 0) {
        return u > 0 ? D / u : kNever;
    }
    const double disc = u * u + 2 * a * D;
    if (disc < 0) {
        return kNever;
    }
    const double denom = u + std::sqrt(disc);
    return denom > 0 ? 2 * D / denom : kNever;
}

} // namespace

LeadScrewAxis::LeadScrewAxis(const AxisProfile& profile) : profile_(profile) {}

void LeadScrewAxis::command(int direction, int speed_position) {
    target_dir_ = direction >= 0 ? +1 : -1;
    target_u_ =
        speed_position >= 1 && speed_position <= 3
            ? profile_.speed_in_per_min.at(static_cast<std::size_t>(speed_position - 1)) / 60.0
            : 0.0;
    plan();
}

double LeadScrewAxis::accel_toward_target() const {
    if (target_u_ == 0) {
        return u_ > 0 ? -profile_.braking_in_per_s2 : 0.0;
    }
    if (u_ > 0 && d_ != target_dir_) {
        return -profile_.acceleration_in_per_s2; // slow to rest before reversing
    }
    if (u_ < target_u_) {
        return profile_.acceleration_in_per_s2;
    }
    if (u_ > target_u_) {
        return -profile_.acceleration_in_per_s2;
    }
    return 0.0;
}

void LeadScrewAxis::plan() {
    if (u_ == 0 && target_u_ > 0) {
        d_ = target_dir_;
    }
    a_ = accel_toward_target();
    // Where the phase ends: at the target speed, or at rest when braking or reversing.
    double end_speed = target_u_;
    if (target_u_ == 0 || d_ != target_dir_) {
        end_speed = 0;
    }
    phase_end_ = a_ == 0 ? kNever : t_ + (end_speed - u_) / a_;
    // Next half-thousandth crossing in the direction of motion.
    const double boundary = (static_cast<double>(k_) + 0.5 * d_) * kInchesPerImpulse;
    const double D = std::max(0.0, (boundary - s_) * d_);
    const double tau = (u_ == 0 && a_ <= 0) ? kNever : time_to_cover(D, u_, a_);
    const double impulse_time = t_ + tau;
    if (impulse_time <= phase_end_) {
        next_time_ = impulse_time;
        next_is_impulse_ = true;
    } else {
        next_time_ = phase_end_;
        next_is_impulse_ = false;
    }
}

std::optional<Impulse> LeadScrewAxis::advance_to(double t) {
    const bool arriving = t >= next_time_;
    if (t <= t_ && !arriving) {
        return std::nullopt;
    }
    if (arriving) {
        t = next_time_;
    }
    const double tau = std::max(0.0, t - t_);
    s_ += d_ * (u_ * tau + 0.5 * a_ * tau * tau);
    u_ = std::max(0.0, u_ + a_ * tau);
    t_ = t;
    if (!arriving) {
        return std::nullopt;
    }
    if (!next_is_impulse_) {
        // End of a speed change: exactly at the target, or at rest.
        if (target_u_ == 0 || d_ != target_dir_) {
            u_ = 0;
        } else {
            u_ = target_u_;
        }
        plan();
        return std::nullopt;
    }
    s_ = (static_cast<double>(k_) + 0.5 * d_) * kInchesPerImpulse;
    k_ += d_;
    ++impulses_;
    Impulse impulse;
    impulse.direction = d_;
    // Commutators 100, 98, 96 close when the crossing also crosses a 0.01, 0.1 or 1 in
    // boundary: the crossing lies between readings upper - 1 and upper, and it passes such a
    // boundary exactly when upper is a whole number of hundredths, tenths or inches.
    const long upper = d_ > 0 ? k_ : k_ + 1;
    auto multiple_of = [upper](long unit) { return upper % unit == 0; }; // also for upper < 0
    impulse.hundredths = multiple_of(10);
    impulse.tenths = multiple_of(100);
    impulse.inches = multiple_of(1000);
    plan();
    return impulse;
}

double LeadScrewAxis::real_in() const {
    return with_screw_error(s_);
}

double LeadScrewAxis::real_in_at(double t) const {
    const double tau = std::clamp(t, t_, std::max(t_, next_time_)) - t_;
    return with_screw_error(s_ + d_ * (u_ * tau + 0.5 * a_ * tau * tau));
}

double LeadScrewAxis::with_screw_error(double s) const {
    const auto& table = profile_.screw_error_in;
    if (table.empty()) {
        return s;
    }
    if (s <= table.front().first) {
        return s + table.front().second;
    }
    if (s >= table.back().first) {
        return s + table.back().second;
    }
    auto it = std::upper_bound(table.begin(), table.end(), s,
                               [](double x, const auto& p) { return x < p.first; });
    const auto& [x1, e1] = *it;
    const auto& [x0, e0] = *(it - 1);
    return s + e0 + (e1 - e0) * (s - x0) / (x1 - x0);
}

bool LeadScrewAxis::beyond_limits() const {
    const double x = real_in();
    return x < profile_.travel_min_in || x > profile_.travel_max_in;
}

double LeadScrewAxis::fixture_angle_deg(bool sine_plate) const {
    const double ratio = (real_in() - profile_.level_in) / profile_.pivot_to_screw_in;
    const double radians = sine_plate ? std::asin(std::clamp(ratio, -1.0, 1.0)) : std::atan(ratio);
    return radians * 180.0 / kPi;
}

} // namespace parsons::axes
