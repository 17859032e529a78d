// The press on the chart of run --plot: press synchronisation is an addition after EP 0436887
// (Mitsubishi), present only in a profile with a press (parsons-extended). What the
// seed draws in Figs. 2A and 2B — crank 21's angle from top dead centre and die 20's height as
// the crank turns — and what Figs. 4 and 6 put beside it — the feeder's moves against the
// crank, the sampling of speed register 11 — become lanes under the five lead-screw panels,
// on the same time axis:
//
//   crank 21 .......... its angle, 0..360 degrees: a sawtooth that falls back at every top
//                       dead centre (register 14 is preset there by setter 15)
//   die 20 ............ its height above bottom dead centre, inches
//   register 14 ....... position register 14, detector pulses (the crank's angle as counted)
//   register 11 ....... speed register 11's stored count: the pulses of the last sampling
//                       interval, which processor 63 reads
//   reader 60 ......... a bar while programmed position reader 60's hold relay holds a card's
//                       motion for its angle R (and a thin one while a sync card's orders
//                       wait for their motion card), a mark where detector 61 conducted
//   processor 63 ...... the speed it sent each speed-synchronised axis's drive, in/min
//
// How we record it: from the trace signals of scope "press" (relaylogic/press/sync_units.cpp and
// the units it installs), through the same observer as the panels. The crank, die and
// registers change at every detector edge — 4 pulses a degree at 2 strokes a minute is 1440
// edges a revolution — so each is kept as the panels keep a position (the "M4" reduction of
// plot_svg.hpp: first, lowest, highest and last sample of a time bucket; the buckets widen as
// the run grows, so memory stays bounded). The hold, the sync card, detector 61's releases, the
// top dead centres and the sync cards read are a few a card and are kept whole.
//
// Emulation note: the cabinet shows crank 21 and die 20 first at the first detector edge (their
// signals read 0 before it), so their lines start there, not at t = 0: a fiftieth of a second
// into the run at the default press.
#pragma once

#include "cardreader/orders.hpp"
#include "outputs/plots/plot_reduce.hpp"
#include "relaylogic/machine_observer.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace parsons::cli {

class PressTrace {
public:
    struct Point {
        double t = 0; // machine seconds
        double x = 0; // in the lane's unit
    };
    // One signal kept as a line: the M4 reduction (plot_reduce.hpp).
    using Reduced = plot::ReducedLine<Point>;
    enum class Series : std::uint8_t {
        crank_21_deg,       // crank_21.angle / 10
        die_20_in,          // die_20.height / 1000
        register_14_pulses, // position_register_14
        register_11_speed,  // speed_register_11.speed: the crank's speed it reads, pulses a second
    };
    struct SyncMark { // a sync card read (on_card)
        double t = 0;
        int number = 0;
        cardreader::SyncOrder order;
    };

    // A signal of the run: returns a slot for on_signal if it is one the lanes draw.
    std::optional<std::size_t> define(const relaylogic::SignalInfo& info, std::uint32_t initial);
    void change(std::size_t slot, double seconds, std::uint32_t old_value, std::uint32_t new_value);
    void card(double seconds, const cardreader::CardOrders& orders);
    void finish(double seconds);

    // The run has a press (the profile installed its units).
    bool present() const { return present_; }
    std::vector<Point> series(Series s) const;
    // Processor 63's output to an axis's drive, in/min (every change, reduced).
    std::vector<Point> speed_63(cardreader::Axis axis) const;
    bool any_speed_63() const { return any_speed_; }
    // When crank 21 passed top dead centre: its angle fell back (forward) or rose past 360
    // (turning backwards), between two detector edges.
    const std::vector<double>& top_dead_centres() const { return top_dead_centres_; }
    // The intervals in which reader 60's hold relay held a card's motion (one still holding at
    // the end is open until t_end), and those in which a sync card's orders waited in 17.
    std::vector<std::pair<double, double>> holds(double t_end) const;
    std::vector<std::pair<double, double>> waiting_cards(double t_end) const;
    // The intervals in which the feeder's interlock held the press (press.feeder_hold_lag_in;
    // one still holding at the end is open until t_end): none without the key.
    std::vector<std::pair<double, double>> interlock_holds(double t_end) const;
    bool has_interlock() const { return !interlock_.empty(); }
    // When detector 61 conducted: register 14 stood on R and the card's motion began.
    const std::vector<double>& releases() const { return releases_; }
    const std::vector<SyncMark>& sync_cards() const { return sync_cards_; }

private:
    enum class Source : std::uint8_t {
        crank_21,
        die_20,
        register_14,
        register_11,
        hold_60,
        card_17,
        detector_61,
        processor_63,
        interlock
    };
    struct Role {
        Source source = Source::crank_21;
        std::size_t axis = 0; // processor 63's axis
    };

    std::vector<Role> roles_;
    std::array<Reduced, 4> series_{}; // by Series
    std::array<Reduced, cardreader::kAxisCount> speed_{};
    std::vector<Point> hold_;      // (t, 0/1) from the initial value on
    std::vector<Point> cards_;     // (t, 0/1)
    std::vector<Point> interlock_; // (t, 0/1): the feeder's interlock holds the press
    std::vector<double> releases_;
    std::vector<double> top_dead_centres_;
    std::vector<SyncMark> sync_cards_;
    bool crank_shown_ = false;
    bool present_ = false;
    bool any_speed_ = false;
};

} // namespace parsons::cli
