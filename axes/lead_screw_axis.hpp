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
// The real part position is s plus the residual screw error left after compensating cam 160
// (a table in the profile); the counters only ever see s. Motion goes through one gateway,
// advance_to(), which is where impulses, coast and the travel limits are all decided.
// Emulation note: the two contact sets of each commutator are the duplicate-contact check of
// relaylogic/; here an impulse is one event seen by both.
#pragma once

#include "axes/machine_profile.hpp"

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

class LeadScrewAxis {
public:
    explicit LeadScrewAxis(const AxisProfile& profile);

    // The motor: direction +1 / -1 and one of the three speeds (1..3), or switched off (0).
    // Takes effect at the current time; the speed changes at the profile's rates.
    void command(int direction, int speed_position);

    // When the next thing happens to this axis by itself: an impulse or the end of a speed
    // change. kNever at rest.
    double next_event_time() const { return next_time_; }
    bool next_event_is_impulse() const { return next_is_impulse_; }

    // The one gateway for motion: moves the axis to machine time t (t <= next_event_time()).
    // Returns the impulse if t is the moment of the next impulse.
    std::optional<Impulse> advance_to(double t);

    double screw_in() const { return s_; }
    double real_in() const; // the part: screw plus residual screw error (cam 160)
    // Where the part is at time t (t_ <= t <= next_event_time()), without moving anything.
    double real_in_at(double t) const;
    double speed_in_per_s() const { return u_; }
    int moving_direction() const { return d_; }
    bool at_rest() const { return u_ == 0 && target_u_ == 0; }
    bool beyond_limits() const;
    long impulses() const { return impulses_; }
    long commutator_index() const { return k_; } // thousandths the commutator has passed
    const AxisProfile& profile() const { return profile_; }

    // Sine-plate geometry for swivel and tilt: the fixture angle this screw position makes,
    // degrees, from its level position (tilt: sin = (screw - level) / arm, the sine plate;
    // swivel: tan = (screw - level) / arm).
    double fixture_angle_deg(bool sine_plate) const;

private:
    void plan(); // works out the current phase and the next event
    double with_screw_error(double s) const;
    double accel_toward_target() const;

    AxisProfile profile_;
    double t_ = 0;        // time of the state below
    double s_ = 0;        // screw position, in
    double u_ = 0;        // speed, in/s (>= 0)
    int d_ = +1;          // direction of motion
    long k_ = 0;          // commutator index: round(s / 0.001)
    int target_dir_ = +1; // what the motor is asked to do
    double target_u_ = 0;
    double a_ = 0; // acceleration of the current phase (signed, along d_)
    double phase_end_ = kNever;
    double next_time_ = kNever;
    bool next_is_impulse_ = false;
    long impulses_ = 0;
};

} // namespace parsons::axes
