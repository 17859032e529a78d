// Control cabinet 52, the zeroizing circuit 290-304: contact 290 closes circuit 292-294 and
// its channels clear storage and the increment counters, open the sequence contacts, reset
// device 288 and index the reader to the next card (col. 11).
#include "relaylogic/control_cabinet.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace parsons::relaylogic {

// Contact 290 closed circuit 292-294: the zeroizing circuit, one channel after the other, each
// signal set before the relays it acts on. Zeroizing "clears the numbers stored in the absolute
// comparer 122', clears both the number and counter circuits of the incremental comparer 122"
// through channel 298, opens all the contacts of the sequence switch mechanisms 224 through
// channel 300, actuates device 288 through channel 302 to close circuit 274, and indexes the
// card reader through channel 304" (col. 13). Nothing else: the speed switches already stand on
// off (every axis stopped), and delay 258 is a timed hold that runs out in its own time, on the
// next card if it must (docs/design-rules.md rules 5 and 8).
void ControlCabinet::zeroize() {
    tracer_.set(zeroizing_, 1);
    tracer_.set(channel_294_, 1); // clears absolute storage 350-356 (122')
    for (auto& c : circuits_) {
        c->absolute_storage.clear();
    }
    tracer_.set(channel_298_, 1); // clears number and counter of the incremental comparer 122''
    for (auto& c : circuits_) {
        c->incremental_storage.clear();
        c->increment_counter.clear();
    }
    tracer_.set(channel_300_, 1); // opens every contact of the sequence switches 224
    for (auto& c : circuits_) {
        c->sequence_switch.open_all();
        c->compare();
    }
    tracer_.set(channel_302_, 1); // actuates device 288: circuit 274 closed again
    shaft_.reset();
    for (auto& c : circuits_) {
        c->stopped = false; // 288's break behind this axis's stop impulse
        c->tripped = false;
        c->compare();
        // Storage is clear, so neither comparer conducts: the equality has left (what the
        // interpretation delay_258_waits_for_equality_to_leave waits for), and a hold that has
        // run out by now releases (with no observer its release after the stop was not queued,
        // release_after_stop: a saved state is the same either way).
        if (!c->absolute_conducting && !c->incremental_conducting) {
            c->speed_switch.equality_left(now_);
        }
    }
    for (const auto& a : attachments_) {
        a->zeroized(*this); // e.g. channel 294 clears PFR and PRG too
    }
    tracer_.set(channel_304_, 1); // indexes card reader 134 to the next card
    reading_complete_ = false;
    update_motors();
    if (record_times_) {
        timings_.back().end_s = now_;
    }
    schedule(now_ + profile_.relay_release_s, EventKind::feed); // channel 304
}

} // namespace parsons::relaylogic
