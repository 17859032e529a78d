// The report of a run (--report R.json, docs/design-rules.md, Interfaces) and the one-screen
// summary.
#pragma once

#include "axes/machine_profile.hpp"
#include "relaylogic/control_cabinet.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace parsons::cli {

// The version of the report's layout: raised when a field changes meaning or goes away.
inline constexpr int kReportSchemaVersion = 1;

// Lengths and times in the report are rounded to what they resolve (docs/reliability.md,
// "Figures in the report"): counter readings to the machine's 0.001 in, lengths the emulator
// knows beyond the counters (real position, error, slip, screw turns, cut proof) to 0.00001 in,
// times to the microsecond, angles to 0.0001 degree. Saved states keep every bit.
double counter_reading(double inches);
double fine_length(double inches);
double time_s(double seconds);
double angle_deg(double degrees);

// `profile_applied`: where each part of the profile came from (cli/support/applied_profile.hpp,
// AppliedProfile::describe()).
nlohmann::json report_json(const relaylogic::RunResult& result, const axes::MachineProfile& profile,
                           const nlohmann::json& profile_applied, const std::string& deck);

// What the operator reads at the end: cards run, machine time, where every axis stands and,
// on a stop, the reason with card, axis and the lamps lit.
std::string summary_text(const relaylogic::RunResult& result, const std::string& deck,
                         const std::string& profile_name);

} // namespace parsons::cli
