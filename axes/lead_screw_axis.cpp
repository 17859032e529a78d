#include "axes/lead_screw_axis.hpp"

#include "axes/state_json.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace parsons::axes {
namespace {} // namespace

LeadScrewAxis::LeadScrewAxis(const AxisProfile& profile)
    : profile_(profile), nut_(profile.backlash_in, ScrewErrorTable(profile.lead_error_in)) {
    measure_by(MeasuringChain::instrument_shaft_74, false);
}

// Compensating cam 160, as the patent draws it: "a conventional compensating cam and nut
// arrangement may be provided for correcting the action of each screw so that the actual lead
// per revolution or fraction thereof is constant throughout its entire length. Such
// compensating means is schematically illustrated herein at 160 for the table lead screw 22.
// It is understood that the remaining lead screws may have similar provisions" (US 2,820,187,
// margin lines 54-61). So cam 160 corrects the main screw's lead: the part stands at
// G(sigma) = sigma + lead_error_in - cam_160_in, whichever chain counts. Through instrument
// shaft 74 that changes how far the screw turns for a count, not where the part stops.
// Under the interpretation cam_160_on_instrument_shaft the cam corrects shaft 74's screw
// instead (axes/instrument_shaft.hpp) and the main screw keeps its whole lead error.
void LeadScrewAxis::measure_by(MeasuringChain chain, bool cam_160_on_instrument_shaft) {
    chain_ = chain;
    const AxisProfile& p = profile_;
    const bool cam_on_shaft = cam_160_on_instrument_shaft && chain != MeasuringChain::screw_turns;
    cam_on_shaft_ = cam_on_shaft;
    shaft_ = InstrumentShaft(p, cam_on_shaft);
    if (chain == MeasuringChain::screw_turns) {
        // The counters read screw turns: the part stands off the screw by everything the
        // screw gets wrong, less what cam 160 corrects.
        nut_.set_part_table(ScrewErrorTable::sum(
            {{&p.screw_error_in, 1}, {&p.lead_error_in, 1}, {&p.cam_160_in, -1}}));
        linear_ = true;
        least_screw_per_impulse_ = kInchesPerImpulse;
        s_ = 0;
    } else {
        const ScrewErrorTable lead =
            cam_on_shaft ? ScrewErrorTable(p.lead_error_in)
                         : ScrewErrorTable::sum({{&p.lead_error_in, 1}, {&p.cam_160_in, -1}});
        linear_ = shaft_.exact() && lead.empty();
        nut_.set_part_table(lead);
        least_screw_per_impulse_ =
            kInchesPerImpulse * shaft_.least_part_per_reading() / nut_.greatest_part_per_screw();
        // The reference zero: where the counters read 0, the part stands at r(0).
        s_ = nut_.sigma_at_part(shaft_.part_at_reading(0));
    }
    nut_.reset_at(s_);
    set_limit_range();
    last_h_ = std::clamp(std::int64_t{1}, h_lo_, std::max(h_lo_, h_hi_));
    start_phase(0);
}

void LeadScrewAxis::set_limit_range() {
    // The crossings inside the travel limits, found by bisection (the part's position is
    // monotonic in the screw's): h = 2m + 1.
    auto real = [this](std::int64_t m) { return real_at_crossing(2 * m + 1); };
    constexpr std::int64_t kFar = std::int64_t{1} << 40;
    std::int64_t lo = -kFar; // smallest m inside the lower limit
    std::int64_t hi = kFar;
    while (lo < hi) {
        const std::int64_t mid = floor_div(lo + hi, 2);
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
        const std::int64_t mid = floor_div(lo + hi + 1, 2);
        if (real(mid) <= profile_.travel_max_in) {
            lo = mid;
        } else {
            hi = mid - 1;
        }
    }
    h_hi_ = 2 * lo + 1;
}

void LeadScrewAxis::begin_slip() {
    nut_.rebase(s_, d_, slip_len_in_);
    slip_len_in_ = 0;
    if (chain_ == MeasuringChain::screw_turns) {
        set_limit_range();
    }
    plan_constants();
}

void LeadScrewAxis::change_command(int dir, int speed) {
    const double u = speed_in_per_s(); // the speed now, before the target changes
    target_dir_ = dir;
    target_speed_ = speed;
    target_u_ =
        speed > 0 ? profile_.speed_in_per_min.at(static_cast<std::size_t>(speed - 1)) / 60.0 : 0.0;
    start_phase(u);
}

void LeadScrewAxis::command_follow(int direction, double speed, double acceleration) {
    const int dir = direction >= 0 ? +1 : -1;
    const double u_target = std::max(0.0, speed);
    if (target_speed_ == kFollowing && u_target == target_u_ && dir == target_dir_ &&
        acceleration == follow_accel_) {
        return;
    }
    const double u = speed_in_per_s();
    target_dir_ = dir;
    target_speed_ = kFollowing;
    target_u_ = u_target;
    follow_accel_ = acceleration;
    start_phase(u);
}

double LeadScrewAxis::accel_toward_target(double u) const {
    if (target_u_ == 0) {
        if (target_speed_ == kFollowing) {
            return u > 0 ? -follow_accel_ : 0.0; // the drive ramps down to a stand
        }
        return u > 0 ? -profile_.braking_in_per_s2 : 0.0;
    }
    const double accel =
        target_speed_ == kFollowing ? follow_accel_ : profile_.acceleration_in_per_s2;
    if (u > 0 && d_ != target_dir_) {
        return -accel; // slow to rest before reversing
    }
    if (u < target_u_) {
        return accel;
    }
    if (u > target_u_) {
        return -accel;
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
    // A new stretch of nut 78: the dead travel used so far is booked (nothing, if the screw
    // has not moved since the last stretch began).
    nut_.rebase(s_, d_);
    if (chain_ == MeasuringChain::screw_turns) {
        set_limit_range();
    }
    a_ = accel_toward_target(u);
    // Where the phase ends: at the target speed, or at rest when braking or reversing.
    phase_end_ = a_ == 0 ? kNever : t0_ + (phase_end_speed() - u0_) / a_;
    plan_constants();
    plan_impulse();
}

void LeadScrewAxis::plan_constants() {
    steady_ = a_ == 0 && u0_ > 0 && linear_;
    if (steady_) {
        // t0 + ((k + d/2) 0.001 + offset - s0) d / u, as a + b k.
        const double offset = chain_ == MeasuringChain::screw_turns ? 0.0 : nut_.o_end();
        time_per_index_ = d_ * kInchesPerImpulse / u0_;
        time_at_index0_ = t0_ + (0.5 * d_ * kInchesPerImpulse + offset - s0_) * d_ / u0_;
    }
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
    move_within_phase(t);
}

double LeadScrewAxis::impulse_time(std::int64_t n) const {
    return boundary_time(k_ + d_ * (n - 1));
}

std::int64_t LeadScrewAxis::impulses_by(double t) const {
    if (!next_is_impulse_ || next_time_ > t) {
        return 0;
    }
    // An estimate from what the counters would read then, made exact by the loops below.
    const double reading = reading_at_screw(position_at(std::min(t, phase_end_)));
    const double first = crossing_in(2 * k_ + d_);
    const double estimate = std::floor((reading - first) * d_ / kInchesPerImpulse) + 1;
    std::int64_t n = estimate >= 1 && estimate < 1e15 ? static_cast<std::int64_t>(estimate) : 1;
    while (n > 1 && impulse_time(n) > t) {
        --n;
    }
    while (impulse_time(n + 1) <= t) {
        ++n;
    }
    return n;
}

void LeadScrewAxis::skip_impulses(std::int64_t n) {
    t_ = impulse_time(n);
    k_ += d_ * (n - 1); // the last one is taken as any impulse is
    impulses_ += n - 1;
    next_time_ = t_;
    take_impulse();
}

std::int64_t LeadScrewAxis::impulses_to_limit() const {
    const std::int64_t h1 = 2 * k_ + d_;
    if (h1 < h_lo_ || h1 > h_hi_) {
        return 1;
    }
    if (d_ > 0) {
        return (h_hi_ - 1) / 2 - k_ + 2;
    }
    return k_ - (h_lo_ - 1) / 2 + 1;
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

// Through instrument shaft 74 the part stands at q + r(q) for the reading q, r the instrument's
// residual (axes/instrument_shaft.hpp); counting screw turns it stands at sigma + E(sigma), E
// everything screw 22 gets wrong, and sigma - s is the slip and the backlash taken up
// (axes/lead_screw_nut.hpp). The tables' figures add up to their sum exactly
// (ScrewErrorTable::sum interpolates on the union of the positions).
ChainFigures LeadScrewAxis::chain_figures() const {
    const AxisProfile& p = profile_;
    auto at = [](const ErrorPoints& t, double x) { return ScrewErrorTable(t).error_at(x); };
    ChainFigures f;
    f.counts_screw_turns = chain_ == MeasuringChain::screw_turns;
    if (f.counts_screw_turns) {
        const double sigma = nut_.sigma_at(s_);
        f.at_in = sigma;
        f.slip_in = nut_.slip_now_in(s_);
        f.backlash_in = (sigma - s_) - f.slip_in;
        f.lead_in = at(p.lead_error_in, sigma);
        f.cam_160_in = -at(p.cam_160_in, sigma);
    } else {
        f.at_in = shaft_.reading_at_part(real_in());
        f.instrument_in = at(p.instrument_error_in, f.at_in);
        if (cam_on_shaft_) {
            f.cam_160_in = -at(p.cam_160_in, f.at_in);
        }
    }
    f.screw_error_in = at(p.screw_error_in, f.at_in);
    return f;
}

double LeadScrewAxis::real_in() const {
    // On a crossing the part is where that crossing puts it (a function of h alone).
    if (has_crossing_ && s_ == last_crossing_s_) {
        return real_at_crossing(last_h_);
    }
    return nut_.part_at_screw(s_);
}

double LeadScrewAxis::real_in_at(double t) const {
    if (t <= t_) {
        return real_in();
    }
    return nut_.part_at_screw(position_at(std::min(t, next_time_)));
}

double fixture_angle_deg(const AxisProfile& profile, double real_in, bool sine_plate) {
    const double ratio = (real_in - profile.level_in) / profile.pivot_to_screw_in;
    const double radians = sine_plate ? std::asin(std::clamp(ratio, -1.0, 1.0)) : std::atan(ratio);
    return radians * 180.0 / std::numbers::pi;
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
                          {"follow_accel", exact(follow_accel_)},
                          {"next_time", exact(next_time_)},
                          {"next_is_impulse", next_is_impulse_},
                          {"impulses", impulses_},
                          {"slip_from", slip_from_},
                          {"slip_length", exact(slip_len_in_)},
                          {"last_crossing_s", exact(last_crossing_s_)},
                          {"has_crossing", has_crossing_},
                          {"nut_78", nut_.save()},
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
    steady_ = a_ == 0 && u0_ > 0 && linear_;
    t_ = exact(member(j, "t"));
    s_ = exact(member(j, "screw_in"));
    k_ = read<std::int64_t>(j, "k");
    last_h_ = read<std::int64_t>(j, "last_h");
    target_dir_ = read<int>(j, "target_dir") >= 0 ? +1 : -1;
    target_speed_ = read<int>(j, "target_speed");
    target_u_ = exact(member(j, "target_u"));
    follow_accel_ = j.contains("follow_accel") ? exact(j.at("follow_accel")) : 0.0;
    next_time_ = exact(member(j, "next_time"));
    next_is_impulse_ = read<bool>(j, "next_is_impulse");
    impulses_ = read<std::int64_t>(j, "impulses");
    slip_from_ = read<std::int64_t>(j, "slip_from");
    slip_len_in_ = exact(member(j, "slip_length"));
    last_crossing_s_ = exact(member(j, "last_crossing_s"));
    has_crossing_ = read<bool>(j, "has_crossing");
    nut_.load(member(j, "nut_78"));
    if (target_speed_ < 0 || target_speed_ > kFollowing ||
        (target_speed_ == kFollowing && !(follow_accel_ > 0))) {
        throw StateError("target_speed must be 0..3, or 4 (the follower drive) with its "
                         "follow_accel");
    }
    set_limit_range();
}

} // namespace parsons::axes
