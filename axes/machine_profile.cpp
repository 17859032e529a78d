#include "axes/machine_profile.hpp"

namespace parsons::axes {

MachineProfile default_profile() {
    MachineProfile p;
    const std::array<const char*, kAxisCount> names = {"table", "cross", "vertical", "swivel",
                                                       "tilt"};
    for (std::size_t i = 0; i < p.axes.size(); ++i) {
        p.axes.at(i).name = names.at(i);
    }
    // The sine plate's vertical screws 24 act 10 in from hinge 19; the swivel screw 26 acts
    // on the end of bottom member 15, taken as 20 in from its pivot.
    p.axes.at(3).pivot_to_screw_in = 20.0;
    p.axes.at(4).pivot_to_screw_in = 10.0;
    // Both stand level at mid-travel, so the fixture turns either way.
    p.axes.at(3).level_in = 5.0;
    p.axes.at(4).level_in = 5.0;
    return p;
}

MachineProfile safe_profile() {
    MachineProfile p = default_profile();
    p.name = "parsons-safe";
    p.refuse_double_punch = true;
    return p;
}

MachineProfile extended_profile() {
    MachineProfile p = safe_profile();
    p.name = "parsons-extended";
    p.condition_cards = true;
    p.press_sync = true;
    p.spindle_sync = true;
    p.contouring = true;
    return p;
}

std::optional<MachineProfile> builtin_profile(const std::string& name) {
    if (name == "parsons-extended") {
        return extended_profile();
    }
    if (name == "parsons-1952") {
        return default_profile();
    }
    if (name == "parsons-safe") {
        return safe_profile();
    }
    return std::nullopt;
}

} // namespace parsons::axes
