// One lead-screw axis of Figs. 2-3: motor (38, 40, 44, 46 or 50), lead screw, the unloaded
// instrument shaft 74 and gear train 82-92 driving the commutators 96, 98, 100, 102, and the
// part it moves (table 14, cutter head 28, fixture 15, sine plate 16).
//
// How we represent it: the screw position s (inches of screw travel) moves with a speed that
// changes at a constant rate toward the speed the control asks for (accelerating between
// speed positions, braking to rest when switched off: coast = v^2 / 2a). Time advances in
// phases of constant acceleration, so the moment the next commutator impulse comes is solved
// exactly (a quadratic), never stepped at a fixed rate.
//
//   commutator 102 closes every 0.001 in, on the half-thousandths:
//        |  k-1  |   k   |  k+1  |          the counters read k while s is within 0.0005 in
//   -----+---+---+---+---+---+---+---- s    of k thousandths; an impulse comes as s crosses
//          k-1.5   k-0.5   k+0.5            a half-thousandth, forward or reverse.
//   commutators 100, 98, 96 close at the same crossings every 10, 100 and 1000 of them.
//
// Every impulse time is a pure function of the phase (its start time, place, speed and
// acceleration) and of the integer index of the half-thousandth crossed, so the n-th impulse
// from now has the same time whether the impulses before it were taken one by one or skipped
// in one jump (fast-forward); the two modes of the cabinet agree to the last bit. The state at
// one instant is likewise a function of the phase and that instant alone, whatever order the
// instant's events reach the plant in: at the end of a speed change the speed is the target
// itself, and a screw standing on an impulse's crossing keeps that crossing's place (the
// fuzz finding of issue 11, tests/fuzz/regressions/machine/tilt-real-position-differs).
//
// s is the main screw's travel (turns x lead). What the commutators count depends on the
// measuring chain (MachineProfile::measuring_chain): in the patent's (Fig. 3) they are turned
// by instrument shaft 74 from the part itself, so the half-thousandth crossings are those of
// the counters' reading q, tied to the part by the instrument's residual error
// (axes/instrument_shaft.hpp), and the part to the screw through nut 78 (lead error less what
// compensating cam 160 corrects, backlash, slip: axes/lead_screw_nut.hpp). The screw
// position of crossing h is then
//     s_h = o_end + G^-1(q_h + r(q_h)),   q_h = h x 0.0005 in,
// a pure function of h within a stretch of the nut. Counting screw turns instead (a departure)
// the crossings are the screw's own, s_h = q_h, and the part lags by whatever nut 78 and the
// drive lose. Either way the part's position at a crossing is a pure function of h, never a
// sum of increments. Motion goes through one gateway, advance_to(), which is where impulses,
// coast and the travel limits are all decided.
// Emulation note: the two contact sets of each commutator are the duplicate-contact check of
// relaylogic/; here an impulse is one event seen by both.
#pragma once

#include "axes/chain_figures.hpp"
#include "axes/instrument_shaft.hpp"
#include "axes/lead_screw_nut.hpp"
#include "axes/machine_profile.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

namespace parsons::axes {

inline constexpr double kInchesPerImpulse = 0.001;
inline constexpr double kNever = std::numeric_limits<double>::infinity();

// The commutators that close at one crossing (102 always; 100, 98, 96 at every tenth,
// hundredth and thousandth crossing).
struct Impulse {
    int direction = 0;       // +1 forward (counters count up), -1 reverse
    bool hundredths = false; // commutator 100
    bool tenths = false;     // commutator 98
    bool inches = false;     // commutator 96
};

// floor(a / b) for b > 0, also for negative a.
inline std::int64_t floor_div(std::int64_t a, std::int64_t b) {
    const std::int64_t q = a / b;
    return (a % b != 0 && a < 0) ? q - 1 : q;
}

// Time to cover distance D > 0 from speed u with acceleration a, or kNever.
inline double time_to_cover(double D, double u, double a) {
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

// The half-thousandth crossing h (odd) as a screw position: exactly the double that
// (k + d / 2) * 0.001 gives for the crossing from k in direction d.
inline double crossing_in(std::int64_t h) {
    return static_cast<double>(h) * (kInchesPerImpulse / 2);
}

// The sine-plate geometry of swivel and tilt: the fixture angle a screw at `real_in` makes,
// degrees, from its level position (tilt: sin = (screw - level) / arm, the sine plate; swivel:
// tan = (screw - level) / arm). The report's angle and the exhibit page's (cli/run_timeline).
double fixture_angle_deg(const AxisProfile& profile, double real_in, bool sine_plate);

class LeadScrewAxis {
public:
    explicit LeadScrewAxis(const AxisProfile& profile);
    // What the commutators count (before any motion): the part through instrument shaft 74
    // (the default, the patent), or the main screw's turns (a departure). Cam 160 corrects
    // the main screw's lead (the patent), or, with cam_160_on_instrument_shaft (an
    // interpretation, instrument chain only), instrument shaft 74's screw.
    void measure_by(MeasuringChain chain, bool cam_160_on_instrument_shaft);
    MeasuringChain measuring_chain() const { return chain_; }

    // The motor: direction +1 / -1 and one of the three speeds (1..3), or switched off (0).
    // Takes effect at the current time; the speed changes at the profile's rates. Asking for
    // what the motor is already doing changes nothing.
    void command(int direction, int speed_position) {
        const int dir = direction >= 0 ? +1 : -1;
        const int speed = speed_position >= 1 && speed_position <= 3 ? speed_position : 0;
        if (speed == target_speed_ && (speed == 0 || dir == target_dir_)) {
            target_dir_ = dir;
            return; // the motor is already doing this: the phase goes on unchanged
        }
        change_command(dir, speed);
    }
    // The follower drive of press synchronisation (an addition after EP 0436887; SyncDrive in
    // the profile): direction and a speed in in/s that the drive reaches at `acceleration`
    // in/s2 (its rate limit). Asking for what it is already doing changes nothing; command()
    // hands the axis back to the three-speed motor.
    void command_follow(int direction, double speed_in_per_s, double acceleration);
    bool following() const { return target_speed_ == kFollowing; }

    // When the next thing happens to this axis by itself: an impulse or the end of a speed
    // change. kNever at rest.
    double next_event_time() const { return next_time_; }
    bool next_event_is_impulse() const { return next_is_impulse_; }

    // The one gateway for motion: moves the axis to machine time t (t <= next_event_time()).
    // Returns the impulse if t is the moment of the next impulse.
    std::optional<Impulse> advance_to(double t) {
        if (t < next_time_) {
            move_within_phase(t); // the common case, inline: nothing happens before t
            return std::nullopt;
        }
        if (next_is_impulse_) {
            return take_impulse();
        }
        advance_slowly(t);
        return std::nullopt;
    }

    // The next impulse, due now (next_event_is_impulse()): the impulse loop's own gateway.
    [[gnu::always_inline]] Impulse take_next_impulse() { return take_impulse(); }

    // Fast-forward: the time of the n-th impulse from now (n >= 1) in the current phase of
    // motion, or kNever if the phase ends (or the axis stops) first.
    double impulse_time(std::int64_t n) const;
    // How many of the coming impulses of this phase come at or before time t.
    std::int64_t impulses_by(double t) const;
    // Takes the next n impulses of this phase at once (n >= 1, impulse_time(n) finite).
    void skip_impulses(std::int64_t n);

    double screw_in() const { return s_; }
    double real_in() const; // the part: where nut 78 really stands
    // Where the part is at time t (t_ <= t <= next_event_time()), without moving anything.
    double real_in_at(double t) const;
    double speed_in_per_s() const;
    int moving_direction() const { return d_; }
    // Motion in this phase: acceleration (signed along moving_direction()), speed at its start.
    double phase_acceleration() const { return a_; }
    double phase_start_speed() const { return u0_; }
    double phase_end_speed() const;
    double phase_end_time() const { return phase_end_; }
    // The least screw travel between two impulses anywhere: 0.001 in counting screw turns;
    // through instrument shaft 74, less where the error tables make the part (and so the
    // reading) run ahead of the screw. The fastest the impulses can come is this over the
    // screw's speed.
    double least_screw_per_impulse() const { return least_screw_per_impulse_; }
    bool at_rest() const { return speed_in_per_s() == 0 && target_u_ == 0; }
    std::int64_t impulses() const { return impulses_; }
    std::int64_t commutator_index() const { return k_; } // thousandths the commutator has passed

    // Travel limits, decided on the half-thousandth crossings (the part's position through the
    // screw-error table is monotonic, so the crossings inside the limits form one range).
    // Did the last impulse's crossing put the part beyond a limit?
    bool beyond_limits() const { return last_h_ < h_lo_ || last_h_ > h_hi_; }
    // The first of the coming impulses (1-based) whose crossing lies beyond a limit.
    std::int64_t impulses_to_limit() const;
    const AxisProfile& profile() const { return profile_; }
    // The part's position at the crossing of the j-th coming impulse (j >= 1).
    double real_at_impulse(std::int64_t j) const {
        return real_at_crossing(2 * (k_ + d_ * (j - 1)) + d_);
    }

    // Fault: from its nth impulse (from 1) the drive slips for `count` thousandths of screw
    // travel: the screw turns, the part stands (axes/lead_screw_nut.hpp).
    void slip_from(std::int64_t n, std::int64_t count) {
        slip_from_ = n;
        slip_len_in_ = static_cast<double>(count) * kInchesPerImpulse;
    }
    bool slipping_ahead() const { return slip_len_in_ > 0 && slip_from_ > impulses_; }
    std::int64_t impulses_to_slip() const { return slipping_ahead() ? slip_from_ - impulses_ : 0; }
    double slip_in() const { return nut_.slip_in(); } // how far the part lags the screw
    // The part against the reading, cause by cause, where the axis stands now.
    ChainFigures chain_figures() const;
    // The first coming impulse (1-based) whose crossing puts the part where trips(x) holds,
    // for a trips that, once true, stays true further along the motion; 0 if none ever does.
    template <typename Trips>
    std::int64_t first_impulse_where(Trips trips) const {
        constexpr std::int64_t kFar = std::int64_t{1} << 40;
        if (!trips(real_at_impulse(kFar))) {
            return 0;
        }
        std::int64_t lo = 1;
        std::int64_t hi = kFar;
        while (lo < hi) {
            const std::int64_t mid = lo + (hi - lo) / 2;
            if (trips(real_at_impulse(mid))) {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        return lo;
    }

    // Everything that moves, for a saved machine state (run --save-state / --resume).
    nlohmann::json save() const;
    void load(const nlohmann::json& j);

    // Sine-plate geometry for swivel and tilt: the fixture angle this screw position makes,
    // degrees, from its level position (tilt: sin = (screw - level) / arm, the sine plate;
    // swivel: tan = (screw - level) / arm).
    double fixture_angle_deg(bool sine_plate) const {
        return axes::fixture_angle_deg(profile_, real_in(), sine_plate);
    }

private:
    [[gnu::always_inline]] Impulse take_impulse() {
        t_ = next_time_;
        last_h_ = 2 * k_ + d_;
        s_ = crossing_screw(last_h_);
        last_crossing_s_ = s_;
        has_crossing_ = true;
        k_ += d_;
        ++impulses_;
        if (impulses_ == slip_from_ && slip_len_in_ > 0) {
            begin_slip(); // the fault: from here the screw turns, the part stands
        }
        Impulse impulse;
        impulse.direction = d_;
        // Commutators 100, 98, 96 close when the crossing also crosses a 0.01, 0.1 or 1 in
        // boundary: the crossing lies between readings upper - 1 and upper, and it passes such
        // a boundary exactly when upper is a whole number of hundredths, tenths or inches.
        const std::int64_t upper = d_ > 0 ? k_ : k_ + 1;
        impulse.hundredths = upper % 10 == 0;  // also for upper < 0
        if (impulse.hundredths) [[unlikely]] { // one crossing in ten: not worked out at the rest
            impulse.tenths = upper % 100 == 0;
            impulse.inches = impulse.tenths && upper % 1000 == 0;
        }
        plan_impulse();
        return impulse;
    }
    void advance_slowly(double t); // t >= next_time_: the end of a speed change
    // Machine time comes to t (t < next_time_): the screw stands where the phase puts it.
    void move_within_phase(double t) {
        if (t > t_) {
            t_ = t;
            s_ = position_at(t);
        }
    }
    void change_command(int dir, int speed); // command() when the motor must change
    void begin_slip();
    void set_limit_range();     // h_lo_, h_hi_ for the limits (and, counting turns, the nut)
    void start_phase(double u); // a new phase of constant acceleration from (t_, s_, u)
    void plan_constants();      // the constant-speed crossing times of this phase
    // The screw position at which the commutators' crossing h comes, in this stretch of nut
    // 78, and where the part then is.
    [[gnu::always_inline]] double crossing_screw(std::int64_t h) const {
        if (chain_ == MeasuringChain::screw_turns) {
            return crossing_in(h);
        }
        if (linear_) {
            return crossing_in(h) + nut_.o_end();
        }
        return nut_.screw_at(nut_.sigma_at_part(shaft_.part_at_reading(crossing_in(h))));
    }
    double real_at_crossing(std::int64_t h) const {
        return chain_ == MeasuringChain::screw_turns ? nut_.part_at_screw(crossing_in(h))
                                                     : shaft_.part_at_reading(crossing_in(h));
    }
    // What the counters would read with the screw at s (no crossing rounding).
    double reading_at_screw(double s) const {
        return chain_ == MeasuringChain::screw_turns
                   ? s
                   : shaft_.reading_at_part(nut_.part_at_screw(s));
    }
    // The time of the next impulse in this phase.
    [[gnu::always_inline]] void plan_impulse() {
        const double t = boundary_time(k_);
        next_is_impulse_ = t != kNever;
        next_time_ = next_is_impulse_ ? t : phase_end_;
    }
    [[gnu::always_inline]] double boundary_time(std::int64_t k_from) const {
        if (steady_) {
            // At constant speed the crossing times are linear in the index: t0 + (boundary -
            // s0) / u, with the constants worked out once a phase. Never before the phase.
            return std::max(t0_, time_at_index0_ + time_per_index_ * static_cast<double>(k_from));
        }
        if (u0_ == 0 && a_ <= 0) {
            return kNever;
        }
        const double boundary = crossing_screw(2 * k_from + d_);
        const double D = std::max(0.0, (boundary - s0_) * d_);
        const double t = t0_ + time_to_cover(D, u0_, a_);
        return t <= phase_end_ ? t : kNever;
    }
    double position_at(double t) const {
        const double tau = std::min(t, phase_end_) - t0_;
        return s0_ + d_ * (u0_ * tau + 0.5 * a_ * tau * tau);
    }
    double accel_toward_target(double u) const;

    AxisProfile profile_;
    MeasuringChain chain_ = MeasuringChain::instrument_shaft_74;
    InstrumentShaft shaft_;     // instrument shaft 74
    LeadScrewNut nut_;          // lead screw 22 and its cam 160, nut 78, the drive's slip
    bool cam_on_shaft_ = false; // the interpretation cam_160_on_instrument_shaft
    bool linear_ = true;        // crossing_screw(h) = crossing_in(h) + offset (no error tables)
    double least_screw_per_impulse_ = kInchesPerImpulse;
    // The current phase: from time t0_ at screw position s0_ and speed u0_ (>= 0), moving in
    // direction d_ with acceleration a_ (signed along d_) until phase_end_.
    double t0_ = 0;
    double s0_ = 0;
    double u0_ = 0;
    double time_at_index0_ = 0; // at constant speed: crossing from index k at
    double time_per_index_ = 0; // time_at_index0_ + time_per_index_ * k
    bool steady_ = false;       // those two hold: a_ == 0, u0_ > 0 and linear_ (plan_constants)
    double a_ = 0;
    int d_ = +1;
    double phase_end_ = kNever;
    // The state now.
    double t_ = 0;
    double s_ = 0;
    std::int64_t k_ = 0;      // commutator index: round(s / 0.001)
    std::int64_t last_h_ = 0; // the last crossing, in half-thousandths (odd)
    int target_dir_ = +1;
    int target_speed_ = 0;
    double target_u_ = 0;
    double next_time_ = kNever;
    bool next_is_impulse_ = false;
    static constexpr int kFollowing = 4; // target_speed_ under the follower drive
    double follow_accel_ = 0;            // its rate limit
    std::int64_t impulses_ = 0;
    std::int64_t h_lo_ = 0; // crossings inside the travel limits: h_lo_ <= h <= h_hi_ (odd)
    std::int64_t h_hi_ = 0;
    std::int64_t slip_from_ = 0; // the slip fault: from this impulse,
    double slip_len_in_ = 0;     // this much screw travel (0 once begun)
    double last_crossing_s_ = 0; // the screw position of the last crossing taken
    bool has_crossing_ = false;
};

} // namespace parsons::axes
