// The control circuit of one lead screw (Fig. 10 draws the table's and the cross slide's; the
// other three are the same): reversing control 214, absolute storage 350-356 and incremental
// storage 318-324, absolute counter 104-110 and increment counter 112, comparers 122' and
// 122'', speed switch 236, lamps 270 and 272, sequence switch 224, the motor, and the duplicate
// contact sets of commutator 102. The plant it drives is an axes::LeadScrewAxis.
#pragma once

#include "axes/lead_screw_axis.hpp"
#include "axes/machine_profile.hpp"
#include "cardreader/orders.hpp"
#include "relaylogic/counters.hpp"
#include "relaylogic/sequence_control.hpp"
#include "relaylogic/speed_switch.hpp"
#include "relaylogic/storage.hpp"

namespace parsons::relaylogic {

// The motor of each axis (Fig. 2): table 38, cutter-head transverse 50, cutter-head vertical
// 46, fixture transverse 44, sine-plate vertical 40.
std::string_view motor_numeral(cardreader::Axis axis);

struct AxisCircuit {
    AxisCircuit(Tracer& tracer, const axes::MachineProfile& profile, cardreader::Axis axis);

    // Reversing control 214 (row 0 forward, row 1 reverse), also setting the counters' sense.
    void set_direction(cardreader::Motion motion);
    // Comparers 122' and 122'': re-read the circuits through storage and counters.
    void compare() {
        absolute_conducting = absolute_storage.conducts(absolute_counter.digits());
        incremental_conducting = incremental_storage.conducts(increment_counter.digits());
        tracer.set(comparer_absolute_, absolute_conducting ? 1 : 0);
        tracer.set(comparer_incremental_, incremental_conducting ? 1 : 0);
        if (tracer.observer() != nullptr) {
            show_lamps(); // the lamps are only seen (no circuit reads them)
        }
    }
    // Lamps 270 (absolute comparer 122' conducting) and 272 (incremental comparer 122''
    // conducting) light whenever speed switch 236 stands on off (contact 238) and their
    // comparer conducts (col. 11). With the interpretation lamps_only_on_trip they light only
    // once balancing circuit 266 has tripped (tripped = true).
    void show_lamps() {
        tracer.set(lamp_270_, lamp_270_lit() ? 1 : 0);
        tracer.set(lamp_272_, lamp_272_lit() ? 1 : 0);
    }
    bool lamp_270_lit() const { return lamps_live() && absolute_conducting; }
    bool lamp_272_lit() const { return lamps_live() && incremental_conducting; }
    bool lamps_live() const { return speed_switch.off() && (!lamps_only_on_trip_ || tripped); }
    void set_powered(bool on) {
        powered = on;
        tracer.set(motor_, on ? 1 : 0);
    }
    // Commutators 96, 98, 100, 102 (gear train 82-92), each with two contact sets A and B: a
    // set's contact changes over at each impulse it sends (segments alternate round the
    // commutator), so its state is the parity of the commutator's position in its unit (1, 0.1,
    // 0.01, 0.001 in). Set B of 102 lags A by the impulses it missed. Traced only.
    void show_contacts() {
        if (tracer.observer() != nullptr) {
            trace_contacts();
        }
    }
    // The state a saved machine keeps (relaylogic/machine_state.cpp).
    nlohmann::json save() const;
    void load(const nlohmann::json& j);

    Tracer& tracer;
    cardreader::Axis axis;
    axes::LeadScrewAxis plant;
    AbsoluteStorage absolute_storage;
    IncrementalStorage incremental_storage;
    AbsoluteCounter absolute_counter;
    IncrementCounter increment_counter;
    SpeedSwitch speed_switch;
    SequenceSwitch sequence_switch;

    int direction = +1;                  // reversing control 214
    bool absolute_conducting = false;    // comparer 122'
    bool incremental_conducting = false; // comparer 122''
    bool powered = false;                // current through cable 248 to the motor
    bool stopped = false;                // reached its stop on this card
    bool tripped = false;                // balancing circuit 266 tripped at this axis's stop
    std::int64_t contact_set_a = 0;      // impulses seen by each contact set of commutator 102
    std::int64_t contact_set_b = 0;
    // What the counters miscounted, as tallies for the summary (nothing reads them in the run):
    // impulses counted against the way the screw turned (coast that ran on after reversing
    // control 214 was set for the next card), and impulses switch 110 stood for
    // (count_hundredths_at_speed_1).
    std::int64_t wrong_way = 0;
    std::int64_t thousandths_uncounted = 0;
    // Where the motion cards read so far put the part, in thousandths from the reference zero:
    // the sum of their checks, each in the sense of its motion column (tap cards come back;
    // the other later cards move no axis by the 1952 columns). A tally of the deck's orders for
    // the summary, no part of the 1952 machine: nothing in the run reads it.
    std::int64_t ordered = 0;
    cardreader::AxisOrder order;

private:
    void trace_contacts();

    SignalId reversing_214_;
    SignalId comparer_absolute_;
    SignalId comparer_incremental_;
    SignalId motor_;
    std::array<SignalId, 8> contacts_{}; // 96 A, 96 B, 98 A, 98 B, 100 A, 100 B, 102 A, 102 B
    SignalId lamp_270_;
    SignalId lamp_272_;
    bool lamps_only_on_trip_;
};

} // namespace parsons::relaylogic
