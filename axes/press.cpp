// The rotary press of EP 0436887 Fig. 1A: motor 22, crank 21, die 20, detector 10
// (axes/press.hpp says what each does and how we represent it).
//
//            crank 21 (theta: 0 = top dead centre, turning forward)
//      0 +-----------+-------+----------+----------+ 360 (next revolution: drift, variation)
//        |   w       | w(1-s)|    w     |  w x f   |
//        +-----------+-------+----------+----------+
//                 pressing_from  pressing_to  change (lasting)      ... stop: w = 0 for good
//
// Between two boundaries the crank turns at one speed, so the time of edge m (at m / ppd
// degrees) is t0 + (m / ppd - theta0) / w, computed from the segment's start alone: the same
// double whether the edges before it were taken one by one or skipped.
//
// The boundary rule: an edge that falls exactly on a segment's end belongs to that segment. It
// is taken first (at the boundary's time, or a rounding earlier), then the boundary begins the
// next segment with the count already past the edge; the next segment's first edge lies strictly
// beyond its start. The only edge at a segment's very start is the one a reverse run meets when
// it starts exactly on an edge: count = floor(theta x ppd) already stands on it, so it is taken
// at t = 0 (count m - 1).
//
// Turning backwards (profile.reverse) the speed is the same function of where the crank stands:
// crossing the interval [b_lo, b_hi) downwards it runs at speed_at(b_lo). Revolutions below the
// first count 0, -1, ... and take their drift and variation like any other. A change or a stop
// acts on the angles at and above its point, so a reverse run that starts at or past the stop
// stands from the start, and one that starts before it turns away from it and never stops.
//
// Emulation note: the speed changes at a boundary at once, with no run-up or run-down of the
// flywheel; motor 22 "stops" the crank dead at the stop point. The seed says only that the
// press's speed "may be variable"; a step is the simplest change that still has exact pulse
// times.
#include "axes/press.hpp"

#include "axes/state_json.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>

namespace parsons::axes {
namespace {

constexpr double kDegPerRev = 360.0;

// splitmix64 (Steele, Lea and Flood): a mixing function, so the variation of a revolution is a
// pure function of seed and revolution, with no generator state to save.
std::uint64_t splitmix64(std::uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30U)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27U)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31U);
}

// u in [-1, 1): the share of the variation revolution rev gets from this seed.
double variation_u(unsigned seed, std::int64_t rev) {
    const std::uint64_t x = splitmix64(splitmix64(seed) ^ static_cast<std::uint64_t>(rev));
    return static_cast<double>(x >> 11U) * 0x1.0p-52 - 1.0;
}

constexpr double kMostDrift = 0.5; // the drift's reach: half the nominal speed either way

// Revolution r starts at 360 (r - 1) degrees (exact for any r a run reaches).
double rev_start(std::int64_t r) {
    return kDegPerRev * static_cast<double>(r - 1);
}

// The revolution r with rev_start(r) <= theta < rev_start(r + 1), decided on the very products
// the boundaries are made of. theta / 360 is exact at a top dead centre and never falls below
// it past one (division rounds monotonically); the guard is for an angle just short of a top
// dead centre whose quotient rounds up to it (none below 200000 revolutions does).
std::int64_t revolution_of(double theta) {
    const std::int64_t r = static_cast<std::int64_t>(std::floor(theta / kDegPerRev)) + 1;
    return rev_start(r) > theta ? r - 1 : r;
}

} // namespace

DetectorEdge phases_at(std::int64_t count) {
    // Gray code of count mod 4: (A, B) = (0, 0), (1, 0), (1, 1), (0, 1).
    static constexpr std::array<int, 4> kA = {0, 1, 1, 0};
    static constexpr std::array<int, 4> kB = {0, 0, 1, 1};
    const auto q = static_cast<std::size_t>(((count % 4) + 4) % 4);
    return DetectorEdge{kA.at(q), kB.at(q), count};
}

Press::Press(const PressProfile& profile)
    : profile_(profile), ppd_(profile.pulses_per_degree), sense_(profile.reverse ? -1 : +1) {
    theta_ = profile.start_angle_deg;
    // count = floor(theta x ppd), decided on the same double edge angles m / ppd the pulses
    // use (theta x ppd alone can round across an edge either way).
    count_ = static_cast<std::int64_t>(std::floor(theta_ * ppd_));
    while (edge_angle(count_ + 1) <= theta_) {
        ++count_;
    }
    while (edge_angle(count_) > theta_) {
        --count_;
    }
    start_segment();
}

// ---- The speed and its boundaries ----

double Press::change_theta() const {
    return rev_start(profile_.change_cycle) + profile_.change_angle_deg;
}

double Press::stop_theta() const {
    return rev_start(profile_.stop_cycle) + profile_.stop_angle_deg;
}

double Press::speed_at(double theta) const {
    const PressProfile& p = profile_;
    if (p.stop_cycle > 0 && theta >= stop_theta()) {
        return 0;
    }
    const std::int64_t r = revolution_of(theta);
    double w = p.strokes_per_min * kDegPerRev / 60.0;
    // Drift per revolution turned, whichever the sense: turning backwards from revolution 1 the
    // crank enters 0, -1, ... (an exponent r - 1 there would make a slowing press race).
    // The drift accumulates up to half the nominal speed either way, where motor 22's governor
    // holds it (unbounded, a press would race to speeds no detector or register could follow).
    w *= std::clamp(std::pow(1.0 + p.drift_per_cycle, static_cast<double>(std::llabs(r - 1))),
                    1.0 - kMostDrift, 1.0 + kMostDrift);
    w *= 1.0 + p.variation * variation_u(p.seed, r);
    if (theta >= rev_start(r) + p.pressing_from_deg && theta < rev_start(r) + p.pressing_to_deg) {
        w *= 1.0 - p.pressing_slowdown;
    }
    if (p.change_cycle > 0 && theta >= change_theta()) {
        w *= p.change_factor;
    }
    return w;
}

double Press::boundary_from(double theta) const {
    double best = sense_ > 0 ? kNever : -kNever;
    auto consider = [&](double b) {
        if (sense_ > 0 ? (b > theta && b < best) : (b < theta && b > best)) {
            best = b;
        }
    };
    const std::int64_t r = revolution_of(theta);
    for (std::int64_t k = r - 1; k <= r + 1; ++k) {
        consider(rev_start(k));
        consider(rev_start(k) + profile_.pressing_from_deg);
        consider(rev_start(k) + profile_.pressing_to_deg);
    }
    if (profile_.change_cycle > 0) {
        consider(change_theta());
    }
    if (profile_.stop_cycle > 0) {
        consider(stop_theta());
    }
    return best;
}

Press::Segment Press::segment_from(double t0, double theta0) const {
    Segment s;
    s.end_theta = boundary_from(theta0);
    // Forward the crank crosses [theta0, end); backward [end, theta0): the speed of the
    // interval is speed_at of its lower end either way.
    const double speed = speed_at(sense_ > 0 ? theta0 : s.end_theta);
    if (!(speed > 0)) {
        return Segment{0, s.end_theta, kNever}; // motor 22 has stopped: the press stands
    }
    s.w = sense_ * speed;
    s.end_t = t0 + (s.end_theta - theta0) / s.w;
    return s;
}

void Press::start_segment() {
    t0_ = t_;
    theta0_ = theta_;
    const Segment s = segment_from(t0_, theta0_);
    w_ = s.w;
    seg_end_theta_ = s.end_theta;
    seg_end_t_ = s.end_t;
    stopped_ = w_ == 0;
    plan_pulse();
}

// ---- Detector 10's edges ----

bool Press::in_segment(std::int64_t m) const {
    // The boundary rule: an edge on the segment's end belongs to the segment.
    return sense_ > 0 ? edge_angle(m) <= seg_end_theta_ : edge_angle(m) >= seg_end_theta_;
}

std::int64_t Press::edges_left() const {
    if (stopped_ || held_) {
        return 0;
    }
    if (sense_ > 0) {
        auto last = static_cast<std::int64_t>(std::floor(seg_end_theta_ * ppd_));
        while (in_segment(last + 1)) {
            ++last;
        }
        while (!in_segment(last)) {
            --last;
        }
        return std::max(std::int64_t{0}, last - count_);
    }
    auto lowest = static_cast<std::int64_t>(std::ceil(seg_end_theta_ * ppd_));
    while (in_segment(lowest - 1)) {
        --lowest;
    }
    while (!in_segment(lowest)) {
        ++lowest;
    }
    return std::max(std::int64_t{0}, count_ - lowest + 1);
}

void Press::plan_pulse() {
    const double t = pulse_time(1);
    next_is_pulse_ = t != kNever;
    next_time_ = next_is_pulse_ ? t : seg_end_t_;
}

double Press::pulse_time(std::int64_t n) const {
    if (stopped_ || held_ || n < 1) {
        return kNever;
    }
    const std::int64_t m = edge_index(n);
    if (!in_segment(m)) {
        return kNever;
    }
    return t0_ + (edge_angle(m) - theta0_) / w_;
}

std::int64_t Press::pulses_by(double t) const {
    if (!next_is_pulse_ || t < next_time_) {
        return 0;
    }
    const std::int64_t left = edges_left();
    if (t >= seg_end_t_) {
        return left;
    }
    // A first guess from the angle at t, then put right on the pulse times themselves.
    const double theta = theta0_ + w_ * (t - t0_);
    const double guess = sense_ > 0 ? std::floor(theta * ppd_) - static_cast<double>(count_)
                                    : static_cast<double>(count_) - std::ceil(theta * ppd_) + 1;
    std::int64_t n = static_cast<std::int64_t>(std::clamp(guess, 1.0, static_cast<double>(left)));
    while (n < left && pulse_time(n + 1) <= t) {
        ++n;
    }
    while (n > 0 && pulse_time(n) > t) {
        --n;
    }
    return n;
}

DetectorEdge Press::take_edge(std::int64_t m, double t) {
    t_ = t;
    theta_ = edge_angle(m);
    count_ = sense_ > 0 ? m : m - 1;
    plan_pulse();
    return phases_at(count_);
}

DetectorEdge Press::skip_pulses(std::int64_t n) {
    const double t = pulse_time(n);
    assert(t != kNever && "skip_pulses: fewer than n edges left in this segment");
    if (t == kNever) {
        return phases_at(count_);
    }
    return take_edge(edge_index(n), t);
}

std::optional<DetectorEdge> Press::advance_to(double t) {
    if (next_time_ != kNever && t >= next_time_) {
        if (next_is_pulse_) {
            return take_edge(edge_index(1), next_time_);
        }
        t_ = seg_end_t_;
        theta_ = seg_end_theta_;
        start_segment();
        return std::nullopt;
    }
    if (t > t_ && t != kNever) {
        theta_ = theta_at(t);
        t_ = t;
    }
    return std::nullopt;
}

// ---- The feeder's interlock ----

void Press::hold(double t) {
    if (held_ || stopped_) {
        return;
    }
    assert(t < next_time_ && "hold: an event due by t not taken");
    advance_to(t);
    t0_ = t_;
    theta0_ = theta_;
    w_ = 0;
    seg_end_t_ = kNever;
    held_ = true;
    plan_pulse();
}

void Press::release(double t) {
    if (!held_) {
        return;
    }
    held_ = false;
    t_ = std::max(t, t_);
    start_segment();
}

double Press::theta_at(double t) const {
    if (w_ == 0) {
        return theta0_;
    }
    // Never past the next event's angle (its time has not come) nor before the segment's start.
    const double next = next_is_pulse_ ? edge_angle(edge_index(1)) : seg_end_theta_;
    const double theta = theta0_ + w_ * (t - t0_);
    return sense_ > 0 ? std::clamp(theta, theta0_, next) : std::clamp(theta, next, theta0_);
}

// ---- Where the crank and the die stand ----

double Press::theta_deg() const {
    return theta_;
}

double Press::angle_deg() const {
    const double a = theta_ - rev_start(revolution_of(theta_));
    return std::clamp(a, 0.0, std::nextafter(kDegPerRev, 0.0));
}

double Press::angle_deg_at(double t) const {
    const double theta = theta_at(t);
    const double a = theta - rev_start(revolution_of(theta));
    return std::clamp(a, 0.0, std::nextafter(kDegPerRev, 0.0));
}

int Press::revolution() const {
    return static_cast<int>(revolution_of(theta_));
}

double Press::die_height_in_at_angle(double a_deg) const {
    const double r = profile_.stroke_in / 2;
    const double L = profile_.rod_in;
    const double a = a_deg * std::numbers::pi / 180;
    const double s = std::sin(a);
    return r * std::cos(a) + std::sqrt(L * L - r * r * s * s) - (L - r);
}

std::optional<std::pair<double, double>> Press::angles_at_height(double h_in) const {
    const double stroke = profile_.stroke_in;
    if (!(h_in >= 0 && h_in <= stroke)) {
        return std::nullopt;
    }
    // The law of cosines in the triangle crank centre, crank pin, wrist pin: with the wrist pin
    // y = h + L - r above the centre, cos a = (y^2 + r^2 - L^2) / (2 y r). Through the half
    // angle, tan^2 (a / 2) = (1 - cos a) / (1 + cos a), whose factors do not cancel near the
    // dead centres:
    //   1 - cos a = (stroke - h)(h + 2 (L - r)) / (2 y r),  1 + cos a = h (h + 2 L) / (2 y r).
    const double r = stroke / 2;
    const double L = profile_.rod_in;
    const double one_minus_c = (stroke - h_in) * (h_in + 2 * (L - r)); // both x 2 y r
    const double one_plus_c = h_in * (h_in + 2 * L);
    const double down =
        2 * std::atan2(std::sqrt(one_minus_c), std::sqrt(one_plus_c)) * 180 / std::numbers::pi;
    // At the top (h = stroke) the way up ends at 360, the next top dead centre.
    return std::pair{down, kDegPerRev - down};
}

// ---- Saved state ----

nlohmann::json Press::save() const {
    return nlohmann::json{{"t", exact(t_)},
                          {"theta_deg", exact(theta_)},
                          {"count", count_},
                          {"t0", exact(t0_)},
                          {"theta0_deg", exact(theta0_)},
                          {"w_deg_per_s", exact(w_)},
                          {"segment_end_t", exact(seg_end_t_)},
                          {"segment_end_deg", exact(seg_end_theta_)},
                          {"next_time", exact(next_time_)},
                          {"next_is_pulse", next_is_pulse_},
                          {"stopped", stopped_},
                          {"held", held_}};
}

void Press::load(const nlohmann::json& j) {
    Press p = *this; // this press is changed only if the whole state is good
    p.t_ = exact(member(j, "t"));
    p.theta_ = exact(member(j, "theta_deg"));
    p.count_ = read<std::int64_t>(j, "count");
    p.t0_ = exact(member(j, "t0"));
    p.theta0_ = exact(member(j, "theta0_deg"));
    p.w_ = exact(member(j, "w_deg_per_s"));
    p.seg_end_t_ = exact(member(j, "segment_end_t"));
    p.seg_end_theta_ = exact(member(j, "segment_end_deg"));
    p.next_time_ = exact(member(j, "next_time"));
    p.next_is_pulse_ = read<bool>(j, "next_is_pulse");
    p.stopped_ = read<bool>(j, "stopped");
    // A state saved before the interlock existed: the press was not held.
    p.held_ = j.contains("held") && read<bool>(j, "held");
    auto fail = [](const std::string& what) { throw StateError("press: " + what); };
    if (!std::isfinite(p.t_) || !std::isfinite(p.theta_) || !std::isfinite(p.t0_) ||
        !std::isfinite(p.theta0_) || !std::isfinite(p.seg_end_theta_) || !(p.t0_ <= p.t_)) {
        fail("times and angles must be finite, with t0 <= t");
    }
    // The segment must be the one this profile gives from where it starts; a held crank
    // stands where the hold caught it, with no end.
    if (p.held_) {
        if (p.stopped_ || p.w_ != 0 || p.seg_end_t_ != kNever) {
            fail("a held press stands (speed 0, no segment end) and motor 22 runs");
        }
    } else {
        const Segment s = p.segment_from(p.t0_, p.theta0_);
        if (s.w != p.w_ || s.end_theta != p.seg_end_theta_ || s.end_t != p.seg_end_t_ ||
            p.stopped_ != (p.w_ == 0)) {
            fail("the segment does not follow from the press profile");
        }
    }
    const bool within = p.sense_ > 0 ? p.theta0_ <= p.theta_ && p.theta_ <= p.seg_end_theta_
                                     : p.seg_end_theta_ <= p.theta_ && p.theta_ <= p.theta0_;
    if ((p.stopped_ || p.held_ ? p.theta_ != p.theta0_ : !within) ||
        !(p.edge_angle(p.count_) <= p.theta_ && p.theta_ <= p.edge_angle(p.count_ + 1))) {
        fail("the crank angle lies outside its segment or off its pulse count");
    }
    const bool is_pulse = p.next_is_pulse_;
    const double next = p.next_time_;
    p.plan_pulse();
    if (p.next_is_pulse_ != is_pulse || p.next_time_ != next || !(next >= p.t_)) {
        fail("the next event does not follow from the segment");
    }
    *this = p;
}

} // namespace parsons::axes
