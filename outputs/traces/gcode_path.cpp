// The machine's path as G-code (outputs/traces/gcode_path.hpp; docs/gcode.md).
#include "outputs/traces/gcode_path.hpp"

#include <fmt/format.h>
#include <fmt/ostream.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <utility>

namespace parsons::cli {
namespace {

double distance_to_segment(const std::array<double, 3>& x, const std::array<double, 3>& p,
                           const std::array<double, 3>& q) {
    std::array<double, 3> d{};
    double len2 = 0;
    double dot = 0;
    for (std::size_t k = 0; k < 3; ++k) {
        d.at(k) = q.at(k) - p.at(k);
        len2 += d.at(k) * d.at(k);
        dot += (x.at(k) - p.at(k)) * d.at(k);
    }
    const double t = len2 == 0 ? 0 : std::clamp(dot / len2, 0.0, 1.0);
    double e2 = 0;
    for (std::size_t k = 0; k < 3; ++k) {
        const double e = x.at(k) - (p.at(k) + t * d.at(k));
        e2 += e * e;
    }
    return std::sqrt(e2);
}

} // namespace

GcodePathWriter::GcodePathWriter(std::ostream& out, std::string deck)
    : out_(out), deck_(std::move(deck)) {}

GcodePathWriter::~GcodePathWriter() = default;

void GcodePathWriter::on_signal_defined(const relaylogic::SignalInfo& info, std::uint32_t) {
    if (info.name == "speed_switch_236") {
        speed_switches_.push_back(info.id);
    }
    static const std::array<std::string_view, 5> axes = {"table", "cross", "vertical", "swivel",
                                                         "tilt"};
    if (info.name.rfind("motor_", 0) == 0 &&
        std::find(axes.begin(), axes.end(), info.scope) != axes.end()) {
        motors_.push_back(info.id);
    }
}

void GcodePathWriter::on_start() {
    fmt::print(out_, "(parsons: {} as the emulated machine moved it)\n",
               deck_.empty() ? "the deck" : deck_);
    fmt::print(out_, "(X table, Y cross slide, Z vertical slide: where the parts really were, "
                     "inches from the reference zero where the counters read 0.000)\n");
    fmt::print(out_, "(F: the speed along each line, inches a minute, as speed switches 236 set "
                     "it with the run-up and coast)\n");
    out_ << "G20 G90 G17 G94\n";
    piece_.assign(1, Point{0, {0, 0, 0}});
}

void GcodePathWriter::on_signal(double seconds, relaylogic::SignalId id, std::uint32_t,
                                std::uint32_t new_value) {
    if (std::find(speed_switches_.begin(), speed_switches_.end(), id) != speed_switches_.end()) {
        flush_piece();
    } else if (new_value != 0 && piece_.size() == 1 &&
               std::find(motors_.begin(), motors_.end(), id) != motors_.end()) {
        // A motor starts from rest: the line that follows begins now, not when the part last
        // stopped (the card was read, the shaft stepped in between).
        piece_.front().t = seconds;
    }
}

void GcodePathWriter::on_motion(double seconds, const std::array<double, 5>& real_in) {
    const Point p{seconds, {real_in[0], real_in[1], real_in[2]}};
    if (!piece_.empty() && piece_.back().at == p.at) {
        return;
    }
    piece_.push_back(p);
    fixture_ = {real_in[3], real_in[4]};
}

void GcodePathWriter::on_card(double, std::int64_t index, const cardreader::CardOrders& orders) {
    flush_piece();
    pending_ += fmt::format("(card {}, number {:04}", index, orders.number);
    if (fixture_[0] != 0 || fixture_[1] != 0) {
        pending_ += fmt::format("; fixture screws: swivel {:.5f} in, tilt {:.5f} in", fixture_[0],
                                fixture_[1]);
    }
    pending_ += ")\n";
}

void GcodePathWriter::on_stop(double seconds, const relaylogic::StopInfo& stop) {
    std::string message = stop.message;
    std::replace(message.begin(), message.end(), '(', '[');
    std::replace(message.begin(), message.end(), ')', ']');
    stop_ = fmt::format("(machine stop at {:.3f} s: {})\n", seconds, message);
}

void GcodePathWriter::on_finish(double seconds) {
    if (finished_) {
        return;
    }
    finished_ = true;
    flush_piece();
    out_ << pending_;
    pending_.clear();
    if (stop_.empty()) {
        fmt::print(out_, "(completed at {:.3f} s of machine time)\n", seconds);
        out_ << "M2\n";
    } else {
        // Cut short: said so, and no M2, so that no controller takes it for a whole program.
        out_ << stop_
             << "(INCOMPLETE: the path ends at the machine stop above; the deck was not run "
                "through, so this program has no M2)\n";
    }
    out_.flush();
}

void GcodePathWriter::flush_piece() {
    if (piece_.size() < 2) {
        return;
    }
    // Douglas-Peucker, without recursion: keep[i] marks the points written.
    std::vector<char> keep(piece_.size(), 0);
    keep.front() = 1;
    keep.back() = 1;
    std::vector<std::pair<std::size_t, std::size_t>> spans{{0, piece_.size() - 1}};
    while (!spans.empty()) {
        const auto [a, b] = spans.back();
        spans.pop_back();
        double worst = -1;
        std::size_t at = a;
        for (std::size_t i = a + 1; i < b; ++i) {
            const double d = distance_to_segment(piece_[i].at, piece_[a].at, piece_[b].at);
            if (d > worst) {
                worst = d;
                at = i;
            }
        }
        if (worst > kGcodePathToleranceIn) {
            keep[at] = 1;
            spans.emplace_back(a, at);
            spans.emplace_back(at, b);
        }
    }
    std::size_t last = 0;
    for (std::size_t i = 1; i < piece_.size(); ++i) {
        if (keep[i] != 0) {
            write_move(piece_[last], piece_[i]);
            last = i;
        }
    }
    const Point end = piece_.back();
    piece_.assign(1, end);
}

void GcodePathWriter::write_move(const Point& from, const Point& to) {
    out_ << pending_;
    pending_.clear();
    double len2 = 0;
    for (std::size_t k = 0; k < 3; ++k) {
        len2 += (to.at.at(k) - from.at.at(k)) * (to.at.at(k) - from.at.at(k));
    }
    const double seconds = to.t - from.t;
    const double feed = seconds > 0 ? std::sqrt(len2) / seconds * 60 : 0;
    // A value that rounds to zero is written 0.00000, never -0.00000.
    auto coordinate = [](double v) { return std::abs(v) < 5e-6 ? 0.0 : v; };
    fmt::print(out_, "G1 X{:.5f} Y{:.5f} Z{:.5f}", coordinate(to.at[0]), coordinate(to.at[1]),
               coordinate(to.at[2]));
    if (feed > 0) {
        fmt::print(out_, " F{:.3f}", feed);
    }
    out_ << '\n';
    ++moves_;
}

} // namespace parsons::cli
