// The frame and the lines every lane under the panels draws (plot_lanes.hpp).
#include "outputs/plots/plot_lanes.hpp"

#include "cardreader/card_svg.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iterator>
#include <string_view>

namespace parsons::cli {

using plot::kLeft;
using plot::kRight;

namespace {

std::back_insert_iterator<std::string> out(std::string& svg) {
    return std::back_inserter(svg);
}

} // namespace

void lane_frame(std::string& svg, const LaneFrame& frame, const LaneTitle& title, double top,
                double bottom, const std::optional<plot::Scale>& ty, const plot::Ticks& ticks) {
    fmt::format_to(
        out(svg),
        R"(<text x="{0:.1f}" y="{1:.1f}" font-size="13" fill="{2}">)"
        R"(<tspan font-weight="bold">{3}</tspan><tspan dx="9" fill="#666" font-size="11.5">{4})"
        R"(</tspan></text>)"
        "\n"
        R"(<rect x="{0:.1f}" y="{5:.1f}" width="{6:.1f}" height="{7:.1f}" )"
        R"(fill="#fdfdfd" stroke="#b8b8b8"/>)"
        "\n",
        kLeft, top - 8, plot::kTextColour, title.name, cardreader::xml_escape(title.what), top,
        kRight - kLeft, bottom - top);
    if (ty) {
        for (double v : ticks.values) {
            const double y = (*ty)(v);
            fmt::format_to(out(svg),
                           R"(<line x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}" stroke="{}"/>)"
                           R"(<text x="{:.1f}" y="{:.1f}" font-size="10.5" text-anchor="end" )"
                           R"(fill="{}">{:.{}f}</text>)"
                           "\n",
                           kLeft, y, kRight, y, plot::kGridColour, kLeft - 6, y + 3.5, title.colour,
                           v, ticks.decimals);
        }
        fmt::format_to(out(svg),
                       R"(<text x="{:.1f}" y="{:.1f}" font-size="10.5" fill="{}">{}</text>)"
                       "\n",
                       kRight + 7, (top + bottom) / 2 + 4, title.colour, title.unit);
    }
    for (double v : frame.time_ticks->values) {
        fmt::format_to(out(svg),
                       R"(<line x1="{0:.1f}" y1="{1:.1f}" x2="{0:.1f}" y2="{2:.1f}" stroke="{3}"/>)"
                       "\n",
                       frame.tx(v), top, bottom, plot::kGridColour);
    }
    for (double x : frame.card_x) {
        fmt::format_to(out(svg),
                       R"(<line class="card" x1="{0:.1f}" y1="{1:.1f}" x2="{0:.1f}" y2="{2:.1f}" )"
                       R"(stroke="{3}" stroke-width="0.8" stroke-dasharray="3,2"/>)"
                       "\n",
                       x, top, bottom, plot::kCardColour);
    }
    if (frame.stop_x) {
        fmt::format_to(out(svg),
                       R"(<line x1="{0:.1f}" y1="{1:.1f}" x2="{0:.1f}" y2="{2:.1f}" )"
                       R"(stroke="{3}" stroke-width="1.2" stroke-dasharray="6,3"/>)"
                       "\n",
                       *frame.stop_x, top, bottom, plot::kStopColour);
    }
}

void lane_path(std::string& svg, const PagePoints& points, const char* cls, const char* colour,
               double width) {
    const std::string d = path_d(thin_to_pixels(points));
    if (!d.empty()) {
        fmt::format_to(out(svg),
                       R"(<path class="{}" fill="none" stroke="{}" stroke-width="{}" )"
                       R"(stroke-linejoin="round" d="{}"/>)"
                       "\n",
                       cls, colour, width, d);
    }
}

int lane_legend(std::string* svg, const std::vector<LegendEntry>& entries, double y,
                const char* cls) {
    if (entries.empty()) {
        return 0;
    }
    int rows = 1;
    double x = kLeft;
    for (const LegendEntry& e : entries) {
        const double w = 30 + static_cast<double>(std::string_view(e.text).size()) * 6.9 + 26;
        if (x + w - 26 > plot::kWidth - 8) {
            ++rows;
            x = kLeft;
            y += 20;
        }
        if (svg != nullptr) {
            switch (e.glyph) {
            case LegendEntry::Glyph::line:
                fmt::format_to(out(*svg),
                               R"(<polyline fill="none" stroke="{}" stroke-width="1.8" )"
                               R"(points="{:.1f},{:.1f} {:.1f},{:.1f} {:.1f},{:.1f}"/>)"
                               "\n",
                               e.colour, x, y + 5, x + 16, y - 5, x + 16, y + 5);
                break;
            case LegendEntry::Glyph::step:
                fmt::format_to(out(*svg),
                               R"(<polyline fill="none" stroke="{}" stroke-width="1.8" )"
                               R"(points="{:.1f},{:.1f} {:.1f},{:.1f} {:.1f},{:.1f} )"
                               R"({:.1f},{:.1f}"/>)"
                               "\n",
                               e.colour, x, y + 4, x + 12, y + 4, x + 12, y - 5, x + 24, y - 5);
                break;
            case LegendEntry::Glyph::bar:
                fmt::format_to(out(*svg),
                               R"(<rect x="{:.1f}" y="{:.1f}" width="24" height="10" fill="{}" )"
                               R"(stroke="{}" stroke-width="0.8"/>)"
                               "\n",
                               x, y - 5, e.colour, e.edge);
                break;
            case LegendEntry::Glyph::mark:
                fmt::format_to(out(*svg),
                               R"(<path d="M{:.1f},{:.1f} l5,9 h-10 z" fill="{}" stroke="{}" )"
                               R"(stroke-width="0.8"/>)"
                               "\n",
                               x + 8, y - 5, e.colour, e.edge);
                break;
            }
            fmt::format_to(out(*svg),
                           R"(<text class="{}" x="{:.1f}" y="{:.1f}" font-size="12" )"
                           R"(fill="{}">{}</text>)"
                           "\n",
                           cls, x + 30, y + 4, plot::kTextColour, e.text);
        }
        x += w;
    }
    return rows;
}

std::vector<double> lane_tops(const std::vector<double>& heights, double top) {
    std::vector<double> tops;
    for (const double h : heights) {
        tops.push_back(top);
        top += h + lanes::kLaneGap;
    }
    return tops;
}

double lanes_height(const std::vector<double>& heights) {
    if (heights.empty()) {
        return 0;
    }
    double total = lanes::kPanelGap - lanes::kLaneGap;
    for (const double h : heights) {
        total += lanes::kLaneGap + h;
    }
    return total;
}

void lane_clip_paths(std::string& svg, const char* prefix, const std::vector<double>& heights,
                     double top) {
    const std::vector<double> tops = lane_tops(heights, top);
    for (std::size_t i = 0; i < heights.size(); ++i) {
        fmt::format_to(out(svg),
                       R"(<clipPath id="{}-clip-{}"><rect x="{:.1f}" y="{:.1f}" )"
                       R"(width="{:.1f}" height="{:.1f}"/></clipPath>)"
                       "\n",
                       prefix, i, kLeft - 7, tops[i] - 3, kRight - kLeft + 14, heights[i] + 6);
    }
}

std::string path_d(const PagePoints& points) {
    std::string d;
    double lx = -1e9;
    double ly = -1e9;
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double x = std::round(points[i].first * 10) / 10;
        const double y = std::round(points[i].second * 10) / 10;
        if (x == lx && y == ly) {
            continue;
        }
        fmt::format_to(std::back_inserter(d), "{}{:.1f},{:.1f}", d.empty() ? "M" : " L", x, y);
        lx = x;
        ly = y;
    }
    return d;
}

PagePoints thin_to_pixels(const PagePoints& points) {
    if (points.size() <= 2) {
        return points;
    }
    PagePoints kept;
    kept.push_back(points.front());
    std::size_t last = 0; // index of the last point kept
    for (std::size_t i = 1; i + 1 < points.size(); ++i) {
        if (std::fabs(points[i].second - kept.back().second) >= 1.0) {
            if (i - 1 != last) {
                kept.push_back(points[i - 1]);
            }
            kept.push_back(points[i]);
            last = i;
        }
    }
    if (points.size() - 2 != last) {
        kept.push_back(points[points.size() - 2]);
    }
    kept.push_back(points.back());
    return kept;
}

} // namespace parsons::cli
