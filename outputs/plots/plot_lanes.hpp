// What the lanes of the additions under the five lead-screw panels of run --plot share, whatever
// part of the machine they show: the press's (plot_press_lanes.hpp) and the spindle's
// (plot_spindle_lanes.hpp). Each lane stands on the panels' time axis in a frame of its own —
// a title, a scale, the panels' time grid, a dashed line at each card read and the stop — and
// draws its signals as lines thinned to the pixel.
//
//   name  what it shows (grey)
//   +--------------------------------------------+
//   | 10                 :          :            | unit
//   |  0 ___/------\_____:__________:____        |
//   +--------------------------------------------+
//                        card        stop
#pragma once

#include "outputs/plots/plot_geometry.hpp"

#include <algorithm>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace parsons::cli {

namespace lanes {
constexpr double kPanelGap = 42;   // as the panels' (plot_chart.cpp): above the first lane
constexpr double kLaneHeight = 64; // a lane with a scale
constexpr double kLaneGap = 34;    // between two lanes (room for the title)
} // namespace lanes

// Where the lanes stand and what crosses every one of them.
struct LaneFrame {
    plot::Scale tx;                  // machine time -> page x, the panels' own
    const plot::Ticks* time_ticks{}; // the panels' time grid
    double top = 0;                  // the first lane's frame, px
    std::vector<double> card_x;      // a dashed line at each card read
    std::optional<double> stop_x;    // the stop, if the machine stopped itself
};

// A lane's words and colour.
struct LaneTitle {
    const char* name;   // bold title
    const char* what;   // grey title
    const char* unit;   // right of the frame
    const char* colour; // the scale's
};

using PagePoints = std::vector<std::pair<double, double>>;

// The frame of a lane from top to bottom: its title, the box, the scale (if ty: ticks at the
// left, the unit at the right), the time grid, the card lines and the stop line.
void lane_frame(std::string& svg, const LaneFrame& frame, const LaneTitle& title, double top,
                double bottom, const std::optional<plot::Scale>& ty, const plot::Ticks& ticks);
// A path of class cls through the points, thinned to the pixel (nothing if there are none).
void lane_path(std::string& svg, const PagePoints& points, const char* cls, const char* colour,
               double width);

// An entry of a lanes' legend: a glyph and a few words.
struct LegendEntry {
    enum class Glyph : std::uint8_t { line, step, bar, mark };
    Glyph glyph;
    const char* colour;
    const char* text;
    const char* edge = "white"; // a bar's outline, a mark's
};
// Lays the entries out in rows from kLeft at y, 20 px apart, and draws them if svg is given
// (each text of class cls). Returns the rows (0 for no entries).
int lane_legend(std::string* svg, const std::vector<LegendEntry>& entries, double y,
                const char* cls);

// A series of (t, x) points on the page: as a line (a value that moves between its samples) or
// as steps (one that holds until the next).
template <class Point>
PagePoints on_page(const std::vector<Point>& series, const plot::Scale& tx, const plot::Scale& ty,
                   bool steps) {
    PagePoints points;
    points.reserve(series.size() * (steps ? 2 : 1));
    for (const Point& p : series) {
        if (steps && !points.empty()) {
            points.emplace_back(tx(p.t), points.back().second);
        }
        points.emplace_back(tx(p.t), ty(p.x));
    }
    return points;
}

// The largest value of a series, at least at_least.
template <class Point>
double max_of(const std::vector<Point>& series, double at_least) {
    double hi = at_least;
    for (const Point& p : series) {
        hi = std::max(hi, p.x);
    }
    return hi;
}

// Each lane's top, the first at top, kLaneGap between one's frame and the next.
std::vector<double> lane_tops(const std::vector<double>& heights, double top);
// The height lanes take under the panels, the gap above the first included; 0 for none.
double lanes_height(const std::vector<double>& heights);
// A clip path per lane, id "{prefix}-clip-{i}", a little larger than its frame.
void lane_clip_paths(std::string& svg, const char* prefix, const std::vector<double>& heights,
                     double top);
// The heights of lanes of any kind (each with a height).
template <class Spec>
std::vector<double> heights_of(const std::vector<Spec>& lanes) {
    std::vector<double> heights;
    heights.reserve(lanes.size());
    for (const Spec& l : lanes) {
        heights.push_back(l.height);
    }
    return heights;
}

// A path's d attribute, to a tenth of a pixel, no point twice in a row.
std::string path_d(const PagePoints& points);

// A polyline of page points thinned for drawing: a point is kept when it lies a pixel or more
// above or below the last one kept, together with the point just before it (so a jump stays a
// jump, where it happened); the first and last are always kept. Exposed for tests.
PagePoints thin_to_pixels(const PagePoints& points);

} // namespace parsons::cli
