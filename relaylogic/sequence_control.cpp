#include "relaylogic/sequence_control.hpp"

#include <algorithm>

namespace parsons::relaylogic {

SequenceSwitch::SequenceSwitch(Tracer& tracer, const std::string& scope) : tracer_(tracer) {
    for (std::size_t i = 0; i < 5; ++i) {
        const std::string numeral = std::to_string(kSequenceContacts.at(i));
        signals_.at(i) = tracer.define(
            scope, "sequence_switch_224.contact_" + numeral,
            "sequence switch 224 contact for position " + std::to_string(i + 1), numeral, 1);
    }
}

void SequenceSwitch::close_pattern(cardreader::SequencePattern pattern) {
    for (std::size_t i = 0; i < 5; ++i) {
        if ((pattern & (1u << i)) != 0) {
            closed_.at(i) = true;
            tracer_.set(signals_.at(i), 1);
        }
    }
}

void SequenceSwitch::open_all() {
    for (std::size_t i = 0; i < 5; ++i) {
        closed_.at(i) = false;
        tracer_.set(signals_.at(i), 0);
    }
}

cardreader::SequencePattern SequenceSwitch::pattern() const {
    cardreader::SequencePattern p = 0;
    for (std::size_t i = 0; i < 5; ++i) {
        if (closed_.at(i)) {
            p = static_cast<cardreader::SequencePattern>(p | (1u << i));
        }
    }
    return p;
}

SteppingShaft::SteppingShaft(Tracer& tracer)
    : tracer_(tracer), shaft_signal_(tracer.define("cabinet", "stepping_shaft_280",
                                                   "stepping shaft and rotary "
                                                   "members 282 (position 1-5)",
                                                   "280", 3, 1)),
      channel_274_(tracer.define("cabinet", "channel_274",
                                 "channel 274: a stop impulse from contact 238 via circuit 268",
                                 "274", 1)),
      circuit_276_(tracer.define("cabinet", "circuit_276",
                                 "circuit 276 delivering current to motor 278", "276", 1)),
      motor_278_(
          tracer.define("cabinet", "motor_278", "motor 278 turning stepping shaft 280", "278", 1)),
      unit_284_(tracer.define("cabinet", "unit_284",
                              "unit 284: added an impulse for a "
                              "simultaneous stop",
                              "284", 1)),
      device_288_(tracer.define("cabinet", "device_288",
                                "device 288: the axes whose path to circuit 276 "
                                "it broke after their impulse (1 table, 2 cross, "
                                "4 vertical, 8 swivel, 16 tilt; until channel 302)",
                                "288", 5)),
      contact_290_(tracer.define("cabinet", "zeroizing_contact_290",
                                 "contact 290: zeroizing "
                                 "circuit 292-304",
                                 "290", 1)) {}

bool SteppingShaft::impulse(double t, cardreader::Axis from) {
    const bool together = pending_ > 0 && t == last_impulse_t_;
    last_impulse_t_ = t;
    if (pending_ < static_cast<int>(from_.size())) { // one impulse an axis a card
        from_.at(static_cast<std::size_t>(pending_)) =
            static_cast<std::uint8_t>(cardreader::axis_index(from));
    }
    ++pending_;
    tracer_.set(channel_274_, 1);
    if (together) {
        tracer_.set(unit_284_, 1);
    }
    tracer_.set(channel_274_, 0); // the impulse has passed on to circuit 276
    return together;
}

void SteppingShaft::begin_step() {
    busy_ = true;
    tracer_.set(circuit_276_, 1);
    tracer_.set(motor_278_, 1);
}

bool SteppingShaft::finish_step() {
    busy_ = false;
    if (pending_ > 0) {
        broken_ |= 1U << from_.front(); // the oldest impulse's axis
        std::rotate(from_.begin(), from_.begin() + 1, from_.end());
    }
    --pending_;
    position_ = position_ == 5 ? 1 : position_ + 1;
    tracer_.set(shaft_signal_, static_cast<std::uint32_t>(position_));
    tracer_.set(motor_278_, 0);
    tracer_.set(circuit_276_, 0);
    tracer_.set(device_288_, broken_); // 276 delivered the impulse: 288 breaks its axis's path
    if (pending_ == 0) {
        tracer_.set(unit_284_, 0);
    }
    const bool home = position_ == 1;
    if (home) {
        tracer_.set(contact_290_, 1);
    }
    return home;
}

void SteppingShaft::reset() {
    pending_ = 0;
    busy_ = false;
    broken_ = 0;
    tracer_.set(motor_278_, 0);
    tracer_.set(circuit_276_, 0);
    tracer_.set(contact_290_, 0);
    tracer_.set(unit_284_, 0);
    tracer_.set(device_288_, 0);
}

} // namespace parsons::relaylogic
