#include "outputs/plots/plot_svg.hpp"

#include "cardreader/card_svg.hpp"
#include "outputs/plots/plot_reduce.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace parsons::cli {

using cardreader::Axis;
using relaylogic::SignalId;
using Point = PlotSvgRecorder::Point;

// ---------------------------------------------------------------------------------------------
// Recording

PlotSvgRecorder::PlotSvgRecorder(std::string title) : title_(std::move(title)) {}

void PlotSvgRecorder::on_signal_defined(const relaylogic::SignalInfo& info, std::uint32_t initial) {
    if (roles_.size() <= info.id) {
        roles_.resize(info.id + std::size_t{1});
    }
    if (const auto slot = press_.define(info, initial)) {
        roles_.at(info.id) = {Role::press, *slot};
        return;
    }
    if (const auto slot = spindle_.define(info, initial)) {
        roles_.at(info.id) = {Role::spindle, *slot};
        return;
    }
    const auto axis = cardreader::axis_named(info.scope);
    if (!axis) {
        return;
    }
    const std::size_t i = cardreader::axis_index(*axis);
    AxisTrace& a = axes_.at(i);
    if (info.name == "speed_switch_236") {
        roles_.at(info.id) = {Role::speed_switch, i};
        a.speed_position = static_cast<int>(initial);
        a.speed.assign(1, Point{0, static_cast<double>(initial)});
    } else if (info.name.rfind("motor_", 0) == 0) {
        roles_.at(info.id) = {Role::motor, i};
        a.motor_on = initial != 0;
        a.motor.assign(1, Point{0, a.motor_on ? 1.0 : 0.0});
        a.motor_name = "motor " + info.name.substr(6);
    }
}

void PlotSvgRecorder::on_signal(double seconds, SignalId id, std::uint32_t old_value,
                                std::uint32_t new_value) {
    if (id >= roles_.size() || roles_[id].role == Role::none) {
        return;
    }
    last_t_ = std::max(last_t_, seconds);
    if (roles_[id].role == Role::press) {
        press_.change(roles_[id].axis, seconds, old_value, new_value);
        return;
    }
    if (roles_[id].role == Role::spindle) {
        spindle_.change(roles_[id].axis, seconds, new_value);
        return;
    }
    AxisTrace& a = axes_.at(roles_[id].axis);
    if (roles_[id].role == Role::motor) {
        a.motor_on = new_value != 0;
        a.motor.push_back(Point{seconds, a.motor_on ? 1.0 : 0.0});
        return;
    }
    const int from = a.speed_position;
    const int to = static_cast<int>(new_value);
    if (a.motor_on && from >= 1 && from <= 3) {
        if (to == 0) {
            a.stops.push_back(seconds); // contact 238: the stop
        } else if (to == from + 1) {
            a.slow_downs.push_back(seconds); // stepping relay 256: one speed slower
        }
    }
    a.speed_position = to;
    a.speed.push_back(Point{seconds, static_cast<double>(to)});
}

void PlotSvgRecorder::add_sample(AxisTrace& a, Point p) {
    a.latest = p;
    plot::add_to_buckets(a.buckets, p, bucket_s_);
}

void PlotSvgRecorder::widen_buckets() {
    bucket_s_ *= 2;
    for (AxisTrace& a : axes_) {
        a.buckets = plot::widened(a.buckets, bucket_s_);
    }
}

void PlotSvgRecorder::on_motion(double seconds, const std::array<double, 5>& real_in) {
    for (std::size_t i = 0; i < axes_.size(); ++i) {
        if (!any_motion_ && seconds > 0) {
            // Where the axes stood from the start: the first report moved one axis by at most
            // one impulse (0.001 in).
            add_sample(axes_[i], Point{0, real_in[i]});
        }
        add_sample(axes_[i], Point{seconds, real_in[i]});
    }
    any_motion_ = true;
    last_t_ = std::max(last_t_, seconds);
    if (axes_[0].buckets.size() > kMaxBuckets) {
        widen_buckets();
    }
}

void PlotSvgRecorder::on_card(double seconds, std::int64_t index,
                              const cardreader::CardOrders& orders) {
    cards_.push_back(CardMark{seconds, index, orders.number});
    press_.card(seconds, orders);
    spindle_.card(seconds, orders);
    last_t_ = std::max(last_t_, seconds);
}

void PlotSvgRecorder::on_stop(double seconds, const relaylogic::StopInfo& stop) {
    stop_ = stop;
    stop_t_ = seconds;
    last_t_ = std::max(last_t_, seconds);
}

void PlotSvgRecorder::on_finish(double seconds) {
    last_t_ = std::max(last_t_, seconds);
    press_.finish(seconds);
    spindle_.finish(seconds);
    for (AxisTrace& a : axes_) {
        if (a.latest && seconds > a.latest->t) {
            add_sample(a, Point{seconds, a.latest->x}); // at rest to the end
        }
    }
}

double PlotSvgRecorder::end_time() const {
    return last_t_;
}

std::vector<PlotSvgRecorder::Point> PlotSvgRecorder::path(Axis axis) const {
    return plot::bucket_points<Point>(axes_.at(cardreader::axis_index(axis)).buckets);
}

const std::vector<PlotSvgRecorder::Point>& PlotSvgRecorder::speed_steps(Axis axis) const {
    return axes_.at(cardreader::axis_index(axis)).speed;
}

const std::vector<double>& PlotSvgRecorder::slow_down_times(Axis axis) const {
    return axes_.at(cardreader::axis_index(axis)).slow_downs;
}

void PlotSvgRecorder::on_condition(double seconds, const relaylogic::ConditionEvent& e) {
    if (e.kind != relaylogic::ConditionEventKind::met) {
        return;
    }
    last_t_ = std::max(last_t_, seconds);
    axes_.at(cardreader::axis_index(e.axis))
        .trips.push_back(Trip{seconds, fmt::format("event {}: {} at {}", e.event,
                                                   cardreader::action_text(e.action, e.parameter),
                                                   cardreader::format_inches(e.position))});
}

const std::vector<PlotSvgRecorder::Trip>& PlotSvgRecorder::trips(cardreader::Axis axis) const {
    return axes_.at(cardreader::axis_index(axis)).trips;
}

const std::vector<double>& PlotSvgRecorder::stop_times(Axis axis) const {
    return axes_.at(cardreader::axis_index(axis)).stops;
}

} // namespace parsons::cli
