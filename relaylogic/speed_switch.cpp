#include "relaylogic/speed_switch.hpp"

namespace parsons::relaylogic {

SpeedSwitch::SpeedSwitch(Tracer& tracer, const std::string& scope)
    : tracer_(tracer),
      switch_signal_(tracer.define(scope, "speed_switch_236", "speed switch (0 = off, contact 238)",
                                   "236", 2)),
      relay_256_(tracer.define(scope, "stepping_relay_256", "stepping relay", "256", 1)),
      delay_258_(tracer.define(scope, "delay_device_258",
                               "delay device (1 = channel 257 held open)", "258", 1)) {}

void SpeedSwitch::step_from_card() {
    position_ = (position_ + 1) % 4;
    tracer_.set(switch_signal_, static_cast<std::uint32_t>(position_));
}

void SpeedSwitch::hold(double t, double hold_s) {
    hold_until_ = t + hold_s;
    left_equality_ = false;
    tracer_.set(relay_256_, 1);
    tracer_.set(delay_258_, 1);
}

void SpeedSwitch::step_slower(double t, double hold_s) {
    position_ = position_ >= 3 ? 0 : position_ + 1;
    tracer_.set(switch_signal_, static_cast<std::uint32_t>(position_));
    hold(t, hold_s);
}

void SpeedSwitch::to_off(double t, double hold_s) {
    position_ = 0;
    tracer_.set(switch_signal_, 0);
    hold(t, hold_s);
}

void SpeedSwitch::hold_expired(double t) {
    if (left_equality_ && t >= hold_until_) {
        tracer_.set(relay_256_, 0);
        tracer_.set(delay_258_, 0);
    }
}

void SpeedSwitch::reset() {
    position_ = 0;
    hold_until_ = 0;
    left_equality_ = true;
    tracer_.set(switch_signal_, 0);
    tracer_.set(relay_256_, 0);
    tracer_.set(delay_258_, 0);
}

} // namespace parsons::relaylogic
