// The outside machine of EP 0436887 (Mitsubishi), Fig. 1A: a rotary press that the numerical
// control does not drive. Motor 22 turns crank 21 at a speed of its own; the crank raises and
// lowers die 20 through a connecting rod (a slider crank); detector 10 on the crank gives a
// two-phase signal. An addition to the 1952 machine (docs/design-rules.md rule 14), present only
// when the profile has press synchronisation (parsons-extended).
//
// How we represent it: the crank's unwrapped angle theta (degrees, 0 = top dead centre of
// the first revolution, growing as the press runs forward) moves at a speed that is constant
// between "segment boundaries": the angles where the profile changes it (every top dead centre,
// where a new revolution takes its drift and seeded variation; the start and end of pressing;
// the lasting change; the stop). A segment's speed is a pure function of the revolution and
// the angle, so the press has no hidden state beyond where it stands.
//
// Detector 10: phases A and B in quadrature; every edge of either is one pulse, so there are
// pulses_per_degree edges a degree. The pulse count c = floor(theta x ppd) (an edge at each
// whole multiple m / ppd of a degree: forward, c becomes m; backward, c becomes m - 1). The
// phases after count c stand at the Gray code of c mod 4: 0 -> (A 0, B 0), 1 -> (1, 0),
// 2 -> (1, 1), 3 -> (0, 1); forward, each edge moves one step along that sequence, backward
// one step back. Direction judging device 13 (relaylogic/) tells the sense from that alone.
//
// Every pulse time is a pure function of the segment and the integer edge index, so the n-th
// pulse from now has the same time whether the pulses before it were taken one by one or
// skipped in one jump (the cabinet's fast-forward), to the last bit. An edge that falls exactly
// on a segment boundary is taken in the segment it ends, before the boundary. Turning backwards
// (profile.reverse) the crank crosses [b_lo, b_hi) at speed_at(b_lo): the same function of
// where it stands (axes/press.cpp).
#pragma once

#include "axes/lead_screw_axis.hpp"
#include "axes/machine_profile.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <utility>

namespace parsons::axes {

// One edge of detector 10: the levels of phases A and B after it, and the count it leaves.
struct DetectorEdge {
    int phase_a = 0;
    int phase_b = 0;
    std::int64_t count = 0; // floor(theta x ppd) after the edge (unwrapped, may be negative)
};

// The phases A, B that stand after pulse count c (Gray code of c mod 4).
DetectorEdge phases_at(std::int64_t count);

class Press {
public:
    explicit Press(const PressProfile& profile);

    // When the next thing happens by itself: a detector edge, or a segment boundary (a change
    // of speed). kNever when the press stands (stopped).
    double next_event_time() const { return next_time_; }
    bool next_event_is_pulse() const { return next_is_pulse_; }
    // The one gateway: moves the crank to machine time t (t <= next_event_time()). Returns the
    // edge if t is its time; at a segment boundary the next segment begins.
    std::optional<DetectorEdge> advance_to(double t);

    // Fast-forward: the time of the n-th coming edge (n >= 1) within this segment, or kNever
    // if the segment ends first; how many come at or before t; take the next n at once (the
    // n-th is returned, as advance_to() would return it).
    double pulse_time(std::int64_t n) const;
    std::int64_t pulses_by(double t) const;
    DetectorEdge skip_pulses(std::int64_t n);

    double time_s() const { return t_; }          // machine time the crank stands at
    std::int64_t count() const { return count_; } // detector pulses, unwrapped
    double theta_deg() const;                     // unwrapped crank angle now
    double angle_deg() const;                     // crank 21 now, 0 <= a < 360
    double angle_deg_at(double t) const;          // t within the current segment
    int revolution() const;                       // 1 during the first revolution, ...
    double speed_deg_per_s() const { return w_; } // signed: negative when turning back
    // Motor 22 has stopped: set when the crank reaches the profile's stop (or starts past it),
    // never cleared; the press then stands for good.
    bool stopped() const { return stopped_; }
    // The feeder's interlock (docs/press-sync.md, "The feeder holds the press"): the press's
    // clutch and brake hold crank 21 where it stands at machine time t, and let it go at t, when
    // it turns on at the speed the profile gives where it stands (every speed is a function of
    // the angle, so a hold shifts the rest of the run in time and changes nothing else). hold()
    // wants every event due by t taken (t before next_event_time()); holding a stopped or held
    // press, or letting go of one not held, changes nothing.
    void hold(double t);
    void release(double t);
    bool held() const { return held_; }
    // Die 20 above its bottom dead centre, in inches, with the crank at angle a (slider crank:
    // r cos a + sqrt(L^2 - r^2 sin^2 a) - (L - r), r = stroke / 2).
    double die_height_in_at_angle(double a_deg) const;
    double die_height_in() const { return die_height_in_at_angle(angle_deg()); }
    // The crank angles (0..180 and 180..360) where the die passes height h going down and up;
    // nothing if h is outside 0 .. stroke. At the top (h = stroke) they are 0 and 360.
    std::optional<std::pair<double, double>> angles_at_height(double h_in) const;
    const PressProfile& profile() const { return profile_; }
    // The speed the profile gives at unwrapped angle theta (degrees per second, >= 0 forward,
    // before the sense is applied): nominal x drift x variation x pressing x change, or 0 past
    // the stop. Pure function.
    double speed_at(double theta) const;

    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    // A segment as it follows from where it starts: its signed speed (0 = the press stands),
    // the boundary that ends it and when the crank reaches that boundary.
    struct Segment {
        double w = 0;
        double end_theta = 0;
        double end_t = kNever;
    };
    Segment segment_from(double t0, double theta0) const;
    double boundary_from(double theta) const; // the next boundary past theta, in the sense
    double change_theta() const;              // where change_factor takes over
    double stop_theta() const;                // where motor 22 stops
    void start_segment();                     // from (t_, theta_, count_): speed, end, next edge
    void plan_pulse();
    // Edge m stands at m / ppd degrees; the n-th coming edge (n >= 1) is edge_index(n).
    double edge_angle(std::int64_t m) const { return static_cast<double>(m) / ppd_; }
    std::int64_t edge_index(std::int64_t n) const {
        return sense_ > 0 ? count_ + n : count_ - n + 1;
    }
    bool in_segment(std::int64_t m) const;
    std::int64_t edges_left() const; // edges still to come before the segment ends
    double theta_at(double t) const;
    DetectorEdge take_edge(std::int64_t m, double t);

    PressProfile profile_;
    double ppd_ = 4;
    int sense_ = +1;
    double t_ = 0;
    double theta_ = 0; // unwrapped, degrees
    std::int64_t count_ = 0;
    // The segment: from time t0_ at angle theta0_, speed w_ (deg/s, signed), until seg_end_t_.
    double t0_ = 0;
    double theta0_ = 0;
    double w_ = 0;
    double seg_end_t_ = kNever;
    double seg_end_theta_ = 0;
    double next_time_ = kNever;
    bool next_is_pulse_ = false;
    bool stopped_ = false;
    bool held_ = false; // the interlock holds the crank (a segment of speed 0 with no end)
};

} // namespace parsons::axes
