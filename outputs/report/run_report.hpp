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

// Whole turns of an axis's counters (10 in each) that a run which completed counted beyond what
// its cards ordered: a card ran the axis past its number and on round the counters until they
// read it again (an equality missed while delay 258 held channel 257 open, say). The counters
// then read the card's number, and no 1952 check can see the difference. From the run's own
// result: its counters' count (AxisResult::counted_in) against the cards' orders
// (AxisResult::ordered_in). 0 for a run that stopped: the stop is what it says.
std::int64_t counter_turns_unseen(const relaylogic::RunResult& result, cardreader::Axis axis);
// The warning for them, without "warning: " and the axis's name ("ends +10.000 in from where
// its cards put it: ..."), or "" when there are none. The summary, `check` and `show` say it.
std::string counter_turns_warning(const relaylogic::RunResult& result, cardreader::Axis axis);

// What a hole did that its "completed" does not tell, without "warning: ": a completed hole
// that bottomed farther from its depth than the NC resolves (a thousandth, or an encoder edge's
// feed: relaylogic::depth_miss_in), or a hole whose feed never came back onto its starting count
// (the NC gave up after 5 s) in a run that went on; "hole 2 (card 5, tool 1, S 36) ...". ""
// for a hole within it, or the last hole of a run that stopped (the stop says why). The summary
// and `check` say it.
std::string tap_hole_warning(const relaylogic::RunResult& result, std::size_t hole);

// The sync drive asked for more than it follows (relaylogic::DriveSaturation), without
// "warning: ": which axis, on which card, the speed asked against sync_drive.max_in_per_min,
// when, and the crank's speed then over the press's rated one; the axis then falls behind the
// crank past the lag docs/press-sync.md bounds. "" when the drive always followed. The summary
// says it with the card, `check` (whose note names the card) without.
std::string press_drive_warning(const relaylogic::RunResult& result, bool name_card = true);

} // namespace parsons::cli
