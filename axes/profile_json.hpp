// The machine profile as JSON (--profile FILE): every key of MachineProfile by its C++ name.
// A partial file changes only the keys it names; an unknown key, a wrong type or a value out
// of range is an error that names the key, so a typo never silently keeps a default.
#pragma once

#include "axes/machine_profile.hpp"

#include <stdexcept>
#include <string>

namespace parsons::axes {

class ProfileError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Applies the JSON text on top of `base`. Throws ProfileError("KEY: what is wrong").
MachineProfile profile_from_json(const std::string& json_text, MachineProfile base);
std::string profile_to_json(const MachineProfile& profile);

} // namespace parsons::axes
