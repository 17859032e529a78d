#include "relaylogic/counters.hpp"

namespace parsons::relaylogic {
namespace {

long total_lost(const std::array<SteppingSwitch, 4>& switches) {
    long n = 0;
    for (const auto& s : switches) {
        n += s.lost();
    }
    return n;
}

} // namespace

int digits_value(const Digits& d) {
    return ((d[0] * 10 + d[1]) * 10 + d[2]) * 10 + d[3];
}

Digits value_digits(int v) {
    v = ((v % 10000) + 10000) % 10000;
    return {v / 1000, v / 100 % 10, v / 10 % 10, v % 10};
}

AbsoluteCounter::AbsoluteCounter(Tracer& tracer, const std::string& scope) : tracer_(tracer) {
    const std::array<const char*, 4> names = {"104", "106", "108", "110"};
    const std::array<const char*, 4> what = {"inches", "tenths", "hundredths", "thousandths"};
    for (std::size_t i = 0; i < 4; ++i) {
        signals_.at(i) = tracer.define(
            scope, std::string("absolute_counter_") + names.at(i),
            std::string("absolute counter stepping switch (") + what.at(i) + ")", names.at(i), 4);
    }
}

void AbsoluteCounter::step(std::size_t i, int direction, double t, double min_interval_s) {
    SteppingSwitch& sw = switches_.at(i);
    if (sw.step(direction, t, min_interval_s).taken) {
        tracer_.set(signals_.at(i), static_cast<std::uint32_t>(sw.position()));
    }
}

void AbsoluteCounter::impulse(int direction, bool hundredths, bool tenths, bool inches, double t,
                              double min_interval_s, bool count_thousandths) {
    if (count_thousandths) {
        step(3, direction, t, min_interval_s);
    }
    if (hundredths) {
        step(2, direction, t, min_interval_s);
    }
    if (tenths) {
        step(1, direction, t, min_interval_s);
    }
    if (inches) {
        step(0, direction, t, min_interval_s);
    }
}

Digits AbsoluteCounter::digits() const {
    return {switches_[0].position(), switches_[1].position(), switches_[2].position(),
            switches_[3].position()};
}

long AbsoluteCounter::lost() const {
    return total_lost(switches_);
}

IncrementCounter::IncrementCounter(Tracer& tracer, const std::string& scope) : tracer_(tracer) {
    const std::array<const char*, 4> names = {"310", "312", "314", "316"};
    const std::array<const char*, 4> what = {"thousandths", "hundredths", "tenths", "inches"};
    for (std::size_t i = 0; i < 4; ++i) {
        signals_.at(i) =
            tracer.define(scope, std::string("increment_counter_") + names.at(i),
                          std::string("increment counter 112 stepping switch (") + what.at(i) + ")",
                          names.at(i), 4);
    }
}

void IncrementCounter::impulse(double t, double min_interval_s) {
    step_from(0, t, min_interval_s);
}

void IncrementCounter::hundredths_impulse(double t, double min_interval_s) {
    step_from(1, t, min_interval_s);
}

void IncrementCounter::step_from(std::size_t first, double t, double min_interval_s) {
    for (std::size_t i = first; i < 4; ++i) {
        SteppingSwitch::Step s = switches_.at(i).step(+1, t, min_interval_s);
        if (!s.taken) {
            return;
        }
        tracer_.set(signals_.at(i), static_cast<std::uint32_t>(switches_.at(i).position()));
        if (!s.carry) {
            return; // no carry over channel 333
        }
    }
}

void IncrementCounter::clear() {
    for (std::size_t i = 0; i < 4; ++i) {
        switches_.at(i).home();
        tracer_.set(signals_.at(i), 0);
    }
}

Digits IncrementCounter::digits() const {
    return {switches_[3].position(), switches_[2].position(), switches_[1].position(),
            switches_[0].position()};
}

long IncrementCounter::lost() const {
    return total_lost(switches_);
}

} // namespace parsons::relaylogic
