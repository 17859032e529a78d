// The press lanes of run --plot (plot_press_lanes.hpp):
//
//   ... tilt panel ...
//   crank 21  angle from top dead centre (Fig. 2A)
//   +--------------------------------------------+ deg    /| /| /|   a sawtooth 0..360;
//   |  /|  /|  /|  ..R.......^                   |       / |/ |/ |   R dashed while a card
//   +--------------------------------------------+                   waits, ^ where 61 conducted
//   die 20 (Fig. 2B) ... register 14 ... register 11 ...
//   reader 60  [=====hold=====]   [==]                               a bar while 60 holds
//   (a red band over the crank's lane while the feeder's interlock holds the press)
//   processor 63 (when a drive followed the press)
//   0     100     200 ...  machine time (s)
#include "outputs/plots/plot_press_lanes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iterator>

namespace parsons::cli {

using plot::kLeft;
using plot::kRight;
using plot::Scale;
using Point = PressTrace::Point;

namespace {

using lanes::kLaneHeight;
constexpr double kBarHeight = 30; // reader 60's bars

using namespace press_colours;

enum class LaneKind : std::uint8_t { crank_21, die_20, register_14, register_11, reader_60, p63 };

struct LaneSpec {
    LaneKind kind;
    const char* id;     // data-lane
    const char* name;   // bold title
    const char* what;   // grey title
    const char* unit;   // right of the frame
    const char* colour; // line and scale
    double height;
};

std::vector<LaneSpec> lanes_of(const PressTrace& press) {
    std::vector<LaneSpec> lanes;
    if (!press.present()) {
        return lanes;
    }
    lanes.push_back({LaneKind::crank_21, "crank_21", "crank 21",
                     "press, EP 0436887: angle from top dead centre (Fig. 2A)", "deg", kCrankColour,
                     kLaneHeight});
    lanes.push_back({LaneKind::die_20, "die_20", "die 20",
                     "height above bottom dead centre (Fig. 2B)", "in", kDieColour, kLaneHeight});
    lanes.push_back({LaneKind::register_14, "position_register_14", "position register 14",
                     "the crank's angle in detector pulses, preset by setter 15 at top dead "
                     "centre",
                     "pulses", kRegister14Colour, kLaneHeight});
    lanes.push_back({LaneKind::register_11, "speed_register_11", "speed register 11",
                     "the crank's speed it reads at each reference block (Fig. 6), its pulses "
                     "timed edge to edge",
                     "pulses/s", kRegister11Colour, kLaneHeight});
    lanes.push_back({LaneKind::reader_60, "position_reader_60", "position reader 60",
                     "hold: a card's motion waits for its angle R; grey: a sync card's orders "
                     "wait",
                     "", kHoldEdge, kBarHeight});
    if (press.any_speed_63()) {
        lanes.push_back({LaneKind::p63, "processor_63", "processor 63",
                         "the speed sent to each speed-synchronised drive (Fig. 4)", "in/min",
                         kAxisColours[0], kLaneHeight});
    }
    return lanes;
}

std::back_insert_iterator<std::string> out(std::string& svg) {
    return std::back_inserter(svg);
}

// The value of a line at t (linear between its points).
double value_at(const std::vector<Point>& series, double t) {
    auto it = std::lower_bound(series.begin(), series.end(), t,
                               [](const Point& p, double v) { return p.t < v; });
    if (it == series.end()) {
        return series.empty() ? 0 : series.back().x;
    }
    if (it == series.begin() || it->t == t) {
        return it->x;
    }
    const Point& a = *(it - 1);
    return a.x + (it->x - a.x) * (t - a.t) / (it->t - a.t);
}

class LaneWriter {
public:
    LaneWriter(std::string& svg, const PressTrace& press, const LaneFrame& frame)
        : svg_(svg), press_(press), frame_(frame), t_end_(frame.tx.d1) {}

    void lane(std::size_t index, const LaneSpec& spec, double top);

private:
    void frame(const LaneSpec& spec, double top, double bottom, const std::optional<Scale>& ty,
               const plot::Ticks& ticks);
    void line(const PagePoints& points, const char* cls, const char* colour, double width);
    void crank(const Scale& ty);
    void interlock(double top, double bottom);
    void reader_60(double top, double bottom);
    void processor_63(const Scale& ty);

    std::string& svg_;
    const PressTrace& press_;
    const LaneFrame& frame_;
    double t_end_;
};

void LaneWriter::frame(const LaneSpec& spec, double top, double bottom,
                       const std::optional<Scale>& ty, const plot::Ticks& ticks) {
    lane_frame(svg_, frame_, LaneTitle{spec.name, spec.what, spec.unit, spec.colour}, top, bottom,
               ty, ticks);
}

void LaneWriter::line(const PagePoints& points, const char* cls, const char* colour, double width) {
    lane_path(svg_, points, cls, colour, width);
}

// The crank: its sawtooth, R dashed while a card waits for it, a mark where 61 conducted.
void LaneWriter::crank(const Scale& ty) {
    const auto series = press_.series(PressTrace::Series::crank_21_deg);
    line(on_page(series, frame_.tx, ty, false), "crank", kCrankColour, 1.5);
    const auto& cards = press_.sync_cards();
    for (const auto& [t0, t1] : press_.holds(t_end_)) {
        const PressTrace::SyncMark* card = nullptr;
        for (const auto& c : cards) {
            if (c.t <= t0 && c.order.position_sync) {
                card = &c;
            }
        }
        if (card == nullptr) {
            continue;
        }
        fmt::format_to(out(svg_),
                       R"(<line class="sync-angle" x1="{0:.1f}" y1="{2:.1f}" x2="{1:.1f}" )"
                       R"(y2="{2:.1f}" stroke="{3}" stroke-width="1.2" stroke-dasharray="4,3">)"
                       R"(<title>card {4}: R {5} deg</title></line>)"
                       "\n",
                       frame_.tx(t0), frame_.tx(t1), ty(card->order.angle_deg), kHoldEdge,
                       card->number, card->order.angle_deg);
    }
    for (double t : press_.releases()) {
        const double a = value_at(series, t);
        fmt::format_to(out(svg_),
                       R"(<path class="release-marker" d="M{:.1f},{:.1f} l5,9 h-10 z" )"
                       R"(fill="{}" stroke="white" stroke-width="0.8">)"
                       R"(<title>detector 61: register 14 on R, crank {:.1f} deg at {:.3f} s)"
                       R"(</title></path>)"
                       "\n",
                       frame_.tx(t), ty(a) - 1, kHoldEdge, a, t);
    }
}

// The feeder's interlock: a band over the crank's lane while it held the press (the crank stands).
void LaneWriter::interlock(double top, double bottom) {
    for (const auto& [t0, t1] : press_.interlock_holds(t_end_)) {
        const double x0 = frame_.tx(t0);
        fmt::format_to(out(svg_),
                       R"(<rect class="interlock-hold" x="{:.1f}" y="{:.1f}" width="{:.1f}" )"
                       R"(height="{:.1f}" fill="{}" stroke="{}" stroke-width="0.5">)"
                       R"(<title>the feeder's interlock holds the press (a synchronised axis )"
                       R"(behind by more than press.feeder_hold_lag_in), {:.3f} s to {:.3f} s)"
                       R"(</title></rect>)"
                       "\n",
                       x0, top + 2, std::max(1.0, frame_.tx(t1) - x0), bottom - top - 4,
                       kInterlockColour, kInterlockEdge, t0, t1);
    }
}

void LaneWriter::reader_60(double top, double bottom) {
    for (const auto& [t0, t1] : press_.waiting_cards(t_end_)) {
        fmt::format_to(out(svg_),
                       R"(<rect class="sync-card-wait" x="{:.1f}" y="{:.1f}" width="{:.1f}" )"
                       R"(height="5" fill="{}"><title>a sync card's orders wait in 17, )"
                       R"({:.3f} s to {:.3f} s</title></rect>)"
                       "\n",
                       frame_.tx(t0), bottom - 7, std::max(1.0, frame_.tx(t1) - frame_.tx(t0)),
                       kWaitColour, t0, t1);
    }
    double free_from = -1e9;
    for (const auto& [t0, t1] : press_.holds(t_end_)) {
        const double x0 = frame_.tx(t0);
        const double w = std::max(1.5, frame_.tx(t1) - x0);
        int angle = -1;
        for (const auto& c : press_.sync_cards()) {
            if (c.t <= t0 && c.order.position_sync) {
                angle = c.order.angle_deg;
            }
        }
        const std::string label = angle >= 0 ? fmt::format("R {}", angle) : std::string("hold");
        fmt::format_to(out(svg_),
                       R"(<rect class="hold-bar" x="{:.1f}" y="{:.1f}" width="{:.1f}" )"
                       R"(height="{:.1f}" fill="{}" stroke="{}" stroke-width="0.8">)"
                       R"(<title>reader 60 holds the card's motion ({}), {:.3f} s to {:.3f} s)"
                       R"(</title></rect>)"
                       "\n",
                       x0, top + 4, w, bottom - top - 14, kHoldColour, kHoldEdge, label, t0, t1);
        if (x0 >= free_from && x0 + 2 + 6.2 * static_cast<double>(label.size()) < kRight) {
            fmt::format_to(out(svg_),
                           R"(<text x="{:.1f}" y="{:.1f}" font-size="10" fill="{}">{}</text>)"
                           "\n",
                           x0 + 2, top + 15, plot::kTextColour, label);
            free_from = x0 + 8 + 6.2 * static_cast<double>(label.size());
        }
    }
}

void LaneWriter::processor_63(const Scale& ty) {
    for (cardreader::Axis a : cardreader::kAxes) {
        const auto series = press_.speed_63(a);
        if (max_of(series, 0) <= 0) {
            continue;
        }
        const std::string cls = fmt::format("speed-63 speed-63-{}", cardreader::axis_name(a));
        line(on_page(series, frame_.tx, ty, true), cls.c_str(),
             kAxisColours.at(cardreader::axis_index(a)), 1.4);
    }
}

void LaneWriter::lane(std::size_t index, const LaneSpec& spec, double top) {
    const double bottom = top + spec.height;
    std::optional<Scale> ty;
    plot::Ticks ticks;
    std::vector<Point> series;
    bool steps = true;
    double hi = 0;
    switch (spec.kind) {
    case LaneKind::crank_21:
        hi = 360;
        break;
    case LaneKind::die_20:
        series = press_.series(PressTrace::Series::die_20_in);
        steps = false;
        hi = max_of(series, 0.001);
        break;
    case LaneKind::register_14:
        series = press_.series(PressTrace::Series::register_14_pulses);
        steps = false; // a count a detector edge: at a pixel a column, a ramp
        hi = max_of(series, 1);
        break;
    case LaneKind::register_11:
        series = press_.series(PressTrace::Series::register_11_speed);
        hi = max_of(series, 1) * 1.1;
        break;
    case LaneKind::p63:
        for (cardreader::Axis a : cardreader::kAxes) {
            hi = std::max(hi, max_of(press_.speed_63(a), 0) * 1.1);
        }
        break;
    case LaneKind::reader_60:
        break;
    }
    if (spec.kind != LaneKind::reader_60) {
        ty = Scale{0, hi, bottom - 5, top + 5};
        ticks = spec.kind == LaneKind::crank_21 ? plot::Ticks{{0, 180, 360}, 0}
                                                : plot::nice_ticks(0, hi, 3);
    }
    fmt::format_to(out(svg_),
                   R"(<g class="press-lane" data-lane="{}">)"
                   "\n",
                   spec.id);
    frame(spec, top, bottom, ty, ticks);
    fmt::format_to(out(svg_),
                   R"~(<g clip-path="url(#press-clip-{})">)~"
                   "\n",
                   index);
    switch (spec.kind) {
    case LaneKind::crank_21:
        interlock(top, bottom);
        crank(*ty);
        break;
    case LaneKind::reader_60:
        reader_60(top, bottom);
        break;
    case LaneKind::p63:
        processor_63(*ty);
        break;
    default:
        line(on_page(series, frame_.tx, *ty, steps), spec.id, spec.colour, 1.4);
        break;
    }
    fmt::format_to(out(svg_), "</g>\n</g>\n");
}

} // namespace

double press_lanes_height(const PressTrace& press) {
    return lanes_height(heights_of(lanes_of(press)));
}

void press_clip_paths(std::string& svg, const PressTrace& press, double top) {
    lane_clip_paths(svg, "press", heights_of(lanes_of(press)), top);
}

void press_lanes(std::string& svg, const PressTrace& press, const LaneFrame& frame) {
    const auto lanes = lanes_of(press);
    const auto tops = lane_tops(heights_of(lanes), frame.top);
    LaneWriter writer(svg, press, frame);
    for (std::size_t i = 0; i < lanes.size(); ++i) {
        writer.lane(i, lanes[i], tops[i]);
    }
}

} // namespace parsons::cli
