// Drawing the press lanes (plot_press.hpp) under the five lead-screw panels of run --plot, on
// the panels' time axis. Only a run with a press has them; the chart of any other run is
// drawn as before, byte for byte.
#pragma once

#include "outputs/plots/plot_lanes.hpp"
#include "outputs/plots/plot_press.hpp"

#include <array>
#include <string>

namespace parsons::cli {

namespace press_colours { // the lanes' and their legend entries'
inline constexpr const char* kCrankColour = "#7b3294";
inline constexpr const char* kDieColour = "#00897b";
inline constexpr const char* kRegister14Colour = "#8c564b";
inline constexpr const char* kRegister11Colour = "#e377c2";
inline constexpr const char* kHoldColour = "#edc948";
inline constexpr const char* kHoldEdge = "#a67c00";
inline constexpr const char* kWaitColour = "#bbbbbb";
inline constexpr const char* kInterlockColour = "#f6c9c4"; // the feeder's interlock holds the press
inline constexpr const char* kInterlockEdge = "#c0392b";
inline constexpr std::array<const char*, cardreader::kAxisCount> kAxisColours = {
    "#1f4e9c", "#59a14f", "#76b7b2", "#9c755f", "#bab0ac"};

} // namespace press_colours

// How much taller the page is for the lanes (0 without a press): from the last panel's bottom
// to the last lane's bottom.
double press_lanes_height(const PressTrace& press);
// The rows of legend entries the lanes add under the panels' legend (0 without a press).
int press_legend_rows(const PressTrace& press);
// The lanes' clip paths (inside <defs>), their legend rows from y, and the lanes themselves.
void press_clip_paths(std::string& svg, const PressTrace& press, double top);
void press_legend(std::string& svg, const PressTrace& press, double y);
void press_lanes(std::string& svg, const PressTrace& press, const LaneFrame& frame);

} // namespace parsons::cli
