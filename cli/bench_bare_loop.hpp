// The bare stepping-chain loop `parsons bench` prints beside the impulse level (issue 51): the
// least an impulse of the 1952 machine can cost in this emulator. An impulse steps the two
// counters of its axis (absolute counter 104-110 through commutators 96-102, increment counter
// 310-316 through channel 120 and its carries over channel 333), each switch with its stepping
// rate check; the loop does that and nothing else, on the project's own classes
// (relaylogic/counters.hpp), with no observer. Everything the impulse level does besides
// (the lead screw's motion, the comparers, speed switch 236, the limits, the event loop) is what
// its ratio to this loop measures.
#pragma once

#include <cstdint>

namespace parsons::cli::bench {

struct BareLoop {
    std::int64_t impulses = 0;
    double seconds = 0;       // the median of the runs
    std::int64_t reading = 0; // the absolute counter's last reading (so the loop is not elided)
};

// `impulses` impulses through one axis's two counters, forward, 1 / 10,000 s apart (every
// step found the switch ready), `runs` times: the median time.
BareLoop bare_stepping_chain(std::int64_t impulses, int runs);

} // namespace parsons::cli::bench
