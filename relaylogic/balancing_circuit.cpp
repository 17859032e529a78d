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
      circuit_266_(tracer.define("cabinet", "balancing_circuit_266",
                                 "balancing circuit 266 unbalanced (one comparer at contact 238)",
                                 "266", 1)) {}

void BalancingCircuit::trip() {
    if (!master_closed_) {
        return;
    }
    master_closed_ = false;
    tracer_.set(magnet_265_, 1);
    tracer_.set(master_204_, 0); // electromagnet 265 opens it
    tracer_.set(indicator_268_, 1);
    lamps_.insert(lamps_.begin(), "indicator 268");
}

void BalancingCircuit::open_by_operator() {
    if (!master_closed_) {
        return;
    }
    master_closed_ = false;
    tracer_.set(master_204_, 0);
}

bool BalancingCircuit::check_at_stop(bool absolute, bool incremental) {
    if (absolute == incremental) {
        return absolute; // both conducting: balanced (neither cannot reach contact 238)
    }
    tracer_.set(circuit_266_, 1); // the cause, then its effects: 265, 204, 268
    trip();
    return false;
}

} // namespace parsons::relaylogic
