// The contouring attachment's interpolator and control cycle (an addition after EP 0636958,
// Black & Decker; docs/contouring.md). Pure arithmetic: the cabinet's attachment
// (contouring_attachment.hpp) runs it in machine time.
//
// A segment is travelled with its three axes together, each at the share of the path speed its
// direction gives it (linear interpolation), along a speed plan of at most three phases: a ramp
// from the speed it enters at towards its nominal speed, the nominal speed, and a ramp down to
// the speed it must leave at, every ramp at the path acceleration `a` (in/s²). The control cycle
// looks at two consecutive segments (claim 1) and picks the speed the first is left at:
// its nominal (the junction passed at speed) or the minimum (slowed), by the motors' speed
// parameters (claims 2, 3: each motor's pulse rate at the segment's nominal speed) and by the
// second segment's length (claims 7, 8).
#pragma once

#include "axes/machine_profile.hpp"
#include "cardreader/orders.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace parsons::relaylogic {

using Point3 = std::array<double, cardreader::kSegmentAxes>;

// One straight segment of a segment card, from where the last one ended.
struct PathSegment {
    int number = 0;        // its card number
    std::int64_t card = 0; // its place in the deck
    Point3 from{};         // inches
    Point3 to{};           // inches
    Point3 unit{};         // its direction
    double length = 0;     // inches
    double nominal = 0;    // in/s
};

PathSegment make_segment(const Point3& from, const cardreader::SegmentOrder& order, int number,
                         std::int64_t card);

// One phase of a plan: from time t0 at s0 along the segment, speed v0, acceleration acc.
struct SpeedPhase {
    double t0 = 0;
    double s0 = 0;
    double v0 = 0;
    double acc = 0;
    double duration = 0;

    double end() const { return t0 + duration; }
    double s_at(double t) const;
    double v_at(double t) const;
};

struct SegmentPlan {
    std::vector<SpeedPhase> phases;
    double exit_speed = 0;    // the speed it reaches the segment's end at
    bool reaches_exit = true; // false: too short to ramp down to the speed asked for
};

// The plan from (t0, s0, v0) to the end of a segment of `length` at most `nominal`, leaving at
// `exit` (or as near as the ramp allows: reaches_exit false), every ramp at `a`.
SegmentPlan plan_segment(double t0, double s0, double v0, double length, double nominal,
                         double exit, double a);

// The control cycle's decision at a junction.
enum class JunctionKind : std::uint8_t {
    none = 0,
    passed = 1,        // the difference within the maximum: passed at the nominal speeds
    slowed_rate = 2,   // claim 1: a motor's speed changes by more than the maximum
    slowed_short = 3,  // claims 7, 8: the second segment is shorter than the ramp
    slowed_always = 4, // junctions "minimum": every junction slowed (the prior art)
    stopped = 5,       // the next segment was not read in time: the motors stopped
};

const char* junction_kind_name(JunctionKind k);

struct JunctionDecision {
    JunctionKind kind = JunctionKind::none;
    Point3 first_rates{};  // each motor's pulse rate along the first at its nominal, steps/s
    Point3 second_rates{}; // ... along the second
    double difference = 0; // the largest |first - second|, steps/s
    double ramp = 0;       // the ramp from the second's nominal to the minimum, inches
    double exit = 0;       // the speed the first is left at, in/s
    double entry = 0;      // the speed the second begins at, in/s
};

// Each motor's pulse rate (steps/s, signed) along the segment at speed v (in/s).
Point3 motor_rates(const PathSegment& s, double v, int steps_per_in);
// The path acceleration (in/s²) that ramps no motor faster than ramp_steps_per_s2.
double path_acceleration(const axes::ContourProfile& p);
double minimum_speed(const axes::ContourProfile& p); // in/s

JunctionDecision control_cycle(const PathSegment& first, const PathSegment& second,
                               const axes::ContourProfile& p);

} // namespace parsons::relaylogic
