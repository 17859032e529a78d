// The profile's spindle synchronisation as JSON (an addition after EP 0360190, Mitsubishi):
// the top-level "spindle_sync" flag and the "spindle" object of SpindleSyncProfile's keys
// (motor 27, encoder 32, the heads 31 with their ratios and tools, PC 130's times, the ratio's
// way into memory 12a). profile_json.cpp calls these; docs/machine-profile.md lists every key
// with its range. An unknown key, a wrong type or a value out of range is a ProfileError that
// names the key ("spindle.heads[1].ratio: ...").
#pragma once

#include "axes/machine_profile.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace parsons::axes {

// Applies "spindle_sync" or "spindle" to p; false for any other key (p unchanged).
bool apply_spindle_sync(MachineProfile& p, const std::string& key, const nlohmann::json& value);
// Writes "spindle_sync" and "spindle" into the profile's JSON object.
void put_spindle_sync(nlohmann::json& j, const MachineProfile& p);

} // namespace parsons::axes
