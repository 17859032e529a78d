// The legend of the press lanes (plot_press_lanes.hpp): under the panels' legend, a glyph and a
// few words for each lane and for detector 61's mark, in as many rows as the page needs.
#include "cli/plot_press_lanes.hpp"

#include <fmt/format.h>

#include <iterator>
#include <string_view>

namespace parsons::cli {

using plot::kLeft;
using namespace press_colours;

namespace {

std::back_insert_iterator<std::string> out(std::string& svg) {
    return std::back_inserter(svg);
}

// The legend entries, laid out in rows from kLeft; draws them if svg is given. Returns the rows.
int legend_rows(std::string* svg, const PressTrace& press, double y) {
    if (!press.present()) {
        return 0;
    }
    struct Entry {
        const char* glyph; // line, step, bar, mark
        const char* colour;
        const char* text;
    };
    std::vector<Entry> entries = {
        {"line", kCrankColour, "crank 21 angle, deg"},
        {"line", kDieColour, "die 20 height, in"},
        {"line", kRegister14Colour, "position register 14, pulses"},
        {"step", kRegister11Colour, "speed register 11 stored, pulses"},
        {"bar", kHoldColour, "reader 60 holds a card for its angle R"},
        {"mark", kHoldEdge, "detector 61: crank on R"},
    };
    if (press.any_speed_63()) {
        entries.push_back({"step", kAxisColours[0], "processor 63 speed, in/min"});
    }
    int rows = 1;
    double x = kLeft;
    for (const Entry& e : entries) {
        const double w = 30 + static_cast<double>(std::string_view(e.text).size()) * 6.9 + 26;
        if (x + w - 26 > plot::kWidth - 8) {
            ++rows;
            x = kLeft;
            y += 20;
        }
        if (svg != nullptr) {
            const std::string_view g = e.glyph;
            if (g == "line") {
                fmt::format_to(out(*svg),
                               R"(<polyline fill="none" stroke="{}" stroke-width="1.8" )"
                               R"(points="{:.1f},{:.1f} {:.1f},{:.1f} {:.1f},{:.1f}"/>)"
                               "\n",
                               e.colour, x, y + 5, x + 16, y - 5, x + 16, y + 5);
            } else if (g == "step") {
                fmt::format_to(out(*svg),
                               R"(<polyline fill="none" stroke="{}" stroke-width="1.8" )"
                               R"(points="{:.1f},{:.1f} {:.1f},{:.1f} {:.1f},{:.1f} )"
                               R"({:.1f},{:.1f}"/>)"
                               "\n",
                               e.colour, x, y + 4, x + 12, y + 4, x + 12, y - 5, x + 24, y - 5);
            } else if (g == "bar") {
                fmt::format_to(out(*svg),
                               R"(<rect x="{:.1f}" y="{:.1f}" width="24" height="10" fill="{}" )"
                               R"(stroke="{}" stroke-width="0.8"/>)"
                               "\n",
                               x, y - 5, e.colour, kHoldEdge);
            } else {
                fmt::format_to(out(*svg),
                               R"(<path d="M{:.1f},{:.1f} l5,9 h-10 z" fill="{}" stroke="white" )"
                               R"(stroke-width="0.8"/>)"
                               "\n",
                               x + 8, y - 5, e.colour);
            }
            fmt::format_to(out(*svg),
                           R"(<text class="press-legend" x="{:.1f}" y="{:.1f}" font-size="12" )"
                           R"(fill="{}">{}</text>)"
                           "\n",
                           x + 30, y + 4, plot::kTextColour, e.text);
        }
        x += w;
    }
    return rows;
}

} // namespace

int press_legend_rows(const PressTrace& press) {
    return legend_rows(nullptr, press, 0);
}

void press_legend(std::string& svg, const PressTrace& press, double y) {
    legend_rows(&svg, press, y);
}

} // namespace parsons::cli
