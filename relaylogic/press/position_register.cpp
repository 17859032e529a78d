#include "relaylogic/press/position_register.hpp"

#include "axes/state_json.hpp"

namespace parsons::relaylogic {

PositionRegister::PositionRegister(Tracer& tracer, int device_16, int value, PulseSource source)
    : tracer_(tracer), device_16_(device_16), value_(value) {
    const std::array<const char*, 4> what = {"thousands", "hundreds", "tens", "units"};
    const Digits d = digits();
    if (source == PulseSource::spindle_encoder_32) {
        for (std::size_t i = 0; i < 4; ++i) {
            switches_.at(i) =
                tracer.define("spindle", std::string("interface_33.counter.") + what.at(i),
                              std::string("interface 33 encoder counter stepping switch (") +
                                  what.at(i) + " of edges; register 14 of EP 0436887 reused)",
                              "33", 4, static_cast<std::uint32_t>(d.at(i)));
        }
        value_signal_ = tracer.define("spindle", "interface_33.counter",
                                      "spindle encoder interface 33: motor 27's angle in encoder "
                                      "edges, up forward, down in reverse (EP 0360190)",
                                      "33", 14, static_cast<std::uint32_t>(value_));
        setter_15_ = tracer.define("spindle", "interface_33.revolution",
                                   "interface 33: operated when its counter passes a motor "
                                   "revolution and presets it",
                                   "33", 1);
        return;
    }
    for (std::size_t i = 0; i < 4; ++i) {
        switches_.at(i) = tracer.define("press", std::string("position_register_14.") + what.at(i),
                                        std::string("position register 14 stepping switch (") +
                                            what.at(i) + " of pulses)",
                                        "14", 4, static_cast<std::uint32_t>(d.at(i)));
    }
    value_signal_ = tracer.define("press", "position_register_14",
                                  "position register 14: the crank's angle in detector pulses "
                                  "(EP 0436887)",
                                  "14", 14, static_cast<std::uint32_t>(value_));
    setter_15_ = tracer.define("press", "setter_15",
                               "setter 15: operated when register 14 reaches device 16's "
                               "value (a revolution) and presets it",
                               "15", 1);
    switch_16A_ = tracer.define("press", "switch_16A",
                                "reset switch 16A: a sync card's reset order clears register 14 "
                                "where the crank stands (claim 5); released at the next "
                                "reference block",
                                "16A", 1);
}

void PositionRegister::show() {
    if (tracer_.observer() == nullptr) {
        return; // nobody watches: the values need not be worked out (they change at every edge)
    }
    const Digits d = digits();
    for (std::size_t i = 0; i < 4; ++i) {
        tracer_.set(switches_.at(i), static_cast<std::uint32_t>(d.at(i)));
    }
    tracer_.set(value_signal_, static_cast<std::uint32_t>(value_));
}

void PositionRegister::count(int sense) {
    if (sense > 0) {
        value_ += 1;
        if (value_ == device_16_) { // the comparer on device 16 operates setter 15
            tracer_.set(setter_15_, 1);
            value_ = 0;
            ++presets_;
        } else {
            tracer_.set(setter_15_, 0);
        }
    } else if (sense < 0) {
        if (value_ == 0) { // the borrow runs through every switch: setter 15 presets
            tracer_.set(setter_15_, 1);
            value_ = device_16_ - 1;
            ++presets_;
        } else {
            tracer_.set(setter_15_, 0);
            value_ -= 1;
        }
    }
    show();
}

void PositionRegister::count_many(std::int64_t n, int sense) {
    if (n <= 0 || sense == 0) {
        return;
    }
    const std::int64_t d = device_16_;
    const std::int64_t from = value_;
    if (sense > 0) {
        presets_ += (from + n) / d;
        value_ = static_cast<int>((from + n) % d);
        // The last count operated setter 15 exactly when it left the register at 0.
        tracer_.set(setter_15_, value_ == 0 ? 1U : 0U);
    } else {
        presets_ += from >= n ? 0 : (n - from - 1) / d + 1;
        value_ = static_cast<int>(((from - n) % d + d) % d);
        tracer_.set(setter_15_, value_ == device_16_ - 1 ? 1U : 0U);
    }
    show();
}

void PositionRegister::preset(int value) {
    value_ = value;
    show();
}

void PositionRegister::release_16A() {
    if (switch_16A_) {
        tracer_.set(*switch_16A_, 0);
    }
}

void PositionRegister::switch_16A() {
    ++resets_;
    if (switch_16A_) {
        tracer_.set(*switch_16A_, 1);
    }
    preset(0);
}

nlohmann::json PositionRegister::save() const {
    return {{"value", value_}, {"presets", presets_}, {"resets", resets_}};
}

void PositionRegister::load(const nlohmann::json& j) {
    const int v = axes::read<int>(j, "value");
    if (v < 0 || v >= device_16_) {
        throw axes::StateError("position_register_14: value outside 0 .. device 16");
    }
    value_ = v;
    presets_ = axes::read<std::int64_t>(j, "presets");
    // A state saved before sync cards could order the reset: none had been.
    resets_ = j.contains("resets") ? axes::read<std::int64_t>(j, "resets") : 0;
}

} // namespace parsons::relaylogic
