// Drawing the spindle lanes (plot_spindle.hpp) under the five lead-screw panels of run --plot
// (and under the press lanes, if there are any), on the panels' time axis. Only a run that read
// a tap card has them; the chart of any other run is drawn as before, byte for byte.
#pragma once

#include "outputs/plots/plot_lanes.hpp"
#include "outputs/plots/plot_spindle.hpp"

#include <array>
#include <string>

namespace parsons::cli {

namespace spindle_colours { // the lanes' and their legend entries'
inline constexpr const char* kMotorColour = "#3f51b5";
inline constexpr const char* kToolColour = "#e6550d";
inline constexpr const char* kInterfaceColour = "#17becf";
inline constexpr const char* kRatioColour = "#6a3d9a";
inline constexpr const char* kExchangeColour = "#555555";
inline constexpr const char* kFeedColour = "#2ca02c";
inline constexpr const char* kDepthColour = "#8c6d31";
inline constexpr const char* kNcColour = "#4e79a7";    // a bus 35 line the NC drives
inline constexpr const char* kPcColour = "#e15759";    // one PC 130 drives
inline constexpr const char* kRelayColour = "#b07aa1"; // a relay of PC 130's ladder
inline constexpr const char* kBarEdge = "#444444";
// The synchronous control's phases (relaylogic::TappingUnits::Phase), 0 idle drawn as none.
inline constexpr std::array<const char*, 6> kPhaseColours = {"none",    "#bbbbbb", "#9ecae1",
                                                             "#fdae6b", "#fd8d3c", "#dddddd"};
inline constexpr std::array<const char*, 6> kPhaseNames = {
    "idle", "tool call", "in", "out", "spindle stopping", "feed settling"};

} // namespace spindle_colours

// How much taller the page is for the lanes (0 without a tap card): from the last lane above
// them (a panel's or the press's) to the last spindle lane's bottom.
double spindle_lanes_height(const SpindleTrace& spindle);
// The rows of legend entries the lanes add under the legend above (0 without a tap card).
int spindle_legend_rows(const SpindleTrace& spindle);
// The lanes' clip paths (inside <defs>), their legend rows from y, and the lanes themselves.
void spindle_clip_paths(std::string& svg, const SpindleTrace& spindle, double top);
void spindle_legend(std::string& svg, const SpindleTrace& spindle, double y);
void spindle_lanes(std::string& svg, const SpindleTrace& spindle, const LaneFrame& frame);

} // namespace parsons::cli
