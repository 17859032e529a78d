#include "relaylogic/contouring/interpolator.hpp"

#include <algorithm>
#include <cmath>

namespace parsons::relaylogic {

PathSegment make_segment(const Point3& from, const cardreader::SegmentOrder& order, int number,
                         std::int64_t card) {
    PathSegment s;
    s.number = number;
    s.card = card;
    s.from = from;
    double sum = 0;
    for (std::size_t i = 0; i < s.to.size(); ++i) {
        s.to[i] = order.to[i] / 1000.0;
        sum += (s.to[i] - from[i]) * (s.to[i] - from[i]);
    }
    s.length = std::sqrt(sum);
    for (std::size_t i = 0; i < s.to.size(); ++i) {
        s.unit[i] = s.length > 0 ? (s.to[i] - from[i]) / s.length : 0.0;
    }
    s.nominal = order.feed / 10.0 / 60.0;
    return s;
}

double SpeedPhase::s_at(double t) const {
    const double tau = std::clamp(t - t0, 0.0, duration);
    return s0 + v0 * tau + 0.5 * acc * tau * tau;
}

double SpeedPhase::v_at(double t) const {
    const double tau = std::clamp(t - t0, 0.0, duration);
    return v0 + acc * tau;
}

namespace {

void add(SegmentPlan& plan, double& t, double& s, double v0, double v1, double a, double d) {
    SpeedPhase ph;
    ph.t0 = t;
    ph.s0 = s;
    ph.v0 = v0;
    if (v1 != v0) {
        ph.acc = v1 > v0 ? a : -a;
        ph.duration = std::abs(v1 - v0) / a;
    } else {
        ph.duration = v0 > 0 ? d / v0 : 0;
    }
    if (ph.duration <= 0) {
        return;
    }
    plan.phases.push_back(ph);
    t += ph.duration;
    s += d;
}

} // namespace

SegmentPlan plan_segment(double t0, double s0, double v0, double length, double nominal,
                         double exit, double a) {
    SegmentPlan plan;
    const double d = std::max(0.0, length - s0);
    double t = t0;
    double s = s0;
    if (v0 * v0 - exit * exit > 2 * a * d) {
        // Too short to ramp down to the speed asked for: down all the way, and leave faster.
        const double v1 = std::sqrt(std::max(0.0, v0 * v0 - 2 * a * d));
        add(plan, t, s, v0, v1, a, d);
        plan.exit_speed = v1;
        plan.reaches_exit = false;
        return plan;
    }
    const double peak = std::sqrt((2 * a * d + v0 * v0 + exit * exit) / 2);
    const double top = std::min(nominal, peak);
    const double up = std::abs(top * top - v0 * v0) / (2 * a);
    const double down = (top * top - exit * exit) / (2 * a);
    const double cruise = std::max(0.0, d - up - down);
    add(plan, t, s, v0, top, a, up);
    add(plan, t, s, top, top, a, cruise);
    add(plan, t, s, top, exit, a, down);
    plan.exit_speed = exit;
    return plan;
}

const char* junction_kind_name(JunctionKind k) {
    switch (k) {
    case JunctionKind::passed:
        return "passed at the nominal speed";
    case JunctionKind::slowed_rate:
        return "slowed: a motor's pulse rate changes by more than the maximum";
    case JunctionKind::slowed_short:
        return "slowed: the next segment is shorter than the ramp";
    case JunctionKind::slowed_always:
        return "slowed: every junction is (junctions \"minimum\")";
    case JunctionKind::stopped:
        return "stopped: the next segment was not read in time";
    case JunctionKind::none:
        break;
    }
    return "none";
}

Point3 motor_rates(const PathSegment& s, double v, int steps_per_in) {
    Point3 r{};
    for (std::size_t i = 0; i < r.size(); ++i) {
        r[i] = v * s.unit[i] * steps_per_in;
    }
    return r;
}

double path_acceleration(const axes::ContourProfile& p) {
    return p.ramp_steps_per_s2 / p.steps_per_in;
}

double minimum_speed(const axes::ContourProfile& p) {
    return p.minimum_in_per_min / 60.0;
}

JunctionDecision control_cycle(const PathSegment& first, const PathSegment& second,
                               const axes::ContourProfile& p) {
    JunctionDecision j;
    j.first_rates = motor_rates(first, first.nominal, p.steps_per_in);
    j.second_rates = motor_rates(second, second.nominal, p.steps_per_in);
    for (std::size_t i = 0; i < j.first_rates.size(); ++i) {
        j.difference = std::max(j.difference, std::abs(j.first_rates[i] - j.second_rates[i]));
    }
    const double vmin = std::min(minimum_speed(p), std::min(first.nominal, second.nominal));
    const double a = path_acceleration(p);
    j.ramp = std::max(0.0, second.nominal * second.nominal - vmin * vmin) / (2 * a);
    if (p.junctions == axes::JunctionPolicy::minimum) {
        j.kind = JunctionKind::slowed_always;
    } else if (p.junctions == axes::JunctionPolicy::pass) {
        j.kind = JunctionKind::passed;
    } else if (j.difference > p.max_rate_change_steps_per_s) {
        j.kind = JunctionKind::slowed_rate;
    } else if (p.short_segment_rule && second.length < j.ramp) {
        j.kind = JunctionKind::slowed_short;
    } else {
        j.kind = JunctionKind::passed;
    }
    if (j.kind == JunctionKind::passed) {
        j.exit = first.nominal;
        j.entry = second.nominal;
    } else {
        j.exit = vmin;
        j.entry = vmin;
    }
    return j;
}

} // namespace parsons::relaylogic
