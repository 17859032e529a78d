// The legend of the spindle lanes (plot_spindle_lanes.hpp): under the legend above it (the
// panels', the press's), a glyph and a few words for each line, mark and kind of bar the lanes
// draw, in as many rows as the page needs.
#include "outputs/plots/plot_spindle_lanes.hpp"

#include <vector>

namespace parsons::cli {

using namespace spindle_colours;

namespace {

std::vector<LegendEntry> entries_of(const SpindleTrace& spindle) {
    if (!spindle.present()) {
        return {};
    }
    using G = LegendEntry::Glyph;
    return {
        {G::step, kMotorColour, "motor 27 speed, rev/min"},
        {G::step, kToolColour, "tool 16 speed, rev/min"},
        {G::step, kInterfaceColour, "interface 33 edges a sample"},
        {G::step, kRatioColour, "ratio A in memory 12a"},
        {G::mark, kExchangeColour, "head exchanged (its tool T)"},
        {G::step, kFeedColour, "feed commanded, in/min"},
        {G::step, kDepthColour, "depth called, in"},
        {G::bar, kPhaseColours.at(1), "waiting for the tool", kBarEdge},
        {G::bar, kPhaseColours.at(2), "tapping in", kBarEdge},
        {G::bar, kPhaseColours.at(3), "coming out", kBarEdge},
        {G::bar, kNcColour, "bus 35: the NC's line", kBarEdge},
        {G::bar, kPcColour, "bus 35: PC 130's line", kBarEdge},
        {G::bar, kRelayColour, "PC 130 relay picked", kBarEdge},
    };
}

} // namespace

int spindle_legend_rows(const SpindleTrace& spindle) {
    return lane_legend(nullptr, entries_of(spindle), 0, "spindle-legend");
}

void spindle_legend(std::string& svg, const SpindleTrace& spindle, double y) {
    lane_legend(&svg, entries_of(spindle), y, "spindle-legend");
}

} // namespace parsons::cli
