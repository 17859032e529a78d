// Fast-forward: the analytic jump between comparer equalities.
//
// Between two events that matter, an axis's impulses each do the same small thing: commutator
// 102 steps switch 110 and the increment counter, commutators 100, 98, 96 step 108, 106, 104
// now and then, and both comparers stay open. Every such "quiet" impulse is a pure function of
// the integer commutator index it crosses, so a stretch of them can be taken in one jump:
//
//   switch i of the absolute counter (unit m = 1000, 100, 10, 1 thousandths) after the impulse
//   that leaves the screw on index k reads  (o_i + sigma * floor(k / m) mod 10) mod 10,
//   sigma = (counting sense of reversing control 214) x (direction the screw turns), and
//   o_i fixed by where it stood;   the increment counter reads  (start + j) mod 10000.
//
// So the comparer closes again at the first index whose digits fall on closed relays, which is
// found from the (few) numbers the banks can match, not by stepping. A stretch ends before the
// first impulse that is not quiet: a comparer conducts, a fault is due, the part would pass a
// travel limit, or a stepping switch could miss a step (impulses closer than its stepping
// time, where one-by-one is the only exact answer). The impulse that ends it, and everything
// after, goes through the ordinary impulse path. A jump leaves every switch, its last-step
// time, the counters and the plant exactly where taking the impulses one by one would.
#pragma once

#include "relaylogic/axis_circuit.hpp"

#include <functional>
#include <span>

namespace parsons::relaylogic {

// Counter readings an attachment watches (condition cards' monitoring unit PRG): a quiet
// stretch ends at the impulse that steps the axis's absolute counter onto one of them.
class CounterWatch {
public:
    virtual bool watching(cardreader::Axis axis) const = 0;
    // Each reading watched on the axis while its counter counts in `direction` (+1 up, -1 down).
    virtual void each_watched(cardreader::Axis axis, int direction,
                              const std::function<void(int)>& f) const = 0;

protected:
    ~CounterWatch() = default;
};

struct QuietConditions {
    double min_interval_s = 0;           // 1 / the stepping switches' fastest rate
    bool machine_stopped = false;        // master switch open: nothing but counting happens
    std::int64_t next_fault_impulse = 0; // contact-set-A count of the next fault on this axis, or 0
    bool counting_hundredths = false;    // the profile's hundredths-only counting is in force
    bool watching_soft_limits = false;   // the axis is powered and has a movement range
    bool faulty_switch_ahead = false;    // a skip fault waits on one of the axis's switches
    // The attachments' counter watches (condition cards' monitoring unit PRG, an addition):
    // their readings end a stretch at the impulse that steps the counter onto one of them.
    std::span<const CounterWatch* const> watches;
};

// The control's soft-limit watch (Mitsubishi's movement range): with the part at x after an
// impulse, moving in direction d at speed v, could it still brake to rest inside the range if
// the motor were switched off at the next impulse? If not, it is switched off now.
bool soft_limit_trips(const axes::AxisProfile& p, int d, double x, double v);

// How many of the axis's coming impulses are quiet (0 when the next one is not, or when the
// axis is not moving toward an impulse).
std::int64_t quiet_impulses(const AxisCircuit& c, const QuietConditions& q);

// Takes the next n quiet impulses at once (n <= quiet_impulses()).
void jump_quiet_impulses(AxisCircuit& c, std::int64_t n);

} // namespace parsons::relaylogic
