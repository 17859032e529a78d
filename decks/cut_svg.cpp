#include "decks/cut_svg.hpp"

#include "cardreader/card_svg.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <utility>

namespace parsons::decks {
namespace {

using Eigen::Vector2d;

constexpr double kWidth = 1200;
constexpr double kLeft = 80, kRight = 30, kTop = 56, kTicks = 44, kLegend = 118;
constexpr double kMaxPlotHeight = 760;
constexpr double kBand_px = 9; // width of the colour band
constexpr int kCircles = 12;   // cutter outlines drawn along the path
constexpr int kLevels = 24;    // colour steps per side of the band
constexpr const char* kFont = R"(font-family="DejaVu Sans, Arial, sans-serif")";

constexpr std::array<double, 3> kWhite{255, 255, 255};
constexpr std::array<double, 3> kBlue{33, 90, 200};
constexpr std::array<double, 3> kRed{205, 35, 35};
constexpr const char* kGrey = "#d4d4d4";

bool finite(const Vector2d& p) {
    return std::isfinite(p.x()) && std::isfinite(p.y());
}

// 1, 2 or 5 times a power of ten, at least x.
double nice_ceil(double x) {
    const double p = std::pow(10.0, std::floor(std::log10(x)));
    for (double m : {1.0, 2.0, 5.0, 10.0}) {
        if (m * p >= x * (1 - 1e-12)) {
            return m * p;
        }
    }
    return 10 * p;
}

// Inches to pixels: equal scales, y up on the paper.
struct View {
    Vector2d lo, hi;   // inches
    double scale = 1;  // px per inch
    double x0 = kLeft; // px of lo.x()
    double y0 = kTop;  // px of hi.y()
    double plot_w = 0, plot_h = 0;
    double px(double x) const { return x0 + (x - lo.x()) * scale; }
    double py(double y) const { return y0 + (hi.y() - y) * scale; }
    Vector2d at(const Vector2d& p) const { return {px(p.x()), py(p.y())}; }
};

View make_view(const CutProof& proof, const DesignContour& design, double radius_in,
               double exaggerate) {
    View v;
    v.lo = Vector2d::Constant(1e300);
    v.hi = Vector2d::Constant(-1e300);
    const auto add = [&](const Vector2d& p) {
        if (finite(p)) {
            v.lo = v.lo.cwiseMin(p);
            v.hi = v.hi.cwiseMax(p);
        }
    };
    for (std::size_t i = 0; i < design.points.size(); ++i) {
        add(design.points[i]);
        if (i < proof.cut_contour.size() && finite(proof.cut_contour[i])) {
            add(design.points[i] + exaggerate * (proof.cut_contour[i] - design.points[i]));
        }
    }
    if (v.lo.x() > v.hi.x()) {
        v.lo = Vector2d::Zero();
        v.hi = Vector2d::Zero();
    }
    const Vector2d pad = Vector2d::Constant(2.2 * radius_in);
    v.lo -= pad;
    v.hi += pad;
    const Vector2d size = (v.hi - v.lo).cwiseMax(1e-6);
    const double full_w = kWidth - kLeft - kRight;
    v.scale = std::min(full_w / size.x(), kMaxPlotHeight / size.y());
    v.plot_w = size.x() * v.scale;
    v.plot_h = size.y() * v.scale;
    v.x0 = kLeft + (full_w - v.plot_w) / 2;
    return v;
}

std::string rgb(const std::array<double, 3>& c) {
    return fmt::format("#{:02x}{:02x}{:02x}", int(std::lround(c[0])), int(std::lround(c[1])),
                       int(std::lround(c[2])));
}

std::array<double, 3> mix(const std::array<double, 3>& a, const std::array<double, 3>& b,
                          double f) {
    return {a[0] + (b[0] - a[0]) * f, a[1] + (b[1] - a[1]) * f, a[2] + (b[2] - a[2]) * f};
}

// The colour step of a deviation on the scale +/- full_in: -kLevels .. kLevels.
int level(double dev_in, double full_in) {
    const double f = std::clamp(dev_in / full_in, -1.0, 1.0);
    return static_cast<int>(std::lround(f * kLevels));
}

std::string level_colour(int lv) {
    const double f = std::abs(lv) / double(kLevels);
    return rgb(lv < 0 ? mix(kWhite, kBlue, f) : mix(kWhite, kRed, f));
}

void draw_axes(std::string& svg, const View& v) {
    fmt::format_to(std::back_inserter(svg),
                   R"(<rect x="{:.1f}" y="{:.1f}" width="{:.1f}" height="{:.1f}" fill="none" )"
                   R"(stroke="#888" stroke-width="1"/>)"
                   "\n",
                   v.x0, v.y0, v.plot_w, v.plot_h);
    svg += fmt::format(R"(<g {} font-size="12" fill="#333">)"
                       "\n",
                       kFont);
    const auto ticks = [&](double lo, double hi, double span_px) {
        const double step = nice_ceil((hi - lo) / std::max(3.0, span_px / 90));
        const int decimals = std::max(0, -static_cast<int>(std::floor(std::log10(step) + 1e-9)));
        std::vector<std::pair<double, std::string>> out;
        for (double t = std::ceil(lo / step) * step; t <= hi + 1e-9 * step; t += step) {
            const double shown = std::abs(t) < step * 1e-6 ? 0.0 : t;
            out.emplace_back(t, fmt::format("{:.{}f}", shown, decimals));
        }
        return out;
    };
    for (const auto& [x, label] : ticks(v.lo.x(), v.hi.x(), v.plot_w)) {
        const double X = v.px(x);
        const double bottom = v.y0 + v.plot_h;
        fmt::format_to(
            std::back_inserter(svg),
            R"(<line x1="{0:.1f}" y1="{1:.1f}" x2="{0:.1f}" y2="{2:.1f}" stroke="#eee"/>)"
            R"(<line x1="{0:.1f}" y1="{2:.1f}" x2="{0:.1f}" y2="{3:.1f}" stroke="#888"/>)"
            R"(<text x="{0:.1f}" y="{4:.1f}" text-anchor="middle">{5}</text>)"
            "\n",
            X, v.y0, bottom, bottom + 6, bottom + 20, label);
    }
    for (const auto& [y, label] : ticks(v.lo.y(), v.hi.y(), std::max(v.plot_h, 220.0))) {
        const double Y = v.py(y);
        const double right = v.x0 + v.plot_w;
        fmt::format_to(
            std::back_inserter(svg),
            R"(<line x1="{1:.1f}" y1="{0:.1f}" x2="{2:.1f}" y2="{0:.1f}" stroke="#eee"/>)"
            R"(<line x1="{3:.1f}" y1="{0:.1f}" x2="{1:.1f}" y2="{0:.1f}" stroke="#888"/>)"
            R"(<text x="{4:.1f}" y="{5:.1f}" text-anchor="end">{6}</text>)"
            "\n",
            Y, v.x0, right, v.x0 - 6, v.x0 - 9, Y + 4, label);
    }
    fmt::format_to(std::back_inserter(svg),
                   R"(<text x="{:.1f}" y="{:.1f}" text-anchor="middle">x, inches</text>)"
                   "\n",
                   v.x0 + v.plot_w / 2, v.y0 + v.plot_h + 36);
    svg += "</g>\n";
}

// A polyline as path data, broken where a point is not finite.
std::string path_data(const View& v, const std::vector<Vector2d>& pts) {
    std::string d;
    bool pen_down = false;
    for (const Vector2d& p : pts) {
        if (!finite(p)) {
            pen_down = false;
            continue;
        }
        fmt::format_to(std::back_inserter(d), "{}{:.2f} {:.2f} ", pen_down ? "L" : "M", v.px(p.x()),
                       v.py(p.y()));
        pen_down = true;
    }
    return d;
}

bool inside(const View& v, const Vector2d& p) {
    return p.x() >= v.lo.x() && p.x() <= v.hi.x() && p.y() >= v.lo.y() && p.y() <= v.hi.y();
}

// kCircles cutter outlines, evenly spaced along the length of path that lies in the view.
void draw_cutters(std::string& svg, const View& v, const std::vector<Vector2d>& runs,
                  double radius_in) {
    std::vector<double> along(runs.size(), 0); // length in view up to each point
    for (std::size_t k = 1; k < runs.size(); ++k) {
        const bool in = inside(v, runs[k - 1]) && inside(v, runs[k]);
        along[k] = along[k - 1] + (in ? (runs[k] - runs[k - 1]).norm() : 0);
    }
    if (runs.size() < 2 || along.back() <= 0) {
        return;
    }
    svg += R"(<g fill="none" stroke="#777" stroke-opacity="0.45" stroke-width="1">)"
           "\n";
    std::size_t k = 1;
    for (int c = 0; c < kCircles; ++c) {
        const double s = along.back() * (c + 0.5) / kCircles;
        while (k + 1 < runs.size() && along[k] < s) {
            ++k;
        }
        const double len = along[k] - along[k - 1];
        const double f = len > 0 ? (s - along[k - 1]) / len : 0;
        const Vector2d centre = runs[k - 1] + f * (runs[k] - runs[k - 1]);
        fmt::format_to(std::back_inserter(svg),
                       R"(<circle cx="{:.2f}" cy="{:.2f}" r="{:.2f}"/>)"
                       R"(<circle cx="{:.2f}" cy="{:.2f}" r="1.5" fill="#777"/>)"
                       "\n",
                       v.px(centre.x()), v.py(centre.y()), radius_in * v.scale, v.px(centre.x()),
                       v.py(centre.y()));
    }
    svg += "</g>\n";
}

// The colour band, laid just inside the material, one polyline per run of equal colour.
void draw_band(std::string& svg, const View& v, const CutProof& proof, const DesignContour& design,
               double full_in) {
    const std::size_t n = design.points.size();
    // In pixels (y down), so the band keeps its width whatever the scale. Plain doubles: GCC 12
    // at -O2 warns falsely about Eigen temporaries here.
    const auto band_point = [&](std::size_t i) {
        const double nx = design.normals[i].x();
        const double ny = design.normals[i].y();
        const double len = std::hypot(nx, ny);
        const double off = (kBand_px / 2 + 0.5) / (len > 0 ? len : 1);
        return std::pair<double, double>{v.px(design.points[i].x()) - off * nx,
                                         v.py(design.points[i].y()) + off * ny};
    };
    const auto colour_of = [&](std::size_t i) {
        const double a = proof.deviation_in[i];
        const double b = proof.deviation_in[i + 1];
        if (std::isnan(a) || std::isnan(b)) {
            return std::string(kGrey);
        }
        return level_colour(level((a + b) / 2, full_in));
    };
    fmt::format_to(std::back_inserter(svg),
                   R"(<g fill="none" stroke-width="{}" stroke-linejoin="round">)"
                   "\n",
                   kBand_px);
    std::size_t i = 0;
    while (i + 1 < n) {
        const std::string colour = colour_of(i);
        std::size_t j = i + 1; // the run covers segments i .. j-1
        while (j + 1 < n && colour_of(j) == colour) {
            ++j;
        }
        std::string d;
        for (std::size_t k = i; k <= j; ++k) {
            const auto [x, y] = band_point(k);
            fmt::format_to(std::back_inserter(d), "{}{:.2f} {:.2f} ", k == i ? "M" : "L", x, y);
        }
        fmt::format_to(std::back_inserter(svg),
                       R"(<path d="{}" stroke="{}"/>)"
                       "\n",
                       d, colour);
        i = j;
    }
    svg += "</g>\n";
}

void draw_legend(std::string& svg, double top, const CutProof& proof, double radius_in,
                 double exaggerate, double full_in, std::size_t design_points) {
    const double thou = full_in * 1000;
    const double bar_x = kLeft, bar_w = 320, bar_y = top + 14;
    svg += R"(<defs><linearGradient id="deviation" x1="0" x2="1" y1="0" y2="0">)";
    fmt::format_to(std::back_inserter(svg),
                   R"(<stop offset="0" stop-color="{}"/><stop offset="0.5" stop-color="#ffffff"/>)"
                   R"(<stop offset="1" stop-color="{}"/></linearGradient></defs>)"
                   "\n",
                   rgb(kBlue), rgb(kRed));
    fmt::format_to(
        std::back_inserter(svg),
        R"(<g {} font-size="12" fill="#222">)"
        "\n"
        R"svg(<rect x="{:.1f}" y="{:.1f}" width="{}" height="14" fill="url(#deviation)" )svg"
        R"(stroke="#666"/>)"
        "\n",
        kFont, bar_x, bar_y, bar_w);
    const auto label = [](double v) {
        return v == 0 ? std::string("0") : fmt::format("{:+.{}f}", v, std::abs(v) >= 10 ? 0 : 1);
    };
    for (int k = -2; k <= 2; ++k) {
        const double x = bar_x + bar_w * (k + 2) / 4.0;
        fmt::format_to(
            std::back_inserter(svg),
            R"(<line x1="{0:.1f}" y1="{1:.1f}" x2="{0:.1f}" y2="{2:.1f}" stroke="#666"/>)"
            R"(<text x="{0:.1f}" y="{3:.1f}" text-anchor="middle">{4}</text>)"
            "\n",
            x, bar_y + 14, bar_y + 18, bar_y + 31, label(thou * k / 2));
    }
    fmt::format_to(std::back_inserter(svg),
                   R"(<text x="{:.1f}" y="{:.1f}">deviation from the design, thousandths of an )"
                   R"(inch</text><text x="{:.1f}" y="{:.1f}" fill="#555">blue = gouge, white = )"
                   R"(on the design, red = leftover, grey = not machined</text>)"
                   "\n",
                   bar_x + bar_w + 36, bar_y + 11, bar_x + bar_w + 36, bar_y + 27);
    // Line key.
    const double key_y = top + 64;
    struct Key {
        const char* stroke;
        double width;
        std::string text;
    };
    const std::array<Key, 4> keys{{
        {"#000", 1, "design contour"},
        {"#1f5fd0", 1, "cutter-centre path"},
        {"#777", 1, fmt::format("cutter, radius {:.4f} in", radius_in)},
        {"#d02020", 1.6, fmt::format("cut surface, deviation \u00d7 {:g}", exaggerate)},
    }};
    double x = kLeft;
    for (const Key& key : keys) {
        fmt::format_to(std::back_inserter(svg),
                       R"(<line x1="{0:.1f}" y1="{1:.1f}" x2="{2:.1f}" y2="{1:.1f}" stroke="{3}" )"
                       R"(stroke-width="{4}"/><text x="{5:.1f}" y="{6:.1f}">{7}</text>)"
                       "\n",
                       x, key_y, x + 28, key.stroke, key.width, x + 34, key_y + 4,
                       cardreader::xml_escape(key.text));
        x += 250;
    }
    fmt::format_to(
        std::back_inserter(svg),
        R"(<text x="{:.1f}" y="{:.1f}" font-size="14">max gouge <tspan font-weight="bold">)"
        R"({:.4f} in</tspan> ({:.1f} thou) · max leftover <tspan font-weight="bold">{:.4f} in)"
        R"(</tspan> ({:.1f} thou) · max scallop <tspan font-weight="bold">{:.4f} in</tspan> )"
        R"(({:.1f} thou) · machined {} of {} design points</text>)"
        "\n",
        kLeft, top + 98, proof.max_gouge_in, proof.max_gouge_in * 1000, proof.max_leftover_in,
        proof.max_leftover_in * 1000, proof.max_scallop_in, proof.max_scallop_in * 1000,
        proof.machined_points, design_points);
    svg += "</g>\n";
}

} // namespace

std::string cut_svg(const CutProof& proof, const std::vector<Vector2d>& path,
                    const DesignContour& design, double radius_in, const std::string& title,
                    double exaggerate) {
    const View v = make_view(proof, design, radius_in, exaggerate);
    const double height = kTop + v.plot_h + kTicks + kLegend;
    const double worst = std::max(proof.max_gouge_in, proof.max_leftover_in);
    const double full_in = worst > 0 ? nice_ceil(worst * 1000) / 1000 : 0.001;

    std::string svg;
    fmt::format_to(std::back_inserter(svg),
                   R"(<svg xmlns="http://www.w3.org/2000/svg" width="{0:.0f}" height="{1:.0f}" )"
                   R"(viewBox="0 0 {0:.0f} {1:.0f}">)"
                   "\n"
                   R"(<rect width="100%" height="100%" fill="#ffffff"/>)"
                   "\n"
                   R"(<text x="{2:.1f}" y="32" {3} font-size="20" font-weight="bold" )"
                   R"(fill="#111">{4}</text>)"
                   "\n",
                   kWidth, height, kLeft, kFont, cardreader::xml_escape(title));
    fmt::format_to(std::back_inserter(svg),
                   R"(<defs><clipPath id="plot"><rect x="{:.1f}" y="{:.1f}" width="{:.1f}" )"
                   R"(height="{:.1f}"/></clipPath></defs>)"
                   "\n",
                   v.x0, v.y0, v.plot_w, v.plot_h);
    draw_axes(svg, v);

    svg += R"svg(<g clip-path="url(#plot)">)svg"
           "\n";
    // The path at a quarter-pixel tolerance: the staircase's corners are below a pixel anyway.
    const std::vector<Vector2d> runs = simplify_path(path, 0.25 / v.scale);
    draw_cutters(svg, v, runs, radius_in);
    fmt::format_to(std::back_inserter(svg),
                   R"(<path d="{}" fill="none" stroke="#1f5fd0" stroke-width="0.9"/>)"
                   "\n",
                   path_data(v, runs));
    if (proof.deviation_in.size() == design.points.size() &&
        design.normals.size() == design.points.size()) {
        draw_band(svg, v, proof, design, full_in);
    }
    fmt::format_to(std::back_inserter(svg),
                   R"(<path d="{}" fill="none" stroke="#000" stroke-width="1"/>)"
                   "\n",
                   path_data(v, design.points));
    std::vector<Vector2d> shown(design.points.size(),
                                Vector2d::Constant(std::numeric_limits<double>::quiet_NaN()));
    for (std::size_t i = 0; i < shown.size() && i < proof.cut_contour.size(); ++i) {
        shown[i] = design.points[i] + exaggerate * (proof.cut_contour[i] - design.points[i]);
    }
    fmt::format_to(std::back_inserter(svg),
                   R"(<path d="{}" fill="none" stroke="#d02020" stroke-width="1.6" )"
                   R"(stroke-linejoin="round"/>)"
                   "\n",
                   path_data(v, shown));
    svg += "</g>\n";

    draw_legend(svg, kTop + v.plot_h + kTicks, proof, radius_in, exaggerate, full_in,
                design.points.size());
    svg += "</svg>\n";
    return svg;
}

} // namespace parsons::decks
