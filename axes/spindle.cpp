// Spindle motor 27, encoder 32, gear unit 30 and head 31 of EP 0360190 Figs. 1 and 3
// (axes/spindle.hpp says what each does and how we represent it).
//
//   rpm
//    +240 |      ____________                 commanded +240, then -240 at t1:
//         |     /            \                  run-up at run_up_rpm_per_s,
//         |    /              \                 run-down at run_down_rpm_per_s to rest
//       0 +---/----------------\------------    (a boundary at zero speed),
//         |  t0                t1\       /      then run-up the other way
//    -240 |                       \_____/
//
// Between two boundaries the speed changes at one constant rate a (rev/min per second), so the
// angle is a quadratic in the time since the segment began:
//
//     phi(tau) = phi0 + tau (w0 + a tau / 2) / 60        (w0 in rev/min, phi in revolutions)
//
// and each segment turns one way only (a reversal is two segments, meeting at rest). Edge m of
// encoder 32 stands at m / ppr revolutions; its time is the smaller root of the quadratic,
// computed from the segment's start and m alone, so the same double whether the edges before it
// were taken one by one or skipped. With D = 60 |m / ppr - phi0|, W = |w0| and A = a in the
// sense of motion, the root is written so that every step rounds monotonically in D (edge times
// never run backwards, however the roundings fall):
//
//     A = 0:  tau = D / W
//     A > 0:  tau = (sqrt(W^2 + 2 A D) - W) / A           (running up)
//     A < 0:  tau = (W - sqrt(W^2 - 2 |A| D)) / |A|       (running down; the root under it is
//                                                          held at 0 or more)
//
// The loss of digits in the differences is a loss in absolute time of an ulp of the segment's
// length, nothing more. Every edge time is held within the segment [t0, end].
//
// The boundary rule is the press's (axes/press.cpp): an edge that falls exactly on a segment's
// end belongs to that segment, taken first (at the end's time, or a rounding earlier); then the
// boundary begins the next segment with the count already past it. The only edge at a segment's
// very start is one the motor stands exactly on as it starts backwards: count = floor(phi x ppr)
// already stands on it, so it is taken at once (count m - 1).
//
// The lasting change: from change_at_s the target is change_factor x the commanded speed, and
// change_at_s is a boundary of every segment that spans it, unless the motor stands commanded to
// stand (then nothing changes there, and the next command finds the change already come).
//
// Emulation note: the motor changes speed at two constant rates (its torque less the load's,
// taken as constant), with no jerk and no slip; the seed gives motor 27 a speed S and says
// nothing of how it gets there. The rates are the profile's run_up_rpm_per_s and
// run_down_rpm_per_s.
#include "axes/spindle.hpp"

#include "axes/state_json.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <string>

namespace parsons::axes {
namespace {

constexpr double kSecondsPerMinute = 60.0;
// More edges than any run takes (9999 rev/min, 9999 edges a revolution, for 30 years): an
// unending segment's edge index stays far from overflow.
constexpr std::int64_t kMostEdges = 1000000000000000000LL;

int sign_of(double x) {
    return x > 0 ? +1 : (x < 0 ? -1 : 0);
}

// The value within [min(a, b), max(a, b)] nearest to v.
double between(double v, double a, double b) {
    return std::clamp(v, std::min(a, b), std::max(a, b));
}

} // namespace

Spindle::Spindle(const SpindleSyncProfile& profile)
    : profile_(profile), ppr_(profile.encoder_pulses_per_rev) {
    start_segment(0, 0, 0);
    mount(profile_.first_tool);
}

// ---- Motor 27: the segments ----

bool Spindle::changed_at(double t) const {
    return profile_.change_at_s && t >= *profile_.change_at_s;
}

Spindle::Segment Spindle::segment_from(double t0, double phi0, double rpm0) const {
    const double target = commanded_rpm_ * (changed_at(t0) ? profile_.change_factor : 1.0);
    const double up = profile_.run_up_rpm_per_s;
    const double down = profile_.run_down_rpm_per_s;
    Segment s;
    s.end_rpm = target;
    if (rpm0 != target) {
        const bool same_way = sign_of(target) == sign_of(rpm0);
        if (rpm0 != 0 && !(same_way && std::abs(target) > std::abs(rpm0))) {
            // Running down: to the lower speed the same way, or to rest (stop, reversal).
            s.end_rpm = same_way ? target : 0.0;
            s.a_rpm_per_s = rpm0 > 0 ? -down : down;
            s.end_t = t0 + (std::abs(rpm0) - std::abs(s.end_rpm)) / down;
        } else {
            s.a_rpm_per_s = target > 0 ? up : -up;
            s.end_t = t0 + (std::abs(target) - std::abs(rpm0)) / up;
        }
    }
    // The lasting change ends the segment that spans it (unless the motor stands, commanded
    // to stand). A change exactly at the ramp's end leaves the ramp's end speed as it is.
    const bool resting = rpm0 == 0 && commanded_rpm_ == 0;
    if (profile_.change_at_s && !changed_at(t0) && !resting && *profile_.change_at_s < s.end_t) {
        s.end_t = *profile_.change_at_s;
        s.end_rpm = between(rpm0 + s.a_rpm_per_s * (s.end_t - t0), rpm0, s.end_rpm);
    }
    s.sense = rpm0 != 0 ? sign_of(rpm0) : sign_of(s.a_rpm_per_s);
    if (s.sense == 0) {
        s.end_revs = phi0; // standing
    } else if (s.end_t == kNever) {
        s.end_revs = s.sense * kNever; // turning steadily for good
    } else {
        const double tau = s.end_t - t0;
        s.end_revs = phi0 + tau * (rpm0 + s.a_rpm_per_s * tau / 2) / kSecondsPerMinute;
    }
    return s;
}

void Spindle::start_segment(double t0, double phi0, double rpm0) {
    seg_t0_ = t0;
    seg_phi0_ = phi0;
    seg_rpm0_ = rpm0;
    seg_ = segment_from(t0, phi0, rpm0);
    plan_pulse();
}

void Spindle::command_rpm(double rpm) {
    if (rpm == commanded_rpm_) {
        return;
    }
    const double rpm_now = rpm_at(t_);
    commanded_rpm_ = rpm;
    start_segment(t_, phi_, rpm_now);
}

// ---- Encoder 32's edges ----

bool Spindle::in_segment(std::int64_t m) const {
    // The boundary rule: an edge on the segment's end belongs to the segment.
    return seg_.sense > 0   ? edge_revs(m) <= seg_.end_revs
           : seg_.sense < 0 ? edge_revs(m) >= seg_.end_revs
                            : false;
}

std::int64_t Spindle::edges_left() const {
    if (seg_.sense == 0) {
        return 0;
    }
    if (std::isinf(seg_.end_revs)) {
        return std::numeric_limits<std::int64_t>::max();
    }
    if (seg_.sense > 0) {
        auto last = static_cast<std::int64_t>(std::floor(seg_.end_revs * ppr_));
        while (in_segment(last + 1)) {
            ++last;
        }
        while (!in_segment(last)) {
            --last;
        }
        return std::max(std::int64_t{0}, last - count_);
    }
    auto lowest = static_cast<std::int64_t>(std::ceil(seg_.end_revs * ppr_));
    while (in_segment(lowest - 1)) {
        --lowest;
    }
    while (!in_segment(lowest)) {
        ++lowest;
    }
    return std::max(std::int64_t{0}, count_ - lowest + 1);
}

double Spindle::edge_time(std::int64_t m) const {
    const int s = seg_.sense;
    const double d = std::max(0.0, s * (edge_revs(m) - seg_phi0_)) * kSecondsPerMinute;
    const double w = s * seg_rpm0_;
    const double a = s * seg_.a_rpm_per_s;
    double tau = 0;
    if (a == 0) {
        tau = d / w;
    } else if (a > 0) {
        tau = (std::sqrt(w * w + 2 * a * d) - w) / a;
    } else {
        tau = (w - std::sqrt(std::max(0.0, w * w - 2 * -a * d))) / -a;
    }
    return std::clamp(seg_t0_ + tau, seg_t0_, seg_.end_t);
}

double Spindle::pulse_time(std::int64_t n) const {
    if (seg_.sense == 0 || n < 1 || n > kMostEdges || n > edges_left()) {
        return kNever;
    }
    return edge_time(edge_index(n));
}

void Spindle::plan_pulse() {
    const double t = pulse_time(1);
    next_is_pulse_ = t != kNever;
    next_time_ = next_is_pulse_ ? t : seg_.end_t;
}

std::int64_t Spindle::pulses_by(double t) const {
    if (!next_is_pulse_ || t < next_time_) {
        return 0;
    }
    const std::int64_t left = edges_left();
    if (t >= seg_.end_t) {
        return left; // every edge of the segment (unending: more than any run takes)
    }
    // A first guess from the angle at t, then put right on the edge times themselves.
    const double phi = revs_formula(t);
    const double guess = seg_.sense > 0 ? std::floor(phi * ppr_) - static_cast<double>(count_)
                                        : static_cast<double>(count_) - std::ceil(phi * ppr_) + 1;
    const double most = static_cast<double>(std::min(left, kMostEdges));
    std::int64_t n = static_cast<std::int64_t>(std::clamp(guess, 1.0, most));
    while (n < left && pulse_time(n + 1) <= t) {
        ++n;
    }
    while (n > 0 && pulse_time(n) > t) {
        --n;
    }
    return n;
}

DetectorEdge Spindle::take_edge(std::int64_t m, double t) {
    t_ = t;
    phi_ = edge_revs(m);
    count_ = seg_.sense > 0 ? m : m - 1;
    plan_pulse();
    return phases_at(count_);
}

DetectorEdge Spindle::skip_pulses(std::int64_t n) {
    const double t = pulse_time(n);
    assert(t != kNever && "skip_pulses: fewer than n edges left in this segment");
    if (t == kNever) {
        return phases_at(count_);
    }
    return take_edge(edge_index(n), t);
}

std::optional<DetectorEdge> Spindle::advance_to(double t) {
    if (next_time_ != kNever && t >= next_time_) {
        if (next_is_pulse_) {
            return take_edge(edge_index(1), next_time_);
        }
        t_ = seg_.end_t;
        phi_ = seg_.end_revs;
        start_segment(t_, phi_, seg_.end_rpm);
        return std::nullopt;
    }
    if (t > t_ && t != kNever) {
        if (seg_.sense != 0) {
            // Never past the next event's angle (its time has not come).
            const double next = next_is_pulse_ ? edge_revs(edge_index(1)) : seg_.end_revs;
            phi_ = between(revs_formula(t), phi_, next);
        }
        t_ = t;
    }
    return std::nullopt;
}

// ---- Where the motor and the tool stand ----

double Spindle::revs_formula(double t) const {
    const double tau = t - seg_t0_;
    return seg_phi0_ + tau * (seg_rpm0_ + seg_.a_rpm_per_s * tau / 2) / kSecondsPerMinute;
}

double Spindle::motor_revs() const {
    return phi_;
}

double Spindle::motor_revs_at(double t) const {
    if (t == t_ || seg_.sense == 0) {
        return phi_; // where it stands (standing, phi_ is the segment's start)
    }
    const double within = std::clamp(t, seg_t0_, seg_.end_t);
    return between(revs_formula(within), seg_phi0_, seg_.end_revs);
}

double Spindle::rpm() const {
    return rpm_at(t_);
}

double Spindle::rpm_at(double t) const {
    if (t >= seg_.end_t) {
        return seg_.end_rpm;
    }
    if (t <= seg_t0_) {
        return seg_rpm0_;
    }
    return between(seg_rpm0_ + seg_.a_rpm_per_s * (t - seg_t0_), seg_rpm0_, seg_.end_rpm);
}

bool Spindle::at_rest() const {
    return commanded_rpm_ == 0 && rpm() == 0;
}

// ---- Gear unit 30 and head 31 ----

void Spindle::mount(int tool) {
    mount_tool_revs_ = tool_revs();
    mount_phi_ = phi_;
    const SpindleHead* head = profile_.head(tool);
    tool_ = head != nullptr ? tool : 0;
    ratio_ = head != nullptr ? head->ratio : 0.0;
}

double Spindle::tool_revs() const {
    return mount_tool_revs_ + (phi_ - mount_phi_) * ratio_;
}

double Spindle::tool_revs_at(double t) const {
    return mount_tool_revs_ + (motor_revs_at(t) - mount_phi_) * ratio_;
}

// ---- Saved state ----

nlohmann::json Spindle::save() const {
    return nlohmann::json{{"t", exact(t_)},
                          {"revs", exact(phi_)},
                          {"count", count_},
                          {"commanded_rpm", exact(commanded_rpm_)},
                          {"t0", exact(seg_t0_)},
                          {"revs0", exact(seg_phi0_)},
                          {"rpm0", exact(seg_rpm0_)},
                          {"a_rpm_per_s", exact(seg_.a_rpm_per_s)},
                          {"segment_end_t", exact(seg_.end_t)},
                          {"segment_end_revs", exact(seg_.end_revs)},
                          {"segment_end_rpm", exact(seg_.end_rpm)},
                          {"next_time", exact(next_time_)},
                          {"next_is_pulse", next_is_pulse_},
                          {"tool", tool_},
                          {"mount_revs", exact(mount_phi_)},
                          {"mount_tool_revs", exact(mount_tool_revs_)}};
}

void Spindle::load(const nlohmann::json& j) {
    Spindle s = *this; // this spindle is changed only if the whole state is good
    s.t_ = exact(member(j, "t"));
    s.phi_ = exact(member(j, "revs"));
    s.count_ = read<std::int64_t>(j, "count");
    s.commanded_rpm_ = exact(member(j, "commanded_rpm"));
    s.seg_t0_ = exact(member(j, "t0"));
    s.seg_phi0_ = exact(member(j, "revs0"));
    s.seg_rpm0_ = exact(member(j, "rpm0"));
    Segment saved;
    saved.a_rpm_per_s = exact(member(j, "a_rpm_per_s"));
    saved.end_t = exact(member(j, "segment_end_t"));
    saved.end_revs = exact(member(j, "segment_end_revs"));
    saved.end_rpm = exact(member(j, "segment_end_rpm"));
    s.next_time_ = exact(member(j, "next_time"));
    s.next_is_pulse_ = read<bool>(j, "next_is_pulse");
    s.tool_ = read<int>(j, "tool");
    s.mount_phi_ = exact(member(j, "mount_revs"));
    s.mount_tool_revs_ = exact(member(j, "mount_tool_revs"));
    auto fail = [](const std::string& what) { throw StateError("spindle: " + what); };
    for (const double v : {s.t_, s.phi_, s.commanded_rpm_, s.seg_t0_, s.seg_phi0_, s.seg_rpm0_,
                           s.mount_phi_, s.mount_tool_revs_}) {
        if (!std::isfinite(v)) {
            fail("times, angles and speeds must be finite");
        }
    }
    // The segment must be the one this profile gives from where it starts.
    s.seg_ = s.segment_from(s.seg_t0_, s.seg_phi0_, s.seg_rpm0_);
    if (s.seg_.a_rpm_per_s != saved.a_rpm_per_s || s.seg_.end_t != saved.end_t ||
        s.seg_.end_revs != saved.end_revs || s.seg_.end_rpm != saved.end_rpm) {
        fail("the segment does not follow from the spindle profile");
    }
    if (!(s.seg_t0_ <= s.t_ && s.t_ <= s.seg_.end_t)) {
        fail("the time lies outside its segment");
    }
    const bool within = s.seg_.sense == 0 ? s.phi_ == s.seg_phi0_
                                          : between(s.phi_, s.seg_phi0_, s.seg_.end_revs) == s.phi_;
    if (!within || !(s.edge_revs(s.count_) <= s.phi_ && s.phi_ <= s.edge_revs(s.count_ + 1))) {
        fail("the motor's angle lies outside its segment or off its encoder count");
    }
    const SpindleHead* head = profile_.head(s.tool_);
    if (s.tool_ != 0 && head == nullptr) {
        fail("tool " + std::to_string(s.tool_) + " is on no head of the profile");
    }
    s.ratio_ = head != nullptr ? head->ratio : 0.0;
    const bool is_pulse = s.next_is_pulse_;
    const double next = s.next_time_;
    s.plan_pulse();
    if (s.next_is_pulse_ != is_pulse || s.next_time_ != next || !(next >= s.t_)) {
        fail("the next event does not follow from the segment");
    }
    *this = s;
}

} // namespace parsons::axes
