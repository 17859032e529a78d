// Drawing the plot that PlotSvgRecorder (plot_svg.cpp) recorded.
#include "outputs/plots/plot_svg.hpp"

#include "cardreader/card_svg.hpp"
#include "outputs/plots/plot_geometry.hpp"
#include "outputs/plots/plot_press_lanes.hpp"
#include "outputs/plots/plot_reduce.hpp"
#include "outputs/plots/plot_spindle_lanes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace parsons::cli {

using cardreader::Axis;
using relaylogic::SignalId;
using Point = PlotSvgRecorder::Point;

// ---------------------------------------------------------------------------------------------
// Drawing
//
//   title, what happened (and the stop message)
//   legend
//   card 1      card 2        card 3 ...                 <- one label per card where room
//   table  motor 38
//   +--------------------------------------------+ speed 1
//   |  position (left scale, inches)             | speed 2
//   |  speed switch step line (right scale)      | speed 3
//   +--------------------------------------------+ off
//   cross ... vertical ... swivel ... tilt
//   crank 21 ... die 20 ... registers 14, 11 ... reader 60 ...   <- with a press only
//   motor 27 ... tool 16 ... 12a ... feed ... bus 35, PC 130     <- with a tap card only
//   0     100     200 ...  machine time (s)

namespace {

using plot::kCardColour;
using plot::kGridColour;
using plot::kLeft;
using plot::kRight;
using plot::kStopColour;
using plot::kTextColour;
using plot::kWidth;
using plot::nice_ticks;
using plot::on_intervals;
using plot::Scale;
using plot::Ticks;

constexpr double kPanelHeight = 150;
constexpr double kPanelGap = 42;
constexpr double kBottomMargin = 62;

constexpr const char* kPositionColour = "#1f4e9c";
constexpr const char* kSpeedColour = "#f28e2b";
constexpr const char* kSlowDownColour = "#c4530b";

// Word-wraps text into at most max_lines lines of about width characters ("..." if cut).
std::vector<std::string> wrap(std::string_view text, std::size_t width, std::size_t max_lines) {
    std::vector<std::string> lines;
    while (!text.empty() && lines.size() < max_lines) {
        if (text.size() <= width) {
            lines.emplace_back(text);
            return lines;
        }
        std::size_t cut = text.rfind(' ', width);
        if (cut == std::string_view::npos || cut == 0) {
            cut = width;
        }
        lines.emplace_back(text.substr(0, cut));
        text.remove_prefix(cut);
        while (!text.empty() && text.front() == ' ') {
            text.remove_prefix(1);
        }
    }
    if (!text.empty() && !lines.empty()) {
        lines.back() += " ...";
    }
    return lines;
}

double interpolate(const std::vector<Point>& path, double t) {
    if (path.empty()) {
        return 0;
    }
    auto it = std::lower_bound(path.begin(), path.end(), t,
                               [](const Point& p, double v) { return p.t < v; });
    if (it == path.end()) {
        return path.back().x;
    }
    if (it == path.begin() || it->t == t) {
        return it->x;
    }
    const Point& b = *it;
    const Point& a = *(it - 1);
    return a.x + (b.x - a.x) * (t - a.t) / (b.t - a.t);
}

// The value of a step signal at t: after every change at or before t.
double step_value_at(const std::vector<Point>& steps, double t) {
    double v = steps.empty() ? 0 : steps.front().x;
    for (const Point& s : steps) {
        if (s.t > t) {
            break;
        }
        v = s.x;
    }
    return v;
}

// The speed-switch scale of a panel: slower is lower, off at the bottom, then 3 (slowest), 2,
// 1 (fastest) at the top.
double speed_y(double position, double bottom) {
    const int level = position >= 1 && position <= 3 ? 4 - static_cast<int>(position) : 0;
    return bottom - 8 - level * (kPanelHeight - 16) / 3.0;
}

struct CardLine {
    double x = 0; // px
    int number = 0;
};

// What one panel shows.
struct Panel {
    std::string name;  // "table"
    std::string motor; // "motor 38"
    std::vector<Point> path;
    std::vector<Point> speed;
    std::vector<Point> motor_steps;
    const std::vector<double>* slow_downs = nullptr;
    const std::vector<double>* stops = nullptr;
    const std::vector<PlotSvgRecorder::Trip>* trips = nullptr;
};

struct StopMark {
    double t = 0;
    std::string reason;
};

class ChartWriter {
public:
    // press, spindle: the run's press and spindle synchronisation (additions), drawn in lanes
    // under the panels if present.
    ChartWriter(double t_end, std::size_t message_lines, const PressTrace& press,
                const SpindleTrace& spindle)
        : press_(press), spindle_(spindle), tx_{0, t_end > 0 ? t_end : 1.0, kLeft, kRight},
          time_ticks_(nice_ticks(0, tx_.d1, 10)),
          legend_y_(80 + 16 * static_cast<double>(message_lines)),
          first_top_(legend_y_ + 62 + 20 * press_legend_rows(press) +
                     20 * spindle_legend_rows(spindle)) {
        svg_.reserve(64 * 1024);
    }

    void begin();
    void titles(const std::string& title, const std::string& outcome,
                const std::vector<std::string>& message);
    void legend(bool with_conditions);
    void cards(const std::vector<CardLine>& cards);
    void panel(std::size_t i, const Panel& p, const std::vector<CardLine>& cards,
               const std::optional<StopMark>& stop);
    void press(const std::vector<CardLine>& cards, const std::optional<StopMark>& stop);
    void spindle(const std::vector<CardLine>& cards, const std::optional<StopMark>& stop);
    void time_axis(const std::optional<StopMark>& stop);
    std::string finish() {
        fmt::format_to(out(), "</svg>\n");
        return std::move(svg_);
    }
    double x(double t) const { return tx_(t); }

private:
    std::back_insert_iterator<std::string> out() { return std::back_inserter(svg_); }
    double top(std::size_t i) const {
        return first_top_ + static_cast<double>(i) * (kPanelHeight + kPanelGap);
    }
    // The panels' bottom, then the press lanes', then the spindle lanes' (additions; none in a
    // 1952 run).
    double panels_bottom() const { return top(cardreader::kAxisCount - 1) + kPanelHeight; }
    double press_bottom() const { return panels_bottom() + press_lanes_height(press_); }
    double time_axis_y() const { return press_bottom() + spindle_lanes_height(spindle_); }
    LaneFrame lane_frame_at(double top, const std::vector<CardLine>& cards,
                            const std::optional<StopMark>& stop) const;
    double height() const { return time_axis_y() + kBottomMargin; }
    void polyline(const std::vector<std::vector<std::pair<double, double>>>& runs,
                  const char* attributes);
    void speed_line(const Panel& p, double bottom);
    void markers(const Panel& p, const Scale& ty);
    void trip_markers(const Panel& p, const Scale& ty);

    const PressTrace& press_;
    const SpindleTrace& spindle_;
    std::string svg_;
    Scale tx_;
    Ticks time_ticks_;
    double legend_y_;
    double first_top_;
};

void ChartWriter::begin() {
    fmt::format_to(out(),
                   R"(<svg xmlns="http://www.w3.org/2000/svg" width="{0:.0f}" height="{1:.0f}" )"
                   R"(viewBox="0 0 {0:.0f} {1:.0f}" )"
                   R"(font-family="DejaVu Sans, Helvetica, Arial, sans-serif">)"
                   "\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<defs>\n",
                   kWidth, height());
    for (std::size_t i = 0; i < cardreader::kAxisCount; ++i) {
        fmt::format_to(out(),
                       R"(<clipPath id="plot-clip-{}"><rect x="{:.1f}" y="{:.1f}" )"
                       R"(width="{:.1f}" height="{:.1f}"/></clipPath>)"
                       "\n",
                       i, kLeft - 7, top(i) - 13, kRight - kLeft + 14, kPanelHeight + 20);
    }
    press_clip_paths(svg_, press_, panels_bottom() + kPanelGap);
    spindle_clip_paths(svg_, spindle_, press_bottom() + kPanelGap);
    fmt::format_to(out(), "</defs>\n");
}

void ChartWriter::titles(const std::string& title, const std::string& outcome,
                         const std::vector<std::string>& message) {
    fmt::format_to(
        out(),
        R"(<text x="{:.1f}" y="30" font-size="19" font-weight="bold" fill="{}">{}</text>)"
        "\n"
        R"(<text x="{:.1f}" y="52" font-size="12.5" fill="#444">{}</text>)"
        "\n",
        kLeft, kTextColour, cardreader::xml_escape(title), kLeft, cardreader::xml_escape(outcome));
    for (std::size_t k = 0; k < message.size(); ++k) {
        fmt::format_to(out(),
                       R"(<text x="{:.1f}" y="{:.1f}" font-size="11.5" fill="{}">{}</text>)"
                       "\n",
                       kLeft, 71 + 16 * static_cast<double>(k), kStopColour,
                       cardreader::xml_escape(message[k]));
    }
}

void ChartWriter::legend(bool with_conditions) {
    const double y = legend_y_;
    double x = kLeft;
    auto label = [&](const char* text) {
        fmt::format_to(out(),
                       R"(<text x="{:.1f}" y="{:.1f}" font-size="12" fill="{}">{}</text>)"
                       "\n",
                       x, y + 4, kTextColour, text);
        x += static_cast<double>(std::string_view(text).size()) * 6.9 + 26;
    };
    auto step_glyph = [&](const char* attributes) {
        fmt::format_to(out(),
                       R"(<polyline fill="none" stroke="{}" {} points=")"
                       R"({:.1f},{:.1f} {:.1f},{:.1f} {:.1f},{:.1f} {:.1f},{:.1f}"/>)"
                       "\n",
                       kSpeedColour, attributes, x, y - 5, x + 12, y - 5, x + 12, y + 4, x + 24,
                       y + 4);
        x += 30;
    };
    fmt::format_to(out(),
                   R"(<line x1="{0:.1f}" y1="{1:.1f}" x2="{2:.1f}" y2="{1:.1f}" stroke="{3}" )"
                   R"(stroke-width="2"/>)"
                   "\n",
                   x, y, x + 24, kPositionColour);
    x += 30;
    label("real position, in (left scale)");
    step_glyph(R"(stroke-width="1.8")");
    label("speed switch 236 (right scale)");
    step_glyph(R"(stroke-width="1.2" stroke-opacity="0.4")");
    label("motor off");
    fmt::format_to(out(),
                   R"(<path d="M{:.1f},{:.1f} h11 l-5.5,9 z" fill="{}" stroke="white" )"
                   R"(stroke-width="0.8"/>)"
                   "\n",
                   x, y - 5, kSlowDownColour);
    x += 17;
    label("slow-down");
    fmt::format_to(out(),
                   R"(<circle cx="{:.1f}" cy="{:.1f}" r="4.5" fill="{}" stroke="white" )"
                   R"(stroke-width="0.8"/>)"
                   "\n",
                   x + 5, y, kStopColour);
    x += 16;
    label("stop");
    fmt::format_to(out(),
                   R"(<line x1="{0:.1f}" y1="{1:.1f}" x2="{0:.1f}" y2="{2:.1f}" stroke="{3}" )"
                   R"(stroke-dasharray="3,2"/>)"
                   "\n",
                   x + 3, y - 7, y + 7, kCardColour);
    x += 10;
    label("card read");
    if (with_conditions) { // condition cards (an addition): only on a chart that has trips
        fmt::format_to(out(),
                       R"(<path d="M{:.1f},{:.1f} l6,6 l-6,6 l-6,-6 z" fill="#59a14f" )"
                       R"(stroke="white" stroke-width="0.8"/>)"
                       "\n",
                       x + 6, y - 6);
        x += 16;
        label("condition met (EP 0640901)");
    }
    press_legend(svg_, press_, y + 20); // press synchronisation (an addition): a row of its own
    spindle_legend(svg_, spindle_, y + 20 + 20 * press_legend_rows(press_)); // spindle sync.
}

// One label per card where there is room: "card N" when every card has room, else "N".
void ChartWriter::cards(const std::vector<CardLine>& cards) {
    bool roomy = true;
    for (std::size_t k = 1; k < cards.size(); ++k) {
        roomy = roomy && cards[k].x - cards[k - 1].x >= 50;
    }
    double free_from = -1e9;
    for (const CardLine& c : cards) {
        const std::string text =
            roomy ? fmt::format("card {}", c.number) : fmt::format("{}", c.number);
        const double w = static_cast<double>(text.size()) * 6.2 + 6;
        if (c.x - 2 < free_from || c.x - 2 + w > kWidth - 4) {
            continue;
        }
        fmt::format_to(out(),
                       R"(<text x="{:.1f}" y="{:.1f}" font-size="10.5" fill="#555">{}</text>)"
                       "\n",
                       c.x - 2, first_top_ - 29, text);
        free_from = c.x - 2 + w;
    }
}

void ChartWriter::polyline(const std::vector<std::vector<std::pair<double, double>>>& runs,
                           const char* attributes) {
    std::string d;
    for (const auto& run : runs) {
        double lx = -1e9;
        double ly = -1e9;
        for (std::size_t i = 0; i < run.size(); ++i) {
            const double x = std::round(run[i].first * 10) / 10;
            const double y = std::round(run[i].second * 10) / 10;
            if (x == lx && y == ly) {
                continue; // lands where the last point did
            }
            fmt::format_to(std::back_inserter(d), "{}{:.1f},{:.1f}", i == 0 ? "M" : " L", x, y);
            lx = x;
            ly = y;
        }
    }
    if (!d.empty()) {
        fmt::format_to(out(),
                       R"(<path fill="none" {} d="{}"/>)"
                       "\n",
                       attributes, d);
    }
}

// The speed switch as a step line: faint all along, strong while the motor runs.
void ChartWriter::speed_line(const Panel& p, double bottom) {
    auto y = [bottom](double position) { return speed_y(position, bottom); };
    auto run = [&](double t0, double t1) {
        std::vector<std::pair<double, double>> pts;
        double v = step_value_at(p.speed, t0);
        pts.emplace_back(tx_(t0), y(v));
        for (const Point& s : p.speed) {
            if (s.t > t0 && s.t < t1) {
                pts.emplace_back(tx_(s.t), y(v));
                v = s.x;
                pts.emplace_back(tx_(s.t), y(v));
            }
        }
        pts.emplace_back(tx_(t1), y(v));
        return pts;
    };
    polyline({run(0, tx_.d1)}, R"(class="speed-off" stroke="#f28e2b" stroke-opacity="0.4" )"
                               R"(stroke-width="1.2")");
    std::vector<std::vector<std::pair<double, double>>> running;
    for (const auto& [t0, t1] : on_intervals(p.motor_steps, tx_.d1)) {
        running.push_back(run(t0, t1));
    }
    polyline(running, R"(class="speed" stroke="#f28e2b" stroke-width="1.8")");
}

void ChartWriter::markers(const Panel& p, const Scale& ty) {
    double last_x = -1e9;
    for (double t : *p.slow_downs) {
        const double x = tx_(t);
        if (std::fabs(x - last_x) >= 1.5) {
            last_x = x;
            fmt::format_to(out(),
                           R"(<path class="slowdown-marker" data-axis="{}" )"
                           R"(d="M{:.1f},{:.1f} h11 l-5.5,9 z" fill="{}" stroke="white" )"
                           R"(stroke-width="0.8"><title>{}: slow-down at {:.3f} s</title></path>)"
                           "\n",
                           p.name, x - 5.5, ty(interpolate(p.path, t)) - 12, kSlowDownColour,
                           p.name, t);
        }
    }
    last_x = -1e9;
    for (double t : *p.stops) {
        const double x = tx_(t);
        if (std::fabs(x - last_x) >= 1.5) {
            last_x = x;
            const double at = interpolate(p.path, t);
            fmt::format_to(out(),
                           R"(<circle class="stop-marker" data-axis="{}" cx="{:.1f}" cy="{:.1f}" )"
                           R"(r="4.5" fill="{}" stroke="white" stroke-width="0.8">)"
                           R"(<title>{}: stop at {:.3f} s, {:.4f} in</title></circle>)"
                           "\n",
                           p.name, x, ty(at), kStopColour, p.name, t, at);
        }
    }
}

// Where a condition was met (condition cards, an addition after EP 0640901): a diamond on the
// path, titled with the event, the action and the position.
void ChartWriter::trip_markers(const Panel& p, const Scale& ty) {
    for (const auto& trip : *p.trips) {
        const double x = tx_(trip.t);
        const double y = ty(interpolate(p.path, trip.t));
        fmt::format_to(
            out(),
            R"(<path class="condition-marker" data-axis="{}" )"
            R"(d="M{:.1f},{:.1f} l6,6 l-6,6 l-6,-6 z" fill="#59a14f" stroke="white" )"
            R"(stroke-width="0.8"><title>{}: {} (condition met at {:.3f} s)</title></path>)"
            "\n",
            p.name, x, y - 6, p.name, cardreader::xml_escape(trip.label), trip.t);
    }
}

void ChartWriter::panel(std::size_t i, const Panel& p, const std::vector<CardLine>& cards,
                        const std::optional<StopMark>& stop) {
    const double panel_top = top(i);
    const double bottom = panel_top + kPanelHeight;
    double lo = 0;
    double hi = 0;
    if (!p.path.empty()) {
        const auto [mn, mx] = std::minmax_element(
            p.path.begin(), p.path.end(), [](const Point& a, const Point& b) { return a.x < b.x; });
        lo = mn->x;
        hi = mx->x;
    }
    const double span = std::max(hi - lo, 0.01);
    const double mid = (lo + hi) / 2;
    const Scale ty{mid - span * 0.56, mid + span * 0.56, bottom, panel_top};
    const Ticks y_ticks = nice_ticks(ty.d0, ty.d1, 5);

    fmt::format_to(
        out(),
        R"(<g class="panel" data-axis="{0}">)"
        "\n"
        R"(<text x="{1:.1f}" y="{2:.1f}" font-size="13.5" fill="{3}">)"
        R"(<tspan font-weight="bold">{0}</tspan><tspan dx="9" fill="#666">{4}</tspan></text>)"
        "\n"
        R"(<rect x="{1:.1f}" y="{5:.1f}" width="{6:.1f}" height="{7:.1f}" )"
        R"(fill="#fdfdfd" stroke="#b8b8b8"/>)"
        "\n",
        p.name, kLeft, panel_top - 9, kTextColour, cardreader::xml_escape(p.motor), panel_top,
        kRight - kLeft, kPanelHeight);
    for (double v : y_ticks.values) {
        const double y = ty(v);
        fmt::format_to(out(),
                       R"(<line x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}" stroke="{}"/>)"
                       R"(<text x="{:.1f}" y="{:.1f}" font-size="11" text-anchor="end" )"
                       R"(fill="{}">{:.{}f}</text>)"
                       "\n",
                       kLeft, y, kRight, y, kGridColour, kLeft - 6, y + 4, kPositionColour, v,
                       y_ticks.decimals);
    }
    for (double v : time_ticks_.values) {
        fmt::format_to(out(),
                       R"(<line x1="{0:.1f}" y1="{1:.1f}" x2="{0:.1f}" y2="{2:.1f}" stroke="{3}"/>)"
                       "\n",
                       tx_(v), panel_top, bottom, kGridColour);
    }
    for (int position : {0, 3, 2, 1}) {
        fmt::format_to(out(),
                       R"(<text x="{:.1f}" y="{:.1f}" font-size="10.5" fill="{}">{}</text>)"
                       "\n",
                       kRight + 7, speed_y(position, bottom) + 4, kSpeedColour,
                       position == 0 ? std::string("off") : fmt::format("speed {}", position));
    }
    fmt::format_to(out(),
                   R"~(<text transform="translate({:.1f},{:.1f}) rotate(-90)" font-size="11" )~"
                   R"(text-anchor="middle" fill="{}">inches</text>)"
                   "\n",
                   kLeft - 64, (panel_top + bottom) / 2, kPositionColour);
    for (const CardLine& c : cards) {
        fmt::format_to(out(),
                       R"(<line class="card" x1="{0:.1f}" y1="{1:.1f}" x2="{0:.1f}" y2="{2:.1f}" )"
                       R"(stroke="{3}" stroke-width="0.8" stroke-dasharray="3,2"/>)"
                       "\n",
                       c.x, i == 0 ? panel_top - 24 : panel_top, bottom, kCardColour);
    }
    if (stop) {
        fmt::format_to(out(),
                       R"(<line x1="{0:.1f}" y1="{1:.1f}" x2="{0:.1f}" y2="{2:.1f}" )"
                       R"(stroke="{3}" stroke-width="1.2" stroke-dasharray="6,3"/>)"
                       "\n",
                       tx_(stop->t), panel_top, bottom, kStopColour);
    }
    fmt::format_to(out(),
                   R"~(<g clip-path="url(#plot-clip-{})">)~"
                   "\n",
                   i);
    speed_line(p, bottom);
    std::vector<std::pair<double, double>> line;
    line.reserve(p.path.size());
    for (const Point& q : p.path) {
        line.emplace_back(tx_(q.t), ty(q.x));
    }
    polyline({line}, R"(class="position" stroke="#1f4e9c" stroke-width="1.8" )"
                     R"(stroke-linejoin="round")");
    markers(p, ty);
    trip_markers(p, ty);
    fmt::format_to(out(), "</g>\n</g>\n");
}

// Where a group of lanes under the panels stands, on their time axis.
LaneFrame ChartWriter::lane_frame_at(double top, const std::vector<CardLine>& cards,
                                     const std::optional<StopMark>& stop) const {
    LaneFrame frame{tx_, &time_ticks_, top, {}, std::nullopt};
    for (const CardLine& c : cards) {
        frame.card_x.push_back(c.x);
    }
    if (stop) {
        frame.stop_x = tx_(stop->t);
    }
    return frame;
}

// The press lanes (an addition after EP 0436887) under the panels, on their time axis.
void ChartWriter::press(const std::vector<CardLine>& cards, const std::optional<StopMark>& stop) {
    if (press_.present()) {
        press_lanes(svg_, press_, lane_frame_at(panels_bottom() + kPanelGap, cards, stop));
    }
}

// The spindle lanes (an addition after EP 0360190) under those, on the same time axis.
void ChartWriter::spindle(const std::vector<CardLine>& cards, const std::optional<StopMark>& stop) {
    if (spindle_.present()) {
        spindle_lanes(svg_, spindle_, lane_frame_at(press_bottom() + kPanelGap, cards, stop));
    }
}

void ChartWriter::time_axis(const std::optional<StopMark>& stop) {
    const double axis_y = time_axis_y();
    for (double v : time_ticks_.values) {
        fmt::format_to(out(),
                       R"(<line x1="{0:.1f}" y1="{1:.1f}" x2="{0:.1f}" y2="{2:.1f}" )"
                       R"(stroke="#888"/><text x="{0:.1f}" y="{3:.1f}" font-size="11" )"
                       R"(text-anchor="middle" fill="{4}">{5:.{6}f}</text>)"
                       "\n",
                       tx_(v), axis_y, axis_y + 5, axis_y + 18, kTextColour, v,
                       time_ticks_.decimals);
    }
    fmt::format_to(out(),
                   R"(<text x="{:.1f}" y="{:.1f}" font-size="12" text-anchor="middle" )"
                   R"(fill="{}">machine time (s)</text>)"
                   "\n",
                   (kLeft + kRight) / 2, axis_y + 40, kTextColour);
    if (stop) {
        const double x = tx_(stop->t);
        const bool left = x > kRight - 150;
        fmt::format_to(out(),
                       R"(<text x="{:.1f}" y="{:.1f}" font-size="10.5" fill="{}" )"
                       R"(text-anchor="{}">stop: {}</text>)"
                       "\n",
                       left ? x - 4 : x + 4, axis_y + 32, kStopColour, left ? "end" : "start",
                       stop->reason);
    }
}

} // namespace

std::string PlotSvgRecorder::svg() const {
    const double t_end = end_time();
    const std::vector<std::string> message =
        stop_ ? wrap(stop_->message, 140, 3) : std::vector<std::string>{};
    ChartWriter chart(t_end, message.size(), press_, spindle_);
    std::optional<StopMark> stop;
    if (stop_) {
        stop = StopMark{stop_t_, std::string(relaylogic::stop_reason_name(stop_->reason))};
    }
    std::vector<CardLine> cards;
    for (const CardMark& c : cards_) {
        const double x = chart.x(c.t);
        if (cards.empty() || x - cards.back().x >= 1.0) { // one line per pixel
            cards.push_back(CardLine{x, c.number});
        }
    }
    const std::string outcome =
        fmt::format("{} card{} read, {:.2f} s of machine time, {}", cards_.size(),
                    cards_.size() == 1 ? "" : "s", t_end,
                    stop_ ? fmt::format("machine stopped at {:.2f} s: {} (card {})", stop_t_,
                                        relaylogic::stop_reason_name(stop_->reason), stop_->card)
                          : std::string("ran to the end of the deck"));

    chart.begin();
    chart.titles(title_.empty() ? std::string("Parsons-Stulen control: the five lead screws "
                                              "against machine time")
                                : title_,
                 outcome, message);
    chart.legend(std::any_of(axes_.begin(), axes_.end(),
                             [](const AxisTrace& a) { return !a.trips.empty(); }));
    chart.cards(cards);
    for (std::size_t i = 0; i < axes_.size(); ++i) {
        const AxisTrace& a = axes_[i];
        Panel p;
        p.name = std::string(cardreader::axis_name(cardreader::kAxes.at(i)));
        p.motor = a.motor_name.empty() ? std::string("lead screw") : "lead screw, " + a.motor_name;
        p.path = path(cardreader::kAxes.at(i));
        p.speed = a.speed;
        p.motor_steps = a.motor;
        p.slow_downs = &a.slow_downs;
        p.stops = &a.stops;
        p.trips = &a.trips;
        chart.panel(i, p, cards, stop);
    }
    chart.press(cards, stop);
    chart.spindle(cards, stop);
    chart.time_axis(stop);
    return chart.finish();
}

} // namespace parsons::cli
