// Speed register 11 of EP 0436887 (Mitsubishi): an addition, not in the 1952
// patent. It "reads the pulse train signal at predetermined intervals and stores the read
// signal serially as speed data": the speed of crank 21 as detector pulses per sampling
// interval.
//
// Built as relays: a counter of four stepping switches in series counts every pulse of
// detector 10 (whichever the sense: the speed, not the velocity); at each sampling instant
// (the reference block of Fig. 6, the profile's speed_sample_s) its reading is picked into a
// bank of holding relays, the stored speed data, and the counter homes for the next interval.
// Processor 63 reads the bank.
#pragma once

#include "relaylogic/press/direction_judging_device.hpp"

#include "relaylogic/counters.hpp"
#include "relaylogic/tracer.hpp"

#include <nlohmann/json.hpp>

namespace parsons::relaylogic {

class SpeedRegister {
public:
    // source names the signals: the press's register 11, or interface 33's count of encoder 32
    // edges per sample (the speed S of motor 27, EP 0360190).
    explicit SpeedRegister(Tracer& tracer, PulseSource source = PulseSource::press_detector_10);
    void pulse() { count_many(1); }
    void count_many(std::int64_t n);
    // The sampling instant: the count moves into the holding bank; the counter homes.
    void sample();
    int stored() const { return stored_; }  // pulses in the last whole interval
    int counting() const { return count_; } // pulses so far in this one
    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    Tracer& tracer_;
    int count_ = 0;
    int stored_ = 0;
    SignalId count_signal_ = 0;
    SignalId stored_signal_ = 0;
};

} // namespace parsons::relaylogic
