// The run as a chart (--plot P.svg): for each of the five lead-screw axes, the real position of
// the part against machine time, the position of its speed switch 236 as a step line, where
// the switch stepped slower (a slow-down: absolute comparer 122' met a slow-down number and
// stepping relay 256 fired) and where it went to off (contact 238: the stop), and a thin line
// at every card the reader 134 fed.
//
// How we record it: a long deck moves the axes through millions of commutator impulses, far
// more points than 1100 pixels can show. Each axis keeps its samples in time buckets and only
// the first, lowest, highest and last sample of each bucket (the "M4" reduction: drawn at one
// bucket per pixel or two it is indistinguishable from every sample). When the buckets pass
// kMaxBuckets the bucket width doubles and neighbours merge, so memory stays under
// 4 * kMaxBuckets points per axis whatever the run's length, and the moments an axis starts
// and stops are never lost (they are a bucket's first, last or extreme point). Speed-switch
// steps, markers and cards are few (a handful per card) and are kept whole.
//
// A run with a press (press synchronisation, an addition after EP 0436887; parsons-extended)
// has lanes under the panels on the same time axis: crank 21, die 20, registers 14 and 11,
// reader 60's hold and processor 63's speeds, recorded from the "press" signals
// (plot_press.hpp). A run that read a tap card (spindle synchronisation, an addition after
// EP 0360190) has lanes under those: motor 27, tool 16, interface 33, memory 12a, the feed and
// depth the synchronous control calls, bus 35's handshake and PC 130's relays, recorded from the
// "spindle" signals (plot_spindle.hpp). A run without a press or a tap card draws exactly the
// chart it drew before them.
#pragma once

#include "outputs/plots/plot_press.hpp"
#include "outputs/plots/plot_spindle.hpp"
#include "relaylogic/machine_observer.hpp"

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace parsons::cli {

class PlotSvgRecorder : public relaylogic::MachineObserver {
public:
    static constexpr std::size_t kMaxBuckets = 1000;

    struct Point {
        double t = 0; // machine seconds
        double x = 0; // inches (real position) or a speed-switch position (0 off, 1..3)
    };

    // title: the chart's heading (e.g. the deck's file name); empty = a generic one.
    explicit PlotSvgRecorder(std::string title = {});

    void on_signal_defined(const relaylogic::SignalInfo& info, std::uint32_t initial) override;
    void on_signal(double seconds, relaylogic::SignalId id, std::uint32_t old_value,
                   std::uint32_t new_value) override;
    void on_motion(double seconds, const std::array<double, 5>& real_in) override;
    void on_card(double seconds, std::int64_t index, const cardreader::CardOrders& orders) override;
    void on_stop(double seconds, const relaylogic::StopInfo& stop) override;
    void on_condition(double seconds, const relaylogic::ConditionEvent& event) override;
    void on_finish(double seconds) override;

    // The chart: five panels stacked on one time axis, about 1100 px wide.
    std::string svg() const;

    // What will be drawn, for tests: the reduced position path (time order), the speed switch
    // (its initial position at t = 0, then every change), and the marker times.
    std::vector<Point> path(cardreader::Axis axis) const;
    const std::vector<Point>& speed_steps(cardreader::Axis axis) const;
    const std::vector<double>& slow_down_times(cardreader::Axis axis) const;
    const std::vector<double>& stop_times(cardreader::Axis axis) const;
    // Where a condition card's condition was met on this axis (an addition): time and label.
    struct Trip {
        double t = 0;
        std::string label; // "event 7: lamp 3"
    };
    const std::vector<Trip>& trips(cardreader::Axis axis) const;
    // The press lanes' record (present() is false in a run without a press).
    const PressTrace& press() const { return press_; }
    // The spindle lanes' record (present() is false in a run without a tap card).
    const SpindleTrace& spindle() const { return spindle_; }

private:
    struct Bucket {
        std::int64_t slot = 0;
        Point first, low, high, last;
    };
    struct AxisTrace {
        std::vector<Bucket> buckets;
        std::optional<Point> latest;
        std::vector<Point> speed; // (t, switch position)
        std::vector<Point> motor; // (t, 1 running / 0 off)
        int speed_position = 0;
        bool motor_on = false;
        std::string motor_name; // "motor 38"
        std::vector<double> slow_downs;
        std::vector<double> stops;
        std::vector<Trip> trips;
    };
    struct CardMark {
        double t = 0;
        std::int64_t index = 0;
        int number = 0;
    };
    enum class Role : std::uint8_t { none, speed_switch, motor, press, spindle };
    struct SignalRole {
        Role role = Role::none;
        std::size_t axis = 0; // or, for Role::press and spindle, the trace's slot
    };

    void add_sample(AxisTrace& a, Point p);
    void widen_buckets();
    double end_time() const;

    std::string title_;
    std::array<AxisTrace, cardreader::kAxisCount> axes_{};
    std::vector<SignalRole> roles_;
    std::vector<CardMark> cards_;
    PressTrace press_;
    SpindleTrace spindle_;
    std::optional<relaylogic::StopInfo> stop_;
    double stop_t_ = 0;
    double bucket_s_ = 1.0 / 64;
    bool any_motion_ = false;
    double last_t_ = 0;
};

} // namespace parsons::cli
