// The machine profile a run actually applied, and where each part of it came from: the named
// profile (parsons-1952, parsons-safe), a profile file over it, a saved state, --limit and
// --feed. The report carries it (profile_applied) so that a run can be told apart from one
// with the same profile name and other figures; a resumed run says where each limit came from.
#pragma once

#include "axes/machine_profile.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <string>
#include <vector>

namespace parsons::cli {

class AppliedProfile {
public:
    // The profile `file` names (empty: the default; a built-in name; or a JSON file, applied
    // over the built-in profile its "name" names, else over the default). Throws DeckError.
    static AppliedProfile load(const std::string& file);
    // The file load(name) reads: "" for the default and for a built-in profile by name.
    static std::string file_read(const std::string& name);
    // The profile a saved state carries (state_file names it in messages). Throws StateError
    // or ProfileError on a state that does not hold one.
    static AppliedProfile from_state(const nlohmann::json& saved, const std::string& state_file);

    // --limit AXIS=MIN:MAX over the profile's movement range; each axis it names is marked as
    // set by --limit.
    void apply_limits(const std::vector<std::string>& limits);
    axes::MachineProfile& profile() { return profile_; }
    const axes::MachineProfile& profile() const { return profile_; }
    // The profile file applied, or "" for a built-in profile.
    const std::string& file() const { return file_; }

    // For the report and the saved state: name, file, the named profile compared with, every
    // value that differs from it (key, value, named value) and, per axis, the soft limits and
    // limit switches with where each came from.
    nlohmann::json describe() const;
    // One line per axis: its movement range and limit switches and where each came from.
    std::vector<std::string> limit_lines() const;

private:
    axes::MachineProfile profile_;
    axes::MachineProfile named_;
    std::string file_; // the profile file, or empty
    // Where each axis's movement range (soft limits) and limit switches came from.
    std::array<std::string, axes::kAxisCount> soft_from_;
    std::array<std::string, axes::kAxisCount> travel_from_;
};

// Every leaf where `applied` differs from `named`, as {"key": "axes.table.backlash_in",
// "value": ..., "named_value": ...}; arrays (speeds, error tables) compare whole.
nlohmann::json profile_differences(const axes::MachineProfile& applied,
                                   const axes::MachineProfile& named);

} // namespace parsons::cli
