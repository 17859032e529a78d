// The spindle of EP 0360190 (Mitsubishi), Figs. 1 and 3: spindle motor 27 turning at a speed the NC
// commands (not only on, off and reverse), encoder 32 coupled directly to the motor, gear unit 30
// and the interchangeable spindle heads 31, each holding its tool 16 (a tap of a given pitch, or a
// cutter). An addition to the 1952 machine (docs/design-rules.md rule 14), present only when the
// profile has spindle synchronisation (parsons-extended).
//
// How we represent it: the motor's unwrapped angle phi (motor revolutions, 0 where the run
// starts, growing forward) moves with a speed that changes at a constant rate between
// "segment boundaries": a command, the end of a run-up or run-down, the instant the speed
// passes through zero on a reversal (so each segment turns one way only), and the profile's
// lasting change (change_at_s: from then on the motor turns at change_factor x its commanded
// speed). Run-up (the speed's magnitude growing) is at run_up_rpm_per_s, run-down at
// run_down_rpm_per_s; a reversal runs down to rest, then up the other way (plugging). The
// lasting change is a boundary of every segment that spans change_at_s, unless the motor stands
// commanded to stand: then nothing happens there, and the next command finds the change come.
//
// Encoder 32: phases A and B in quadrature, encoder_pulses_per_rev edges a motor revolution, and
// (rigid tapping, an addition) an index, once a revolution: the forward edge onto a whole
// revolution, count m with m mod ppr == 0 (relaylogic/tapping/tapping_units.hpp latches it).
// The count c = floor(phi x ppr): an edge at each whole multiple m / ppr of a revolution
// (forward, c becomes m; backward, c becomes m - 1); the phases after count c stand at the
// Gray code of c mod 4, as detector 10 of the press (axes/press.hpp: phases_at()), so the same
// direction judging device 13 tells the sense.
//
// Every edge time is a pure function of the segment and the integer edge index (the root of
// the segment's quadratic), so the n-th edge from now has the same time whether the edges
// before it were taken one by one or skipped in one jump (the cabinet's fast-forward), to the
// last bit. An edge that falls exactly on a segment boundary is taken in the segment it ends,
// before the boundary.
//
// Gear unit 30 and head 31: the tool turns at ratio A x the motor (S x A, the seed's
// expression); its angle is kept as tool revolutions, whatever heads were on before. Heads are
// exchanged with the motor at rest (PC 130 does it,
// relaylogic/tapping/programmable_controller.hpp).
#pragma once

#include "axes/machine_profile.hpp"
#include "axes/press.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>

namespace parsons::axes {

class Spindle {
public:
    explicit Spindle(const SpindleSyncProfile& profile);

    // Motor 27 commanded at the current time (time_s()): rev/min, + forward, - reverse, 0 to
    // rest; |rpm| is at most the profile's max_rpm (the caller checks). Asking for what it is
    // already commanded changes nothing.
    void command_rpm(double rpm);
    double commanded_rpm() const { return commanded_rpm_; }

    // When the next thing happens by itself: an encoder edge, or a segment boundary. kNever
    // when the motor stands and nothing is coming.
    double next_event_time() const { return next_time_; }
    bool next_event_is_pulse() const { return next_is_pulse_; }
    // The one gateway: moves the motor to machine time t (t <= next_event_time()). Returns the
    // edge if t is its time; at a segment boundary the next segment begins.
    std::optional<DetectorEdge> advance_to(double t);

    // Fast-forward: the time of the n-th coming edge (n >= 1) within this segment, or kNever if
    // the segment ends first; how many come at or before t (exactly the n with pulse_time(n)
    // <= t; pulses_by(kNever) is all the segment's edges, LONG_MAX for a steady speed that never
    // ends); take the next n at once (the n-th is returned, as advance_to() would return it).
    double pulse_time(std::int64_t n) const;
    std::int64_t pulses_by(double t) const;
    DetectorEdge skip_pulses(std::int64_t n);

    double time_s() const { return t_; }
    std::int64_t count() const { return count_; } // encoder edges, unwrapped (negative backwards)
    double motor_revs() const;                    // phi now
    double motor_revs_at(double t) const;         // t within the current segment
    double rpm() const;                           // motor 27 now, signed
    double rpm_at(double t) const;                // t within the current segment
    bool at_rest() const;                         // standing, and commanded to stand

    // Gear unit 30 and head 31. mount() puts the head holding `tool` on (the motor at rest);
    // the tool then turns at that head's ratio. An unknown tool mounts nothing (tool() 0).
    void mount(int tool);
    int tool() const { return tool_; }
    double ratio() const { return ratio_; } // the head's real ratio A (0 with no head)
    double tool_revs() const;               // the tool's revolutions, unwrapped
    double tool_revs_at(double t) const;    // t within the current segment
    // The tool's revolutions where encoder edge m stands (m / ppr motor revolutions), the head
    // now on: where the tool stood at an index of encoder 32 (rigid tapping, an addition).
    double tool_revs_at_edge(std::int64_t m) const {
        return mount_tool_revs_ + (edge_revs(m) - mount_phi_) * ratio_;
    }

    const SpindleSyncProfile& profile() const { return profile_; }
    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    // A segment as it follows from where it starts (time t0, angle phi0, speed rpm0) and what
    // is commanded: its constant acceleration, the boundary that ends it, the angle and speed
    // there, and the sense it turns (+1, -1; 0 standing).
    struct Segment {
        double a_rpm_per_s = 0;
        double end_t = kNever;
        double end_revs = 0;
        double end_rpm = 0;
        int sense = 0;
    };
    Segment segment_from(double t0, double phi0, double rpm0) const;
    bool changed_at(double t) const; // the lasting change has come by time t
    void start_segment(double t0, double phi0, double rpm0);
    void plan_pulse();
    // Edge m stands at m / ppr motor revolutions; the n-th coming edge (n >= 1) is
    // edge_index(n).
    double edge_revs(std::int64_t m) const { return static_cast<double>(m) / ppr_; }
    std::int64_t edge_index(std::int64_t n) const {
        return seg_.sense > 0 ? count_ + n : count_ - n + 1;
    }
    bool in_segment(std::int64_t m) const;
    std::int64_t edges_left() const; // edges still to come before the segment ends
    double edge_time(std::int64_t m) const;
    double revs_formula(double t) const; // the segment's quadratic, unclamped
    DetectorEdge take_edge(std::int64_t m, double t);

    SpindleSyncProfile profile_;
    double ppr_ = 24;
    double t_ = 0;
    double phi_ = 0; // motor revolutions now, unwrapped
    double commanded_rpm_ = 0;
    std::int64_t count_ = 0;
    int tool_ = 0;
    double ratio_ = 0;
    double next_time_ = kNever;
    bool next_is_pulse_ = false;
    // The segment: from time seg_t0_ at angle seg_phi0_ and speed seg_rpm0_ (rev/min, signed).
    double seg_t0_ = 0;
    double seg_phi0_ = 0;
    double seg_rpm0_ = 0;
    Segment seg_;
    // Where the motor and the tool stood at the last mount (tool_revs() continues from there).
    double mount_phi_ = 0;
    double mount_tool_revs_ = 0;
};

} // namespace parsons::axes
