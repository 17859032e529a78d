#include "relaylogic/press/speed_register.hpp"

#include "axes/state_json.hpp"

#include <algorithm>

namespace parsons::relaylogic {

SpeedRegister::SpeedRegister(Tracer& tracer, PulseSource source) : tracer_(tracer) {
    if (source == PulseSource::spindle_encoder_32) {
        count_signal_ = tracer.define("spindle", "interface_33.speed_counter",
                                      "interface 33: encoder 32 edges counted in this sample "
                                      "(speed register 11 of EP 0436887 reused)",
                                      "33", 14);
        stored_signal_ = tracer.define("spindle", "interface_33.speed_stored",
                                       "interface 33: the edges of the last whole sample, the "
                                       "motor speed S the NC reads (EP 0360190)",
                                       "33", 14);
        return;
    }
    count_signal_ = tracer.define("press", "speed_register_11.counter",
                                  "speed register 11: detector pulses counted in this "
                                  "sampling interval (EP 0436887)",
                                  "11", 14);
    stored_signal_ = tracer.define("press", "speed_register_11.stored",
                                   "speed register 11: holding relays with the pulses of the "
                                   "last whole interval, the speed data processor 63 reads",
                                   "11", 14);
}

void SpeedRegister::count_many(std::int64_t n) {
    // Four decades; the profile keeps an interval's pulses under 10000 (a wrap would be the
    // counter's own, as on any stepping-switch counter).
    count_ = static_cast<int>((count_ + n) % 10000);
    tracer_.set(count_signal_, static_cast<std::uint32_t>(count_));
}

void SpeedRegister::sample() {
    stored_ = count_;
    count_ = 0;
    tracer_.set(stored_signal_, static_cast<std::uint32_t>(stored_));
    tracer_.set(count_signal_, 0);
}

nlohmann::json SpeedRegister::save() const {
    return {{"count", count_}, {"stored", stored_}};
}

void SpeedRegister::load(const nlohmann::json& j) {
    count_ = std::clamp(axes::read<int>(j, "count"), 0, 9999);
    stored_ = std::clamp(axes::read<int>(j, "stored"), 0, 9999);
}

} // namespace parsons::relaylogic
