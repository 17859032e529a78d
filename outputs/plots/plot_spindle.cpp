#include "outputs/plots/plot_spindle.hpp"

#include <array>

namespace parsons::cli {

using Point = SpindleTrace::Point;

namespace {

using S = SpindleTrace::Series;
using St = SpindleTrace::Steps;
using L = SpindleTrace::Line;

template <class E>
constexpr std::size_t at(E e) {
    return static_cast<std::size_t>(e);
}

} // namespace

// The signals of scope "spindle" the lanes draw, and what each becomes. Values in thousandths
// (the feed, the depth) and millionths (a ratio) are turned into the lane's unit. Encoder 32's
// phases, interface 33's counters, register 132, buffer 9 and the NC's step are not drawn.
std::optional<SpindleTrace::Role> SpindleTrace::role_of(std::string_view name) {
    struct Drawn {
        std::string_view name;
        Role role;
    };
    static constexpr std::array<Drawn, 23> kDrawn = {{
        {"motor_27.rpm", {Source::series, at(S::motor_27_rpm), 1}},
        {"tool_16.rpm", {Source::series, at(S::tool_16_rpm), 1}},
        {"interface_33.speed_stored", {Source::series, at(S::interface_33_edges), 1}},
        {"synchronous_control.feed", {Source::series, at(S::feed_in_per_min), 1e-3}},
        {"synchronous_control.depth_called", {Source::series, at(S::depth_called_in), 1e-3}},
        {"memory_12a.ratio", {Source::steps, at(St::ratio_12a), 1e-6}},
        {"head_31.tool", {Source::steps, at(St::head_31), 1}},
        {"synchronous_control.phase", {Source::steps, at(St::phase), 1}},
        {"bus35.tool_call", {Source::line, at(L::tool_call), 1}},
        {"bus35.transfer_request", {Source::line, at(L::transfer_request), 1}},
        {"bus35.nc_ready", {Source::line, at(L::nc_ready), 1}},
        {"bus35.data_valid", {Source::line, at(L::data_valid), 1}},
        {"bus35.nc_received", {Source::line, at(L::nc_received), 1}},
        {"bus35.tool_ready", {Source::line, at(L::tool_ready), 1}},
        {"pc130.cr1_tool_call", {Source::relay, 0, 1}},
        {"pc130.cr2_exchange", {Source::relay, 1, 1}},
        {"pc130.cr3_exchanged", {Source::relay, 2, 1}},
        {"pc130.cr4_head_on", {Source::relay, 3, 1}},
        {"pc130.cr5_ratio_change", {Source::relay, 4, 1}},
        {"pc130.cr6_request", {Source::relay, 5, 1}},
        {"pc130.cr7_transfer", {Source::relay, 6, 1}},
        {"pc130.cr8_done", {Source::relay, 7, 1}},
        {"bus35.data_ratio", {Source::data_ratio, 0, 1e-6}},
    }};
    for (const Drawn& d : kDrawn) {
        if (d.name == name) {
            return d.role;
        }
    }
    return std::nullopt;
}

// ---------------------------------------------------------------------------------------------
// Recording

std::optional<std::size_t> SpindleTrace::define(const relaylogic::SignalInfo& info,
                                                std::uint32_t initial) {
    if (info.scope != "spindle") {
        return std::nullopt;
    }
    defined_ = true;
    const auto role = role_of(info.name);
    if (!role) {
        return std::nullopt;
    }
    roles_.push_back(*role);
    const std::size_t slot = roles_.size() - 1;
    change(slot, 0, initial); // where it stands at the start
    return slot;
}

void SpindleTrace::change(std::size_t slot, double seconds, std::uint32_t new_value) {
    const Role role = roles_.at(slot);
    const Point p{seconds, static_cast<double>(new_value) * role.scale};
    switch (role.source) {
    case Source::series:
        series_.at(role.index).add(p);
        break;
    case Source::steps:
        steps_.at(role.index).push_back(p);
        break;
    case Source::line:
        lines_.at(role.index).push_back(p);
        break;
    case Source::relay:
        relays_.at(role.index).push_back(p);
        break;
    case Source::data_ratio:
        data_ratio_.push_back(p);
        break;
    }
}

void SpindleTrace::card(double seconds, const cardreader::CardOrders& orders) {
    if (orders.kind == cardreader::CardKind::tap) {
        taps_.push_back(TapMark{seconds, orders.number, orders.tap});
    }
}

void SpindleTrace::finish(double seconds) {
    for (Reduced& r : series_) {
        r.hold_to(seconds);
    }
}

// ---------------------------------------------------------------------------------------------
// Reading

std::vector<Point> SpindleTrace::series(Series s) const {
    return series_.at(at(s)).points();
}

const std::vector<Point>& SpindleTrace::steps(Steps s) const {
    return steps_.at(at(s));
}

const std::vector<Point>& SpindleTrace::line_steps(Line line) const {
    return lines_.at(at(line));
}

std::vector<SpindleTrace::Exchange> SpindleTrace::exchanges() const {
    std::vector<Exchange> out;
    const auto& head = steps_.at(at(St::head_31));
    for (std::size_t i = 1; i < head.size(); ++i) {
        if (head[i].x != head[i - 1].x) {
            out.push_back(Exchange{head[i].t, static_cast<int>(head[i].x)});
        }
    }
    return out;
}

std::vector<std::pair<double, double>> SpindleTrace::line_on(Line line, double t_end) const {
    return plot::on_intervals(lines_.at(at(line)), t_end);
}

std::vector<std::pair<double, double>> SpindleTrace::relay_on(std::size_t relay,
                                                              double t_end) const {
    return plot::on_intervals(relays_.at(relay), t_end);
}

double SpindleTrace::value_at(const std::vector<Point>& steps, double t) {
    double v = steps.empty() ? 0 : steps.front().x;
    for (const Point& s : steps) {
        if (s.t > t) {
            break;
        }
        v = s.x;
    }
    return v;
}

} // namespace parsons::cli
