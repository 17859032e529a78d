// The two counters of each axis (Fig. 3, Figs. 11 and 12).
//
// Absolute counter 104-110: four stepping switches, each driven by its own geared commutator
// (96 inches, 98 tenths, 100 hundredths, 102 thousandths), stepping up or down as reversing
// control 214 set them. They do not carry into each other: the gearing does that. Its reading
// is the position from the reference zero.
//
// Increment counter 112: four stepping switches 310 (thousandths) .. 316 (inches) in series,
// fed by commutator 102 over channel 120, each stepping once per ten steps of the one before
// over channel 333. It counts travel since this card began, up whichever way the screw turns,
// and the zeroizing circuit homes it before each card.
#pragma once

#include "relaylogic/stepping_switch.hpp"
#include "relaylogic/tracer.hpp"

#include <array>

namespace parsons::relaylogic {

// Digits from the inch down: {inches, tenths, hundredths, thousandths}.
using Digits = std::array<int, 4>;

inline int digits_value(const Digits& d) { // thousandths
    return ((d[0] * 10 + d[1]) * 10 + d[2]) * 10 + d[3];
}
Digits value_digits(int thousandths);

class AbsoluteCounter {
public:
    AbsoluteCounter(Tracer& tracer, const std::string& scope);

    // One crossing of the commutators: 102 always, 100 / 98 / 96 when they close too. With
    // count_thousandths false, commutator 102's impulse is not counted (switch 110 stands):
    // the patent's counting of hundredths only, at high speed.
    // Returns whether any switch stepped (the reading changed).
    bool impulse(int direction, bool hundredths, bool tenths, bool inches, double t,
                 double min_interval_s, bool count_thousandths = true) {
        bool stepped = false;
        if (count_thousandths) {
            stepped = step(3, direction, t, min_interval_s);
        }
        if (hundredths) {
            stepped = step(2, direction, t, min_interval_s) || stepped;
            if (tenths) {
                stepped = step(1, direction, t, min_interval_s) || stepped;
                if (inches) {
                    stepped = step(0, direction, t, min_interval_s) || stepped;
                }
            }
        }
        return stepped;
    }

    Digits digits() const {
        return {switches_[0].position(), switches_[1].position(), switches_[2].position(),
                switches_[3].position()};
    }
    int value() const { return digits_value(digits()); }
    std::int64_t lost() const;
    // Switch i of {104, 106, 108, 110}.
    const SteppingSwitch& stepping_switch(std::size_t i) const { return switches_.at(i); }
    SteppingSwitch& stepping_switch(std::size_t i) { return switches_.at(i); }
    // Fast-forward: every switch stands where a stretch of ready impulses left it, switch 104
    // having passed 9 -> 0 net `inch_turns` times.
    void jump(const Digits& positions, const std::array<double, 4>& last_step_s,
              std::int64_t inch_turns = 0);
    // The reading with the inch switch's wrap-arounds counted (thousandths; may pass 9999 or
    // go below 0): what the counter has counted, for the report's position error.
    std::int64_t unwrapped_value() const {
        return value() + std::int64_t{10000} * switches_[0].turns();
    }
    // The state a saved machine keeps (relaylogic/machine_state.cpp).
    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    bool step(std::size_t i, int direction, double t, double min_interval_s) {
        SteppingSwitch& sw = switches_[i];
        if (sw.step(direction, t, min_interval_s).taken) {
            tracer_.set(signals_[i], static_cast<std::uint32_t>(sw.position()));
            return true;
        }
        return false;
    }

    Tracer& tracer_;
    std::array<SteppingSwitch, 4> switches_; // 104, 106, 108, 110
    std::array<SignalId, 4> signals_{};
};

class IncrementCounter {
public:
    IncrementCounter(Tracer& tracer, const std::string& scope);

    // One impulse from commutator 102 (channel 120): 310 steps, carries ripple over 333.
    void impulse(double t, double min_interval_s) { step_from(0, t, min_interval_s); }
    // Counting hundredths only: commutator 100's impulse steps 312 directly (310 stands).
    void hundredths_impulse(double t, double min_interval_s);
    // Zeroizing circuit, channel 298: every switch homes.
    void clear();

    Digits digits() const { // {316, 314, 312, 310}
        return {switches_[3].position(), switches_[2].position(), switches_[1].position(),
                switches_[0].position()};
    }
    int value() const { return digits_value(digits()); }
    std::int64_t lost() const;
    // Switch i of {310, 312, 314, 316}.
    const SteppingSwitch& stepping_switch(std::size_t i) const { return switches_.at(i); }
    SteppingSwitch& stepping_switch(std::size_t i) { return switches_.at(i); }
    // Fast-forward: positions {316, 314, 312, 310} and last steps {310, 312, 314, 316}.
    void jump(const Digits& positions, const std::array<double, 4>& last_step_s);
    // The state a saved machine keeps (relaylogic/machine_state.cpp).
    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    void step_from(std::size_t first, double t, double min_interval_s) {
        for (std::size_t i = first; i < 4; ++i) {
            SteppingSwitch::Step s = switches_[i].step(+1, t, min_interval_s);
            if (!s.taken) {
                return;
            }
            tracer_.set(signals_[i], static_cast<std::uint32_t>(switches_[i].position()));
            if (!s.carry) {
                return; // no carry over channel 333
            }
        }
    }

    Tracer& tracer_;
    std::array<SteppingSwitch, 4> switches_; // 310, 312, 314, 316 (thousandths first)
    std::array<SignalId, 4> signals_{};
};

} // namespace parsons::relaylogic
