// The report of a run (--report R.json, docs/design-rules.md, Interfaces) and the one-screen
// summary.
#pragma once

#include "axes/machine_profile.hpp"
#include "outputs/report/figures.hpp" // the report's figures, rounded to what they resolve
#include "relaylogic/control_cabinet.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace parsons::cli {

// The version of the report's layout: raised when a field changes meaning or goes away.
inline constexpr int kReportSchemaVersion = 1;

// `profile_applied`: where each part of the profile came from (cli/support/applied_profile.hpp,
// AppliedProfile::describe()).
nlohmann::json report_json(const relaylogic::RunResult& result, const axes::MachineProfile& profile,
                           const nlohmann::json& profile_applied, const std::string& deck);

// What the operator reads at the end: cards run, machine time, where every axis stands and,
// on a stop, the reason with card, axis and the lamps lit.
std::string summary_text(const relaylogic::RunResult& result, const std::string& deck,
                         const std::string& profile_name);

} // namespace parsons::cli
