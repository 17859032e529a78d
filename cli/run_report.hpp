// The report of a run (--report R.json, DESIGN.md section 6) and the one-screen summary.
#pragma once

#include "axes/machine_profile.hpp"
#include "relaylogic/control_cabinet.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace parsons::cli {

nlohmann::json report_json(const relaylogic::RunResult& result, const axes::MachineProfile& profile,
                           const std::string& deck);

// What the operator reads at the end: cards run, machine time, where every axis stands and,
// on a stop, the reason with card, axis and the lamps lit.
std::string summary_text(const relaylogic::RunResult& result, const std::string& deck,
                         const std::string& profile_name);

} // namespace parsons::cli
