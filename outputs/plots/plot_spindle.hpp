// The spindle on the chart of run --plot: spindle synchronisation is an addition after EP 0360190
// (Mitsubishi), present in a profile with spindle_sync (parsons-extended), and drawn
// only in a run that read a tap card. What the seed's Figs. 1 and 3 wire together — spindle
// motor 27 with encoder 32, gear unit 30 and the head 31 holding tool 16, gear ratio data memory
// 12a, the synchronous operation of the feed (S x A), and the handshake of Fig. 4 between the
// NC and programmable controller 130 over bus 35 — become lanes under the five lead-screw
// panels (and under the press's, if there is a press), on the same time axis:
//
//   motor 27 .......... its speed, rev/min (the size: reverse shows as forward)
//   tool 16 ........... the tool's speed, rev/min: motor 27's times the head's ratio
//   interface 33 ...... encoder 32's edges in the last sample: the speed S the NC reads
//   memory 12a ........ the ratio A the NC computes with; the head on the spindle (head_31.tool)
//                       written over it, a mark at each exchange
//   feed .............. the synchronous control's command to the follower drive, in/min
//   depth called ...... what the tool's turns call for, inches; a band under it for the phase
//                       (tool call, in, out, spindle stopping, feed settling)
//   bus 35 ............ a bar per handshake line while it stands: tool call, transfer request,
//                       NC ready, data valid, NC received, tool ready (the seed's order)
//   PC 130 ............ a bar per relay of its ladder while it is picked, CR1 to CR8
//
// How we record it: from the trace signals of scope "spindle"
// (relaylogic/tapping/tapping_units.cpp, programmable_controller.cpp, gear_ratio_memory.cpp and
// interface 33's registers), through the same observer as the panels. The speeds, the feed and the
// depth change at every sample of interface 33 (20 a second by default) for as long as a tap runs,
// so each is kept as the press keeps its crank (the M4 reduction, plot_reduce.hpp: memory stays
// bounded whatever the run's length). Encoder 32's phases and interface 33's counters change at
// every encoder edge and are not drawn (interface 33's stored count is, once a sample). The ratio,
// the head, the phase, the bus lines and PC 130's relays change a few times a tap card and are kept
// whole.
#pragma once

#include "cardreader/orders.hpp"
#include "outputs/plots/plot_reduce.hpp"
#include "relaylogic/machine_observer.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>

namespace parsons::cli {

class SpindleTrace {
public:
    struct Point {
        double t = 0; // machine seconds
        double x = 0; // in the lane's unit
    };
    using Reduced = plot::ReducedLine<Point>;

    enum class Series : std::uint8_t {
        motor_27_rpm,       // motor_27.rpm
        tool_16_rpm,        // tool_16.rpm
        interface_33_edges, // interface_33.speed_stored, edges a sample
        feed_in_per_min,    // synchronous_control.feed / 1000
        depth_called_in,    // synchronous_control.depth_called / 1000
        kCount
    };
    // Step signals kept whole: their value at t = 0, then every change.
    enum class Steps : std::uint8_t {
        ratio_12a, // memory_12a.ratio, as a ratio
        head_31,   // head_31.tool: the tool number of the head on the spindle
        phase,     // synchronous_control.phase: 0 idle ... 5 feed settling
        kCount
    };
    // Bus 35's handshake lines, in the seed's order (Fig. 4).
    enum class Line : std::uint8_t {
        tool_call,        // bus35.tool_call (the NC: on while it calls a tool, the value T)
        transfer_request, // bus35.transfer_request (PC, S4)
        nc_ready,         // bus35.nc_ready (NC, S13)
        data_valid,       // bus35.data_valid (PC, S6)
        nc_received,      // bus35.nc_received (NC, S15)
        tool_ready,       // bus35.tool_ready (PC: CR8)
        kCount
    };
    static constexpr std::size_t kLines = static_cast<std::size_t>(Line::kCount);
    static constexpr std::size_t kRelays = 8; // PC 130's CR1 ... CR8

    // A signal of the run: returns a slot for on_signal if it is one the lanes draw.
    std::optional<std::size_t> define(const relaylogic::SignalInfo& info, std::uint32_t initial);
    void change(std::size_t slot, double seconds, std::uint32_t new_value);
    void card(double seconds, const cardreader::CardOrders& orders);
    void finish(double seconds);

    // The run has spindle synchronisation (its units defined their signals) and read a tap card.
    bool present() const { return defined_ && !taps_.empty(); }
    std::vector<Point> series(Series s) const;
    const std::vector<Point>& steps(Steps s) const;
    // When a head came onto the spindle (head_31.tool changed) and the tool it holds.
    struct Exchange {
        double t = 0;
        int tool = 0;
    };
    std::vector<Exchange> exchanges() const;
    // The intervals in which a bus line stood (tool call: a tool was called), and PC 130's relay
    // CR(n + 1) was picked; one still on at the end is open until t_end.
    std::vector<std::pair<double, double>> line_on(Line line, double t_end) const;
    std::vector<std::pair<double, double>> relay_on(std::size_t relay, double t_end) const;
    // The value of a step signal at t (the tool called, the ratio on the data lines, ...).
    static double value_at(const std::vector<Point>& steps, double t);
    const std::vector<Point>& line_steps(Line line) const;
    const std::vector<Point>& data_ratio() const { return data_ratio_; }
    // The tap cards read: when, and their orders.
    struct TapMark {
        double t = 0;
        int number = 0;
        cardreader::TapOrder order;
    };
    const std::vector<TapMark>& taps() const { return taps_; }

private:
    enum class Source : std::uint8_t { series, steps, line, relay, data_ratio };
    struct Role {
        Source source = Source::series;
        std::size_t index = 0;
        double scale = 1; // the signal's value times this is the lane's
    };
    // What a signal of scope "spindle" becomes, if the lanes draw it.
    static std::optional<Role> role_of(std::string_view name);

    std::vector<Role> roles_;
    std::array<Reduced, static_cast<std::size_t>(Series::kCount)> series_{};
    std::array<std::vector<Point>, static_cast<std::size_t>(Steps::kCount)> steps_{};
    std::array<std::vector<Point>, kLines> lines_{};
    std::array<std::vector<Point>, kRelays> relays_{};
    std::vector<Point> data_ratio_;
    std::vector<TapMark> taps_;
    bool defined_ = false;
};

} // namespace parsons::cli
