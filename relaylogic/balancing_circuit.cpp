#include "relaylogic/balancing_circuit.hpp"

namespace parsons::relaylogic {

BalancingCircuit::BalancingCircuit(Tracer& tracer)
    : tracer_(tracer), master_204_(tracer.define("cabinet", "master_switch_204",
                                                 "master switch (1 = closed)", "204", 1, 1)),
      magnet_265_(tracer.define("cabinet", "electromagnet_265",
                                "electromagnet on the master "
                                "switch",
                                "265", 1)),
      indicator_268_(tracer.define("cabinet", "indicator_268",
                                   "audible indicator in circuit "
                                   "262-264",
                                   "268", 1)),
      lamp_270_(tracer.define("cabinet", "lamp_270", "lamp: absolute comparer 122' conducting",
                              "270", 1)),
      lamp_272_(tracer.define("cabinet", "lamp_272",
                              "lamp: incremental comparer 122'' "
                              "conducting",
                              "272", 1)) {}

void BalancingCircuit::trip() {
    if (!master_closed_) {
        return;
    }
    master_closed_ = false;
    tracer_.set(magnet_265_, 1);
    tracer_.set(indicator_268_, 1);
    tracer_.set(master_204_, 0);
    lamps_.insert(lamps_.begin(), "indicator 268");
}

bool BalancingCircuit::check_at_stop(bool absolute, bool incremental) {
    if (absolute == incremental) {
        return absolute; // both conducting: balanced (neither cannot reach contact 238)
    }
    trip();
    if (absolute) {
        tracer_.set(lamp_270_, 1);
        lamps_.push_back("lamp 270 (absolute comparer 122' conducting)");
    } else {
        tracer_.set(lamp_272_, 1);
        lamps_.push_back("lamp 272 (incremental comparer 122'' conducting)");
    }
    return false;
}

} // namespace parsons::relaylogic
