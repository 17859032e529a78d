// Sequence control (Fig. 10): sequence switches 224, one per axis, and the stepping shaft 280
// common to all of them.
//
// Each switch 224 has five contacts 226, 228, 230, 232, 234, closed by electromagnets from the
// punches of the axis's sequence pattern 222 (the row of cross marks). Rotary member 282 of
// every switch sits on shaft 280, driven by motor 278: it sweeps positions 1 -> 5, and an axis
// runs while the contact under the member is closed and it has not yet stopped.
//
// Each axis that stops sends one impulse through contact 238, circuit 268, channel 274 and
// circuit 276 to motor 278 (traced: channel_274 carries the impulse, circuit_276 conducts and
// motor_278 runs while the shaft takes its step). Unit 284 senses two impulses arriving together
// and adds one, so simultaneous stops count as separate impulses. "At the time the circuit 276 is
// delivering current to operate the sequence switch mechanisms a device indicated at 288 breaks
// the circuit 276 so that the circuit discontinues conducting after delivering its impulse"
// (col. 13): contact 238 of a stopped axis stays closed, so 288 breaks its path behind the
// impulse and each stop steps the shaft exactly once. The break holds until zeroizing "actuates
// device 288 through channel 302 to close circuit 274". The break is per axis: the trace's
// cabinet.device_288 holds one bit per axis (1 table, 2 cross, 4 vertical, 8 swivel, 16 tilt),
// set when the step that axis's impulse drove is done and cleared only at channel 302; in the
// machine the break behind an axis is AxisCircuit::stopped, which only channel 302 clears. After
// the fifth impulse the members return to position 1, engaging contact 290: the zeroizing circuit
// 292-304 fires.
#pragma once

#include "cardreader/orders.hpp"
#include "relaylogic/tracer.hpp"

#include <array>

namespace parsons::relaylogic {

// The contacts of sequence switch 224 by sequence position 1..5 (the reader's wiring names them
// too, relaylogic/card_reader.cpp).
inline constexpr std::array<int, 5> kSequenceContacts = {226, 228, 230, 232, 234};

class SequenceSwitch {
public:
    SequenceSwitch(Tracer& tracer, const std::string& scope);
    // The reader's first brush bank, over cable 223.
    void close_pattern(cardreader::SequencePattern pattern);
    // Zeroizing, channel 300.
    void open_all();
    bool closed(int position) const { return closed_.at(static_cast<std::size_t>(position - 1)); }
    cardreader::SequencePattern pattern() const;
    // The state a saved machine keeps (relaylogic/machine_state.cpp).
    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    Tracer& tracer_;
    std::array<bool, 5> closed_{};
    std::array<SignalId, 5> signals_{}; // contacts 226, 228, 230, 232, 234
};

class SteppingShaft {
public:
    explicit SteppingShaft(Tracer& tracer);

    int position() const { return position_; } // 1..5, the contact under rotary member 282
    bool busy() const { return busy_; }
    int pending() const { return pending_; }

    // An axis stopped: one impulse to motor 278. Returns true if unit 284 had to count it as
    // an extra impulse (it arrived together with another).
    bool impulse(double t, cardreader::Axis from);
    // Motor 278 begins one step.
    void begin_step();
    // The step is done: circuit 276 has delivered the oldest pending impulse and device 288
    // breaks the path of the axis it came from (its bit in device_288()). Returns
    // true when the members came round to position 1 past contact
    // 290 (the fifth impulse): the zeroizing circuit fires.
    bool finish_step();
    // Zeroizing, channel 302: device 288 closes circuit 274 again.
    void reset();
    // The axes whose path device 288 has broken: bit axis_index (1 table ... 16 tilt).
    std::uint32_t device_288() const { return broken_; }
    // The state a saved machine keeps (relaylogic/machine_state.cpp).
    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    Tracer& tracer_;
    int position_ = 1;
    int pending_ = 0;
    bool busy_ = false;
    double last_impulse_t_ = -1;
    std::array<std::uint8_t, 5> from_{}; // the axes of the pending impulses, oldest first
    std::uint32_t broken_ = 0;           // device 288's breaks, one bit an axis
    SignalId shaft_signal_;
    SignalId channel_274_;
    SignalId circuit_276_;
    SignalId motor_278_;
    SignalId unit_284_;
    SignalId device_288_;
    SignalId contact_290_;
};

} // namespace parsons::relaylogic
