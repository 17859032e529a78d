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

AxisCircuit::AxisCircuit(Tracer& t, const axes::MachineProfile& profile, cardreader::Axis a)
    : tracer(t), axis(a), plant(profile.axes.at(cardreader::axis_index(a))),
      absolute_storage(t, std::string(cardreader::axis_name(a)), profile.separate_registers),
      incremental_storage(t, std::string(cardreader::axis_name(a))),
      absolute_counter(t, std::string(cardreader::axis_name(a))),
      increment_counter(t, std::string(cardreader::axis_name(a))),
      speed_switch(t, std::string(cardreader::axis_name(a)),
                   profile.delay_258_waits_for_equality_to_leave),
      sequence_switch(t, std::string(cardreader::axis_name(a))),
      lamps_only_on_trip_(profile.lamps_only_on_trip) {
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
    const std::array<const char*, 4> commutators = {"96", "98", "100", "102"};
    for (std::size_t i = 0; i < 4; ++i) {
        for (std::size_t set = 0; set < 2; ++set) {
            const std::string ab = set == 0 ? "a" : "b";
            contacts_.at(2 * i + set) = t.define(
                scope, std::string("commutator_") + commutators.at(i) + ".contact_set_" + ab,
                std::string("commutator ") + commutators.at(i) + " contact set " +
                    (set == 0 ? "A" : "B") + " (changes over at each impulse)",
                commutators.at(i), 1);
        }
    }
    lamp_270_ = t.define(scope, "lamp_270", "lamp: absolute comparer 122' conducting, 236 on off",
                         "270", 1);
    lamp_272_ = t.define(scope, "lamp_272",
                         "lamp: incremental comparer 122'' conducting, 236 on off", "272", 1);
}

void AxisCircuit::set_direction(cardreader::Motion motion) {
    direction = motion == cardreader::Motion::forward ? +1 : -1;
    tracer.set(reversing_214_, direction > 0 ? 0 : 1);
}

void AxisCircuit::trace_contacts() {
    static constexpr std::array<std::int64_t, 4> kUnits = {1000, 100, 10, 1}; // 96, 98, 100, 102
    const std::int64_t k = plant.commutator_index();
    for (std::size_t i = 0; i < 4; ++i) {
        const std::int64_t a = axes::floor_div(k, kUnits.at(i));
        const std::int64_t b = i == 3 ? a - (contact_set_a - contact_set_b) : a;
        tracer.set(contacts_.at(2 * i), static_cast<std::uint32_t>(a & 1));
        tracer.set(contacts_.at(2 * i + 1), static_cast<std::uint32_t>(b & 1));
    }
}

} // namespace parsons::relaylogic
