// The relations between a machine profile's keys, listed once (axes/profile_relations.cpp): each
// a rule the machine model needs beyond every key's own range (axes/profile_keys.hpp), checked
// by the loader once every key of a file is applied (profile_json.cpp), written into
// docs/machine-profile.md's "Every number's range" and tested at its exact edge
// (tests/profile_keys_test.cpp).
//
// To add one: a row of kRelations with the rule as the docs state it, a line of why, a
// predicate, and the message when it does not hold, which starts with the key to change
// ("spindle.sample_s: ..."); then a case at its edge in tests/profile_keys_test.cpp.
#pragma once

#include "axes/machine_profile.hpp"

#include <span>
#include <string>
#include <string_view>

namespace parsons::axes {

struct ProfileRelation {
    std::string_view rule; // "first_bank_s + relay_operate_s < second_bank_s"
    std::string_view why;  // one line
    bool (*holds)(const MachineProfile& p);
    // What is wrong, naming the key first; called only when `holds` is false.
    std::string (*message)(const MachineProfile& p);
};

// Every relation, in the order the loader checks them.
std::span<const ProfileRelation> profile_relations();
// Throws ProfileError(message) for the first relation p breaks.
void check_profile_relations(const MachineProfile& p);

} // namespace parsons::axes
