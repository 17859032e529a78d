// Checking and warning (Fig. 10): balancing circuit 266 with electromagnet 265 on master
// switch 204, and indicator 268. Lamps 270 and 272 belong to each axis's circuit
// (relaylogic/axis_circuit.hpp).
//
// When speed switch 236 reaches off (contact 238) both comparers must conduct at that moment.
// If only one does, the vacuum-tube balancing circuit 266 closes circuit 262-264: indicator
// 268 sounds and electromagnet 265 opens master switch 204 (every motor loses power). With the
// switch on off, lamp 270 is lit if absolute comparer 122' is conducting, lamp 272 if
// incremental comparer 122'' is: the dark one shows which comparer was not functioning. The
// other checks (card number, duplicate contacts, limit switches) open the master switch the
// same way and light a lamp of their own.
#pragma once

#include "relaylogic/tracer.hpp"

#include <string>
#include <vector>

namespace parsons::relaylogic {

class BalancingCircuit {
public:
    explicit BalancingCircuit(Tracer& tracer);

    bool master_switch_closed() const { return master_closed_; }

    // At contact 238: returns true if balanced; otherwise trips and names the lit lamp.
    bool check_at_stop(bool absolute_conducting, bool incremental_conducting);
    // Another check fired: open the master switch and sound indicator 268.
    void trip();
    // The operator opened master switch 204 by hand (Ctrl-C, SIGTERM): no check fired, so
    // electromagnet 265 stays still, indicator 268 silent and no lamp of the stop lights.
    void open_by_operator();
    // Indicator 268 sounding (a check tripped the circuit), then the check lamps the additions
    // lit (light()); lamps 270 and 272 are each axis's (AxisCircuit::lamp_270_lit), and the
    // cabinet reads the whole panel (ControlCabinet::panel_lamps).
    std::vector<std::string> lamps() const { return lamps_; }
    void light(const std::string& lamp) { lamps_.push_back(lamp); }

private:
    Tracer& tracer_;
    bool master_closed_ = true;
    std::vector<std::string> lamps_;
    SignalId master_204_;
    SignalId magnet_265_;
    SignalId indicator_268_;
    SignalId circuit_266_;
};

} // namespace parsons::relaylogic
