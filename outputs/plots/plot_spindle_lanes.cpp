// The spindle lanes of run --plot (plot_spindle_lanes.hpp):
//
//   ... tilt panel (and the press's lanes) ...
//   motor 27  its speed (EP 0360190)
//   +--------------------------------------------+ rev/min    __        run-up, the tap's S,
//   |      /----\__         /--\__               |           /  \__     run-down and back
//   +--------------------------------------------+
//   tool 16 ... interface 33 ... memory 12a (T2 v at each exchange) ... feed ... depth called
//   bus 35   tool call  [=========================]                      a bar a line while it
//            request        [=]                                          stands, in the seed's
//            ...            ...                                          order (Fig. 4)
//   PC 130   CR1 ... CR8                                                 a bar a picked relay
//   0     100     200 ...  machine time (s)
#include "outputs/plots/plot_spindle_lanes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <iterator>
#include <optional>
#include <string_view>

namespace parsons::cli {

using plot::kLeft;
using plot::kRight;
using plot::Scale;
using Point = SpindleTrace::Point;
using Line = SpindleTrace::Line;

namespace {

using lanes::kLaneHeight;
using namespace spindle_colours;

constexpr double kRowHeight = 10; // a bar lane's row
constexpr double kBarLanePad = 6; // above and below a bar lane's rows

enum class LaneKind : std::uint8_t {
    motor_27,
    tool_16,
    interface_33,
    memory_12a,
    feed,
    depth,
    bus_35,
    pc_130
};

struct LaneSpec {
    LaneKind kind;
    const char* id;     // data-lane
    const char* name;   // bold title
    const char* what;   // grey title
    const char* unit;   // right of the frame
    const char* colour; // line and scale
    double height;
};

// A row of a bar lane: a bus 35 line or a relay of PC 130.
struct Row {
    const char* id;    // data-line / data-relay
    const char* label; // left of the frame
    const char* title; // the bar's tooltip, before its times
    const char* colour;
};

constexpr std::array<Row, SpindleTrace::kLines> kBusRows = {{
    {"tool_call", "tool call", "bus 35: the NC calls tool", kNcColour},
    {"transfer_request", "request", "bus 35: PC 130's transfer request (S4)", kPcColour},
    {"nc_ready", "NC ready", "bus 35: the NC's preparation completion (S13)", kNcColour},
    {"data_valid", "data valid", "bus 35: PC 130's ratio on the data lines (S6)", kPcColour},
    {"nc_received", "received", "bus 35: the NC's reception completion (S15)", kNcColour},
    {"tool_ready", "tool ready", "bus 35: PC 130's tool ready (CR8)", kPcColour},
}};

constexpr std::array<Row, SpindleTrace::kRelays> kRelayRows = {{
    {"cr1_tool_call", "CR1", "PC 130 CR1 (S1): the tool call latched", kRelayColour},
    {"cr2_exchange", "CR2", "PC 130 CR2 (S1): head exchange timer running", kRelayColour},
    {"cr3_exchanged", "CR3", "PC 130 CR3 (S1): this call's exchange done", kRelayColour},
    {"cr4_head_on", "CR4", "PC 130 CR4: the called head on the spindle", kRelayColour},
    {"cr5_ratio_change", "CR5", "PC 130 CR5 (S2, S3): the ratio must change", kRelayColour},
    {"cr6_request", "CR6", "PC 130 CR6 (S4, S5): transfer request", kRelayColour},
    {"cr7_transfer", "CR7", "PC 130 CR7 (S6-S8): the ratio on the data lines", kRelayColour},
    {"cr8_done", "CR8", "PC 130 CR8: sequence done, tool ready", kRelayColour},
}};

double bar_lane_height(std::size_t rows) {
    return static_cast<double>(rows) * kRowHeight + 2 * kBarLanePad;
}

std::vector<LaneSpec> lanes_of(const SpindleTrace& spindle) {
    if (!spindle.present()) {
        return {};
    }
    return {
        {LaneKind::motor_27, "motor_27", "motor 27",
         "spindle motor, EP 0360190: its speed (reverse shown as its size)", "rev/min",
         kMotorColour, kLaneHeight},
        {LaneKind::tool_16, "tool_16", "tool 16",
         "the tool's speed on head 31: motor 27's times the head's gear ratio", "rev/min",
         kToolColour, kLaneHeight},
        {LaneKind::interface_33, "interface_33", "encoder interface 33",
         "encoder 32's edges in the last sample: the speed S the NC reads", "edges",
         kInterfaceColour, kLaneHeight},
        {LaneKind::memory_12a, "memory_12a", "gear ratio memory 12a",
         "the ratio A the NC computes with (S x A); above it the head on the spindle, marked "
         "at each exchange",
         "ratio", kRatioColour, kLaneHeight},
        {LaneKind::feed, "synchronous_feed", "synchronous control",
         "the feed it commands the follower drive", "in/min", kFeedColour, kLaneHeight},
        {LaneKind::depth, "depth_called", "depth called",
         "what the tool's turns call for (S x A x pitch summed); the band: its phase", "in",
         kDepthColour, kLaneHeight},
        {LaneKind::bus_35, "bus_35", "bus 35",
         "the handshake of Fig. 4: a bar while a line stands (blue: the NC's, red: PC 130's)", "",
         kNcColour, bar_lane_height(kBusRows.size())},
        {LaneKind::pc_130, "pc_130", "programmable controller 130",
         "a bar while a relay of its ladder is picked", "", kRelayColour,
         bar_lane_height(kRelayRows.size())},
    };
}

std::back_insert_iterator<std::string> out(std::string& svg) {
    return std::back_inserter(svg);
}

class LaneWriter {
public:
    LaneWriter(std::string& svg, const SpindleTrace& spindle, const LaneFrame& frame)
        : svg_(svg), spindle_(spindle), frame_(frame), t_end_(frame.tx.d1) {}

    void lane(std::size_t index, const LaneSpec& spec, double top);

private:
    void memory_12a(const Scale& ty, double top);
    void phase_band(double bottom);
    void row_labels(double top, const Row* rows, std::size_t n);
    void bars(double top, const Row& row, std::size_t index,
              const std::vector<std::pair<double, double>>& on, const char* cls, const char* data);
    static double row_y(double top, std::size_t i) {
        return top + kBarLanePad + static_cast<double>(i) * kRowHeight;
    }

    std::string& svg_;
    const SpindleTrace& spindle_;
    const LaneFrame& frame_;
    double t_end_;
};

// The ratio as steps, and over it, at each exchange, a mark and the tool the new head holds.
void LaneWriter::memory_12a(const Scale& ty, double top) {
    const auto& ratio = spindle_.steps(SpindleTrace::Steps::ratio_12a);
    lane_path(svg_, on_page(ratio, frame_.tx, ty, true), "ratio-12a", kRatioColour, 1.6);
    // Its value under the line, where it starts and wherever it changes.
    double ratio_free_from = -1e9;
    for (std::size_t i = 0; i < ratio.size(); ++i) {
        if (i > 0 && ratio[i].x == ratio[i - 1].x) {
            continue;
        }
        const double x = std::max(kLeft + 3, frame_.tx(ratio[i].t) + 3);
        if (x >= ratio_free_from && x + 40 < kRight) {
            fmt::format_to(out(svg_),
                           R"(<text class="ratio-label" x="{:.1f}" y="{:.1f}" font-size="10" )"
                           R"(fill="{}">{:.4f}</text>)"
                           "\n",
                           x, ty(ratio[i].x) + 11, kRatioColour, ratio[i].x);
            ratio_free_from = x + 44;
        }
    }
    const auto& head = spindle_.steps(SpindleTrace::Steps::head_31);
    double free_from = -1e9;
    auto label = [&](double x, int tool) {
        const std::string text = fmt::format("T{}", tool);
        if (x >= free_from && x + 2 + 6.2 * static_cast<double>(text.size()) < kRight) {
            fmt::format_to(out(svg_),
                           R"(<text class="head-label" x="{:.1f}" y="{:.1f}" font-size="10" )"
                           R"(fill="{}">{}</text>)"
                           "\n",
                           x, top + 12, kExchangeColour, text);
            free_from = x + 6 + 6.2 * static_cast<double>(text.size());
        }
    };
    if (!head.empty()) {
        label(kLeft + 3, static_cast<int>(head.front().x));
    }
    for (const auto& e : spindle_.exchanges()) {
        const double x = frame_.tx(e.t);
        fmt::format_to(out(svg_),
                       R"(<path class="exchange-marker" d="M{:.1f},{:.1f} l5,9 h-10 z" )"
                       R"(fill="{}" stroke="white" stroke-width="0.8">)"
                       R"(<title>head 31 with tool {} on the spindle at {:.3f} s; 12a then )"
                       R"(holds {:.6f}</title></path>)"
                       "\n",
                       x, top + 1, kExchangeColour, e.tool, e.t,
                       SpindleTrace::value_at(spindle_.steps(SpindleTrace::Steps::ratio_12a), e.t));
        label(x + 6, e.tool);
    }
}

// The synchronous control's phase as a band along the bottom of the depth lane.
void LaneWriter::phase_band(double bottom) {
    const auto& phase = spindle_.steps(SpindleTrace::Steps::phase);
    for (std::size_t i = 0; i < phase.size(); ++i) {
        const auto p = static_cast<std::size_t>(phase[i].x);
        if (p == 0 || p >= kPhaseColours.size()) {
            continue;
        }
        const double t0 = phase[i].t;
        const double t1 = i + 1 < phase.size() ? phase[i + 1].t : t_end_;
        if (t1 <= t0) {
            continue; // left at the same instant
        }
        fmt::format_to(out(svg_),
                       R"(<rect class="phase-band" data-phase="{}" x="{:.1f}" y="{:.1f}" )"
                       R"(width="{:.1f}" height="5" fill="{}"><title>synchronous control: {}, )"
                       R"({:.3f} s to {:.3f} s</title></rect>)"
                       "\n",
                       p, frame_.tx(t0), bottom - 7, std::max(1.0, frame_.tx(t1) - frame_.tx(t0)),
                       kPhaseColours.at(p), kPhaseNames.at(p), t0, t1);
    }
}

// The rows' labels left of a bar lane's frame (outside its clip path).
void LaneWriter::row_labels(double top, const Row* rows, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) {
        fmt::format_to(out(svg_),
                       R"(<text x="{:.1f}" y="{:.1f}" font-size="9" text-anchor="end" )"
                       R"(fill="{}">{}</text>)"
                       "\n",
                       kLeft - 5, row_y(top, i) + 7.5, rows[i].colour, rows[i].label);
    }
}

// One row of a bar lane: a bar for each interval its line stood or its relay was picked.
void LaneWriter::bars(double top, const Row& row, std::size_t index,
                      const std::vector<std::pair<double, double>>& on, const char* cls,
                      const char* data) {
    const std::string_view id = row.id;
    for (const auto& [t0, t1] : on) {
        std::string what = row.title;
        if (id == "tool_call") {
            what += fmt::format(" {}", static_cast<int>(SpindleTrace::value_at(
                                           spindle_.line_steps(Line::tool_call), t0)));
        } else if (id == "data_valid") {
            what += fmt::format(": {:.6f}", SpindleTrace::value_at(spindle_.data_ratio(), t0));
        }
        fmt::format_to(out(svg_),
                       R"(<rect class="{}" {}="{}" x="{:.1f}" y="{:.1f}" width="{:.1f}" )"
                       R"(height="{:.1f}" fill="{}" stroke="{}" stroke-width="0.5">)"
                       R"(<title>{}, {:.3f} s to {:.3f} s</title></rect>)"
                       "\n",
                       cls, data, id, frame_.tx(t0), row_y(top, index) + 1,
                       std::max(1.5, frame_.tx(t1) - frame_.tx(t0)), kRowHeight - 2, row.colour,
                       kBarEdge, what, t0, t1);
    }
}

void LaneWriter::lane(std::size_t index, const LaneSpec& spec, double top) {
    using S = SpindleTrace::Series;
    const double bottom = top + spec.height;
    std::optional<Scale> ty;
    plot::Ticks ticks;
    std::vector<Point> series;
    switch (spec.kind) {
    case LaneKind::motor_27:
        series = spindle_.series(S::motor_27_rpm);
        break;
    case LaneKind::tool_16:
        series = spindle_.series(S::tool_16_rpm);
        break;
    case LaneKind::interface_33:
        series = spindle_.series(S::interface_33_edges);
        break;
    case LaneKind::memory_12a:
        series = spindle_.steps(SpindleTrace::Steps::ratio_12a);
        break;
    case LaneKind::feed:
        series = spindle_.series(S::feed_in_per_min);
        break;
    case LaneKind::depth:
        series = spindle_.series(S::depth_called_in);
        break;
    case LaneKind::bus_35:
    case LaneKind::pc_130:
        break;
    }
    const bool with_scale = spec.kind != LaneKind::bus_35 && spec.kind != LaneKind::pc_130;
    if (with_scale) {
        const double hi = max_of(series, 0.001) * 1.1;
        // The ratio's lane leaves room above its line for the head's labels.
        const double room = spec.kind == LaneKind::memory_12a ? 16 : 5;
        ty = Scale{0, hi, bottom - 5, top + room};
        ticks = plot::nice_ticks(0, hi, 3);
    }
    fmt::format_to(out(svg_),
                   R"(<g class="spindle-lane" data-lane="{}">)"
                   "\n",
                   spec.id);
    lane_frame(svg_, frame_, LaneTitle{spec.name, spec.what, spec.unit, spec.colour}, top, bottom,
               ty, ticks);
    if (spec.kind == LaneKind::bus_35) {
        row_labels(top, kBusRows.data(), kBusRows.size());
    } else if (spec.kind == LaneKind::pc_130) {
        row_labels(top, kRelayRows.data(), kRelayRows.size());
    }
    fmt::format_to(out(svg_),
                   R"~(<g clip-path="url(#spindle-clip-{})">)~"
                   "\n",
                   index);
    switch (spec.kind) {
    case LaneKind::memory_12a:
        memory_12a(*ty, top);
        break;
    case LaneKind::depth:
        phase_band(bottom);
        lane_path(svg_, on_page(series, frame_.tx, *ty, true), spec.id, spec.colour, 1.4);
        break;
    case LaneKind::bus_35:
        for (std::size_t i = 0; i < kBusRows.size(); ++i) {
            bars(top, kBusRows.at(i), i, spindle_.line_on(static_cast<Line>(i), t_end_),
                 "bus35-bar", "data-line");
        }
        break;
    case LaneKind::pc_130:
        for (std::size_t i = 0; i < kRelayRows.size(); ++i) {
            bars(top, kRelayRows.at(i), i, spindle_.relay_on(i, t_end_), "pc130-bar", "data-relay");
        }
        break;
    default:
        lane_path(svg_, on_page(series, frame_.tx, *ty, true), spec.id, spec.colour, 1.4);
        break;
    }
    fmt::format_to(out(svg_), "</g>\n</g>\n");
}

} // namespace

double spindle_lanes_height(const SpindleTrace& spindle) {
    return lanes_height(heights_of(lanes_of(spindle)));
}

void spindle_clip_paths(std::string& svg, const SpindleTrace& spindle, double top) {
    lane_clip_paths(svg, "spindle", heights_of(lanes_of(spindle)), top);
}

void spindle_lanes(std::string& svg, const SpindleTrace& spindle, const LaneFrame& frame) {
    const auto lanes = lanes_of(spindle);
    const auto tops = lane_tops(heights_of(lanes), frame.top);
    LaneWriter writer(svg, spindle, frame);
    for (std::size_t i = 0; i < lanes.size(); ++i) {
        writer.lane(i, lanes[i], tops[i]);
    }
}

} // namespace parsons::cli
