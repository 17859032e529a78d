#include "relaylogic/counters.hpp"

namespace parsons::relaylogic {
namespace {

std::int64_t total_lost(const std::array<SteppingSwitch, 4>& switches) {
    std::int64_t n = 0;
    for (const auto& s : switches) {
        n += s.lost();
    }
    return n;
}

} // namespace

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

void AbsoluteCounter::jump(const Digits& positions, const std::array<double, 4>& last_step_s,
                           std::int64_t inch_turns) {
    for (std::size_t i = 0; i < 4; ++i) {
        switches_.at(i).jump(positions.at(i), last_step_s.at(i), i == 0 ? inch_turns : 0);
        tracer_.set(signals_.at(i), static_cast<std::uint32_t>(positions.at(i)));
    }
}

std::int64_t AbsoluteCounter::lost() const {
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

void IncrementCounter::hundredths_impulse(double t, double min_interval_s) {
    step_from(1, t, min_interval_s);
}

void IncrementCounter::jump(const Digits& positions, const std::array<double, 4>& last_step_s) {
    for (std::size_t i = 0; i < 4; ++i) {
        switches_.at(i).jump(positions.at(3 - i), last_step_s.at(i));
        tracer_.set(signals_.at(i), static_cast<std::uint32_t>(positions.at(3 - i)));
    }
}

void IncrementCounter::clear() {
    for (std::size_t i = 0; i < 4; ++i) {
        switches_.at(i).home();
        tracer_.set(signals_.at(i), 0);
    }
}

std::int64_t IncrementCounter::lost() const {
    return total_lost(switches_);
}

} // namespace parsons::relaylogic
