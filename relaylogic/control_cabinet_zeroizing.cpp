// Control cabinet 52, the zeroizing circuit 290-304: contact 290 closes circuit 292-294 and
// its channels clear storage and the increment counters, open the sequence contacts, reset
// device 288 and index the reader to the next card (col. 11).
#include "relaylogic/control_cabinet.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace parsons::relaylogic {

// Contact 290 closed circuit 292-294: the zeroizing circuit, one channel after the other, each
// signal set before the relays it acts on (col. 11). Emulation note: the speed switches stand
// on off already (every axis stopped); the cabinet resets their delay devices here.
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
        c->speed_switch.reset();
        c->stopped = false;
        c->tripped = false;
        c->compare();
    }
    tracer_.set(channel_302_, 1); // resets device 288, closing circuit 274
    shaft_.reset();
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
