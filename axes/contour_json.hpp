// The contouring attachment's profile keys (an addition after EP 0636958, Black & Decker;
// docs/machine-profile.md, "Contouring"): "contouring" (on or off) and the object "contour".
// Each number's range, and why, is in axes/profile_keys.cpp ("contour.KEY"); the relation of the
// interpolator's ramps to the motors' acceleration in axes/profile_relations.cpp.
#pragma once

#include "axes/machine_profile.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace parsons::axes {

bool apply_contouring(MachineProfile& p, const std::string& key, const nlohmann::json& value);
void put_contouring(nlohmann::json& j, const MachineProfile& p);
// "rule", "pass", "minimum"
const char* junction_policy_name(JunctionPolicy policy);

} // namespace parsons::axes
