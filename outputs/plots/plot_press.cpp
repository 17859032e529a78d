#include "outputs/plots/plot_press.hpp"

#include "outputs/plots/plot_reduce.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace parsons::cli {

using Point = PressTrace::Point;

// ---------------------------------------------------------------------------------------------
// Recording

std::optional<std::size_t> PressTrace::define(const relaylogic::SignalInfo& info,
                                              std::uint32_t initial) {
    if (info.scope != "press") {
        return std::nullopt;
    }
    present_ = true;
    std::optional<Role> role;
    const auto v = static_cast<double>(initial);
    if (info.name == "crank_21.angle") {
        role = Role{Source::crank_21}; // from its first change (the note in the header)
    } else if (info.name == "die_20.height") {
        role = Role{Source::die_20};
    } else if (info.name == "position_register_14") {
        role = Role{Source::register_14};
        series_.at(static_cast<std::size_t>(Series::register_14_pulses)).add(Point{0, v});
    } else if (info.name == "speed_register_11.speed") {
        role = Role{Source::register_11};
        series_.at(static_cast<std::size_t>(Series::register_11_speed)).add(Point{0, v / 100});
    } else if (info.name == "position_reader_60.hold") {
        role = Role{Source::hold_60};
        hold_.assign(1, Point{0, initial != 0 ? 1.0 : 0.0});
    } else if (info.name == "synchronisation_processor_17.sync_card") {
        role = Role{Source::card_17};
        cards_.assign(1, Point{0, initial != 0 ? 1.0 : 0.0});
    } else if (info.name == "feeder_interlock.hold") {
        role = Role{Source::interlock};
        interlock_.assign(1, Point{0, initial != 0 ? 1.0 : 0.0});
    } else if (info.name == "sync_position_detector_61") {
        role = Role{Source::detector_61};
    } else if (info.name.rfind("processor_63.", 0) == 0) {
        const auto axis = cardreader::axis_named(info.name.substr(13));
        if (axis) {
            const std::size_t i = cardreader::axis_index(*axis);
            role = Role{Source::processor_63, i};
            speed_.at(i).add(Point{0, v / 1000});
            any_speed_ = any_speed_ || initial != 0;
        }
    }
    if (!role) {
        return std::nullopt;
    }
    roles_.push_back(*role);
    return roles_.size() - 1;
}

void PressTrace::change(std::size_t slot, double seconds, std::uint32_t old_value,
                        std::uint32_t new_value) {
    const Role role = roles_.at(slot);
    const auto v = static_cast<double>(new_value);
    switch (role.source) {
    case Source::crank_21:
        // Tenths of a degree, 0..3599: a step of more than half a turn between two edges is
        // the crank passing top dead centre.
        if (crank_shown_ &&
            (old_value > new_value ? old_value - new_value : new_value - old_value) > 1800U) {
            top_dead_centres_.push_back(seconds);
        }
        crank_shown_ = true;
        series_.at(static_cast<std::size_t>(Series::crank_21_deg)).add(Point{seconds, v / 10});
        break;
    case Source::die_20:
        series_.at(static_cast<std::size_t>(Series::die_20_in)).add(Point{seconds, v / 1000});
        break;
    case Source::register_14:
        series_.at(static_cast<std::size_t>(Series::register_14_pulses)).add(Point{seconds, v});
        break;
    case Source::register_11:
        series_.at(static_cast<std::size_t>(Series::register_11_speed))
            .add(Point{seconds, v / 100});
        break;
    case Source::hold_60:
        hold_.push_back(Point{seconds, new_value != 0 ? 1.0 : 0.0});
        break;
    case Source::card_17:
        cards_.push_back(Point{seconds, new_value != 0 ? 1.0 : 0.0});
        break;
    case Source::interlock:
        interlock_.push_back(Point{seconds, new_value != 0 ? 1.0 : 0.0});
        break;
    case Source::detector_61:
        if (new_value != 0) {
            releases_.push_back(seconds);
        }
        break;
    case Source::processor_63:
        speed_.at(role.axis).add(Point{seconds, v / 1000}); // thousandths of in/min
        any_speed_ = any_speed_ || new_value != 0;
        break;
    }
}

void PressTrace::card(double seconds, const cardreader::CardOrders& orders) {
    if (orders.kind == cardreader::CardKind::sync) {
        sync_cards_.push_back(SyncMark{seconds, orders.number, orders.sync});
    }
}

void PressTrace::finish(double seconds) {
    for (Reduced& r : series_) {
        r.hold_to(seconds);
    }
    for (Reduced& r : speed_) {
        r.hold_to(seconds);
    }
}

std::vector<Point> PressTrace::series(Series s) const {
    return series_.at(static_cast<std::size_t>(s)).points();
}

std::vector<Point> PressTrace::speed_63(cardreader::Axis axis) const {
    return speed_.at(cardreader::axis_index(axis)).points();
}

std::vector<std::pair<double, double>> PressTrace::holds(double t_end) const {
    return plot::on_intervals(hold_, t_end);
}

std::vector<std::pair<double, double>> PressTrace::interlock_holds(double t_end) const {
    return plot::on_intervals(interlock_, t_end);
}

std::vector<std::pair<double, double>> PressTrace::waiting_cards(double t_end) const {
    return plot::on_intervals(cards_, t_end);
}

} // namespace parsons::cli
