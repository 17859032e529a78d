#include "relaylogic/speed_switch.hpp"

namespace parsons::relaylogic {

SpeedSwitch::SpeedSwitch(Tracer& tracer, const std::string& scope, bool waits_for_leave)
    : tracer_(tracer), waits_for_leave_(waits_for_leave),
      switch_signal_(tracer.define(scope, "speed_switch_236", "speed switch (0 = off, contact 238)",
                                   "236", 2)),
      contact_238_(tracer.define(
          scope, "contact_238", "contact 238: speed switch 236 on off (circuit 268)", "238", 1, 1)),
      channel_257_(tracer.define(scope, "channel_257",
                                 "channel 257: an equality impulse on its way to stepping relay "
                                 "256",
                                 "257", 1)),
      relay_256_(tracer.define(scope, "stepping_relay_256", "stepping relay", "256", 1)),
      delay_258_(tracer.define(scope, "delay_device_258",
                               "delay device (1 = channel 257 held open)", "258", 1)) {}

// The switch, then contact 238 it engages or leaves: cause before effect.
void SpeedSwitch::show_position() {
    tracer_.set(switch_signal_, static_cast<std::uint32_t>(position_));
    tracer_.set(contact_238_, position_ == 0 ? 1 : 0);
}

void SpeedSwitch::step_from_card() {
    position_ = (position_ + 1) % 4;
    show_position();
}

void SpeedSwitch::hold(double t, double hold_s) {
    hold_until_ = t + hold_s;
    left_equality_ = false;
    held_ = true;
    tracer_.set(delay_258_, 1);
    tracer_.set(channel_257_, 0); // 258 opens channel 257: the impulse has been delivered
}

void SpeedSwitch::impulse_256(double t, double hold_s) {
    tracer_.set(channel_257_, 1);
    tracer_.set(relay_256_, 1);
    position_ = position_ >= 3 ? 0 : position_ + 1;
    show_position();
    hold(t, hold_s);
}

void SpeedSwitch::to_off(double t, double hold_s) {
    tracer_.set(channel_257_, 1);
    tracer_.set(relay_256_, 1);
    position_ = 0;
    show_position();
    hold(t, hold_s);
}

} // namespace parsons::relaylogic
