#include "relaylogic/axis_circuit.hpp"

namespace parsons::relaylogic {

std::string_view motor_numeral(cardreader::Axis axis) {
    switch (axis) {
    case cardreader::Axis::table:
        return "38";
    case cardreader::Axis::cross:
        return "50";
    case cardreader::Axis::vertical:
        return "46";
    case cardreader::Axis::swivel:
        return "44";
    case cardreader::Axis::tilt:
        return "40";
    }
    return "38";
}

AxisCircuit::AxisCircuit(Tracer& t, const axes::AxisProfile& profile, cardreader::Axis a,
                         bool separate_registers)
    : tracer(t), axis(a), plant(profile),
      absolute_storage(t, std::string(cardreader::axis_name(a)), separate_registers),
      incremental_storage(t, std::string(cardreader::axis_name(a))),
      absolute_counter(t, std::string(cardreader::axis_name(a))),
      increment_counter(t, std::string(cardreader::axis_name(a))),
      speed_switch(t, std::string(cardreader::axis_name(a))),
      sequence_switch(t, std::string(cardreader::axis_name(a))) {
    const std::string scope(cardreader::axis_name(a));
    reversing_214_ =
        t.define(scope, "reversing_control_214", "reversing control (1 = reverse)", "214", 1);
    comparer_absolute_ = t.define(scope, "absolute_comparer_122a",
                                  "absolute comparer 122' "
                                  "conducting",
                                  "122'", 1);
    comparer_incremental_ = t.define(scope, "incremental_comparer_122b",
                                     "incremental comparer "
                                     "122'' conducting",
                                     "122''", 1);
    motor_ = t.define(scope, "motor_" + std::string(motor_numeral(a)), "lead-screw motor running",
                      std::string(motor_numeral(a)), 1);
}

void AxisCircuit::set_direction(cardreader::Motion motion) {
    direction = motion == cardreader::Motion::forward ? +1 : -1;
    tracer.set(reversing_214_, direction > 0 ? 0 : 1);
}

void AxisCircuit::set_powered(bool on) {
    powered = on;
    tracer.set(motor_, on ? 1 : 0);
}

} // namespace parsons::relaylogic
