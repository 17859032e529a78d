// The legend of the press lanes (plot_press_lanes.hpp): under the panels' legend, a glyph and a
// few words for each lane and for detector 61's mark, in as many rows as the page needs.
#include "outputs/plots/plot_press_lanes.hpp"

#include <vector>

namespace parsons::cli {

using namespace press_colours;

namespace {

std::vector<LegendEntry> entries_of(const PressTrace& press) {
    if (!press.present()) {
        return {};
    }
    using G = LegendEntry::Glyph;
    std::vector<LegendEntry> entries = {
        {G::line, kCrankColour, "crank 21 angle, deg"},
        {G::line, kDieColour, "die 20 height, in"},
        {G::line, kRegister14Colour, "position register 14, pulses"},
        {G::step, kRegister11Colour, "speed register 11, pulses a second"},
        {G::bar, kHoldColour, "reader 60 holds a card for its angle R", kHoldEdge},
        {G::mark, kHoldEdge, "detector 61: crank on R"},
    };
    if (press.has_interlock()) {
        entries.push_back(
            {G::bar, kInterlockColour, "the feeder's interlock holds the press", kInterlockEdge});
    }
    if (press.any_speed_63()) {
        entries.push_back({G::step, kAxisColours[0], "processor 63 speed, in/min"});
    }
    return entries;
}

} // namespace

int press_legend_rows(const PressTrace& press) {
    return lane_legend(nullptr, entries_of(press), 0, "press-legend");
}

void press_legend(std::string& svg, const PressTrace& press, double y) {
    lane_legend(&svg, entries_of(press), y, "press-legend");
}

} // namespace parsons::cli
