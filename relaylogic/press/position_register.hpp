// Position register 14 of EP 0436887 (Mitsubishi), with setter 15, position input
// device 16 and reset switch 16A: an addition, not in the 1952 patent. "A position register 14
// accumulates positive and negative-direction pulses output by the direction judging device
// 13, and a setter 15 presets position data in the position register 14"; "the position
// register 14 is set to 0 by the setter 15 when the angular position reaches 360 deg (0 deg) at
// each rotation", the value set on device 16 (claim 5: "selectively resettable at a reference
// position").
//
// Built as the 1952 cabinet builds a counter: four ten-position stepping switches (units, tens,
// hundreds, thousands of detector pulses) in series, each stepping once per ten steps of the one
// before, up or down as device 13 judged the edge (the increment counter 310-316 with a
// borrow). Device 16 is a row of four decade switches set to a revolution's pulses (360 x
// pulses a degree); a comparer on the register's wipers against it operates setter 15, which
// homes every switch (the crank at top dead centre again). Counting down below zero, setter 15
// presets device 16's value less one. Switch 16A homes the register wherever the crank stands:
// the register starts the run lined up with top dead centre, and a sync card's reset order
// operates the switch as the card is read, so that the crank's angle there becomes the reference
// every later R, and setter 15's revolution, counts from.
//
// The register's switches step at the detector's rate; the profile keeps that under the
// stepping switches' fastest rate (a press whose pulses come faster is refused when the
// profile is loaded), so no count is lost to a moving wiper.
#pragma once

#include "relaylogic/press/direction_judging_device.hpp"

#include "relaylogic/counters.hpp"
#include "relaylogic/tracer.hpp"

#include <nlohmann/json.hpp>

#include <optional>

namespace parsons::relaylogic {

class PositionRegister {
public:
    // device_16: a revolution in pulses (1 .. 9999); the register stands at `value` (0 ..
    // device_16 - 1) when the run starts.
    // source names the signals: the press's register 14, or the encoder counter of spindle
    // encoder interface 33 (EP 0360190), device 16 then being a motor revolution's edges.
    PositionRegister(Tracer& tracer, int device_16, int value = 0,
                     PulseSource source = PulseSource::press_detector_10);

    // One count from device 13 (+1 up, -1 down).
    void count(int sense);
    // Setter 15 presets a value (0 .. device 16 - 1).
    void preset(int value);
    // Switch 16A, operated by a sync card's reset order (claim 5: "selectively resettable at a
    // reference position"): the register homes wherever the crank stands, which becomes the
    // reference position every later angle counts from.
    void switch_16A();
    // The switch's contact opens again (at the next reference block: the same instant at
    // either pace, where an edge may be taken in a jump).
    void release_16A();
    // Fast-forward: n counts in one sense at once (what n single counts leave).
    void count_many(std::int64_t n, int sense);
    int value() const { return value_; }
    int device_16() const { return device_16_; }
    Digits digits() const { return value_digits(value_); }
    // Each time setter 15 operated (the crank passing top dead centre), for the report.
    std::int64_t presets() const { return presets_; }
    // Each time switch 16A operated, for the report.
    std::int64_t resets() const { return resets_; }
    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    void show();

    Tracer& tracer_;
    int device_16_;
    int value_ = 0;
    std::int64_t presets_ = 0;
    std::int64_t resets_ = 0;
    std::array<SignalId, 4> switches_{};
    SignalId setter_15_ = 0;
    std::optional<SignalId> switch_16A_; // the press's register only
    SignalId value_signal_ = 0;
};

} // namespace parsons::relaylogic
