#include "axes/lead_screw_axis.hpp"

#include "axes/state_json.hpp"

#include <algorithm>
#include <cmath>

namespace parsons::axes {
namespace {

constexpr double kPi = 3.14159265358979323846;

} // namespace

LeadScrewAxis::LeadScrewAxis(const AxisProfile& profile) : profile_(profile) {
    set_limit_range();
    last_h_ = std::clamp(1L, h_lo_, std::max(h_lo_, h_hi_));
    start_phase(0);
}

void LeadScrewAxis::set_limit_range() {
    // The crossings inside the travel limits, found by bisection (the part's position is
    // monotonic in the screw's): h = 2m + 1.
    auto real = [this](long m) { return with_screw_error(crossing_in(2 * m + 1)) + slip_in_; };
    constexpr long kFar = 1L << 40;
    long lo = -kFar; // smallest m inside the lower limit
    long hi = kFar;
    while (lo < hi) {
        const long mid = floor_div(lo + hi, 2);
        if (real(mid) >= profile_.travel_min_in) {
            hi = mid;
        } else {
            lo = mid + 1;
        }
    }
    h_lo_ = 2 * lo + 1;
    lo = -kFar; // largest m inside the upper limit
    hi = kFar;
    while (lo < hi) {
        const long mid = floor_div(lo + hi + 1, 2);
        if (real(mid) <= profile_.travel_max_in) {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    h_hi_ = 2 * lo + 1;
}

void LeadScrewAxis::slip() {
    slip_in_ -= d_ * kInchesPerImpulse;
    --slip_left_;
    set_limit_range();
}

void LeadScrewAxis::command(int direction, int speed_position) {
    const int dir = direction >= 0 ? +1 : -1;
    const int speed = speed_position >= 1 && speed_position <= 3 ? speed_position : 0;
    if (speed == target_speed_ && (speed == 0 || dir == target_dir_)) {
        target_dir_ = dir;
        return; // the motor is already doing this: the phase goes on unchanged
    }
    const double u = speed_in_per_s(); // the speed now, before the target changes
    target_dir_ = dir;
    target_speed_ = speed;
    target_u_ =
        speed > 0 ? profile_.speed_in_per_min.at(static_cast<std::size_t>(speed - 1)) / 60.0 : 0.0;
    start_phase(u);
}

double LeadScrewAxis::accel_toward_target(double u) const {
    if (target_u_ == 0) {
        return u > 0 ? -profile_.braking_in_per_s2 : 0.0;
    }
    if (u > 0 && d_ != target_dir_) {
        return -profile_.acceleration_in_per_s2; // slow to rest before reversing
    }
    if (u < target_u_) {
        return profile_.acceleration_in_per_s2;
    }
    if (u > target_u_) {
        return -profile_.acceleration_in_per_s2;
    }
    return 0.0;
}

double LeadScrewAxis::phase_end_speed() const {
    return target_u_ == 0 || d_ != target_dir_ ? 0.0 : target_u_;
}

void LeadScrewAxis::start_phase(double u) {
    t0_ = t_;
    s0_ = s_;
    u0_ = u;
    if (u == 0 && target_u_ > 0) {
        d_ = target_dir_;
    }
    a_ = accel_toward_target(u);
    // Where the phase ends: at the target speed, or at rest when braking or reversing.
    phase_end_ = a_ == 0 ? kNever : t0_ + (phase_end_speed() - u0_) / a_;
    if (a_ == 0 && u0_ > 0) {
        // t0 + ((k + d/2) 0.001 - s0) d / u, as a + b k.
        time_per_index_ = d_ * kInchesPerImpulse / u0_;
        time_at_index0_ = t0_ + (0.5 * d_ * kInchesPerImpulse - s0_) * d_ / u0_;
    }
    plan_impulse();
}

void LeadScrewAxis::advance_slowly(double t) {
    if (t >= next_time_) {
        // End of a speed change: exactly at the target, or at rest. If the screw already
        // stands at that instant (an impulse came at the very moment the speed change ends),
        // it keeps the place the impulse gave it: the state at one instant never depends on
        // the order in which that instant's events reached the plant.
        if (phase_end_ > t_) {
            t_ = phase_end_;
            s_ = position_at(phase_end_);
        }
        start_phase(phase_end_speed());
        return;
    }
    if (t > t_) {
        t_ = t;
        s_ = position_at(t);
    }
}

double LeadScrewAxis::impulse_time(long n) const {
    return boundary_time(k_ + d_ * (n - 1));
}

long LeadScrewAxis::impulses_by(double t) const {
    if (!next_is_impulse_ || next_time_ > t) {
        return 0;
    }
    const double tau = std::min(t, phase_end_) - t0_;
    const double covered = u0_ * tau + 0.5 * a_ * tau * tau;
    const double first = ((static_cast<double>(k_) + 0.5 * d_) * kInchesPerImpulse - s0_) * d_;
    const double estimate = std::floor((covered - first) / kInchesPerImpulse) + 1;
    long n = estimate >= 1 && estimate < 1e15 ? static_cast<long>(estimate) : 1;
    while (n > 1 && impulse_time(n) > t) {
        --n;
    }
    while (impulse_time(n + 1) <= t) {
        ++n;
    }
    return n;
}

void LeadScrewAxis::skip_impulses(long n) {
    t_ = impulse_time(n);
    k_ += d_ * (n - 1); // the last one is taken as any impulse is
    next_time_ = t_;
    take_impulse();
    impulses_ += n - 1;
}

long LeadScrewAxis::impulses_to_limit() const {
    const long h1 = 2 * k_ + d_;
    if (h1 < h_lo_ || h1 > h_hi_) {
        return 1;
    }
    if (d_ > 0) {
        return (h_hi_ - 1) / 2 - k_ + 2;
    }
    return k_ - (h_lo_ - 1) / 2 + 1;
}

double LeadScrewAxis::position_at(double t) const {
    const double tau = std::min(t, phase_end_) - t0_;
    return s0_ + d_ * (u0_ * tau + 0.5 * a_ * tau * tau);
}

double LeadScrewAxis::speed_in_per_s() const {
    // At or past the end of a speed change the speed is the target itself, not u0 + a tau
    // rounded: so a command at that instant starts from the same speed whether or not the
    // phase's end was taken first (the fuzz finding of issue 11).
    if (t_ >= phase_end_) {
        return phase_end_speed();
    }
    return std::max(0.0, u0_ + a_ * (t_ - t0_));
}

double LeadScrewAxis::real_in() const {
    return with_screw_error(s_) + slip_in_;
}

double LeadScrewAxis::real_in_at(double t) const {
    if (t <= t_) {
        return real_in();
    }
    return with_screw_error(position_at(std::min(t, next_time_))) + slip_in_;
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

double LeadScrewAxis::fixture_angle_deg(bool sine_plate) const {
    const double ratio = (real_in() - profile_.level_in) / profile_.pivot_to_screw_in;
    const double radians = sine_plate ? std::asin(std::clamp(ratio, -1.0, 1.0)) : std::atan(ratio);
    return radians * 180.0 / kPi;
}

nlohmann::json LeadScrewAxis::save() const {
    return nlohmann::json{{"t0", exact(t0_)},
                          {"s0", exact(s0_)},
                          {"u0", exact(u0_)},
                          {"a", exact(a_)},
                          {"d", d_},
                          {"phase_end", exact(phase_end_)},
                          {"time_at_index0", exact(time_at_index0_)},
                          {"time_per_index", exact(time_per_index_)},
                          {"t", exact(t_)},
                          {"screw_in", exact(s_)},
                          {"k", k_},
                          {"last_h", last_h_},
                          {"target_dir", target_dir_},
                          {"target_speed", target_speed_},
                          {"target_u", exact(target_u_)},
                          {"next_time", exact(next_time_)},
                          {"next_is_impulse", next_is_impulse_},
                          {"impulses", impulses_},
                          {"slip_from", slip_from_},
                          {"slip_left", slip_left_},
                          {"slip_in", exact(slip_in_)},
                          {"real_in", exact(real_in())}};
}

void LeadScrewAxis::load(const nlohmann::json& j) {
    t0_ = exact(member(j, "t0"));
    s0_ = exact(member(j, "s0"));
    u0_ = exact(member(j, "u0"));
    a_ = exact(member(j, "a"));
    d_ = read<int>(j, "d") >= 0 ? +1 : -1;
    phase_end_ = exact(member(j, "phase_end"));
    time_at_index0_ = exact(member(j, "time_at_index0"));
    time_per_index_ = exact(member(j, "time_per_index"));
    t_ = exact(member(j, "t"));
    s_ = exact(member(j, "screw_in"));
    k_ = read<long>(j, "k");
    last_h_ = read<long>(j, "last_h");
    target_dir_ = read<int>(j, "target_dir") >= 0 ? +1 : -1;
    target_speed_ = read<int>(j, "target_speed");
    target_u_ = exact(member(j, "target_u"));
    next_time_ = exact(member(j, "next_time"));
    next_is_impulse_ = read<bool>(j, "next_is_impulse");
    impulses_ = read<long>(j, "impulses");
    slip_from_ = read<long>(j, "slip_from");
    slip_left_ = read<long>(j, "slip_left");
    slip_in_ = exact(member(j, "slip_in"));
    if (target_speed_ < 0 || target_speed_ > 3) {
        throw StateError("target_speed must be 0..3");
    }
    set_limit_range();
}

} // namespace parsons::axes
