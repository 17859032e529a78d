#include "tests/press_support.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>

namespace parsons::test {

using namespace parsons::cardreader;

axes::MachineProfile press_profile() {
    axes::MachineProfile p = axes::extended_profile();
    p.press.strokes_per_min = 2.0; // 12 deg/s
    p.press.pulses_per_degree = 4; // 48 pulses/s
    // Each number its own register: the moves below need not dodge the shared banks' spurious
    // matches (docs/design-rules.md rule 2), which are not what these tests are about.
    p.separate_registers = true;
    return p;
}

CardOrders sync_card(int number, SyncOrder order) {
    CardOrders c;
    c.kind = CardKind::sync;
    c.number = number;
    c.sync = order;
    return c;
}

SyncOrder position_sync(int angle) {
    SyncOrder o;
    o.position_sync = true;
    o.angle_deg = angle;
    return o;
}

SyncOrder speed_sync(Axis a, int travel) {
    SyncOrder o;
    o.travel_per_pulse.at(axis_index(a)) = travel;
    return o;
}

SyncOrder loop_to(int card, int count) {
    SyncOrder o;
    o.loop = true;
    o.loop_to = card;
    o.loop_count = count;
    return o;
}

// The table moves from `from` to `to` at speed 1 with slow-downs 0.100 and 0.050 before the stop;
// every other axis stands.
CardOrders table_move(int number, int from, int to) {
    CardOrders c = idle_card(number, {from, 0, 0, 0, 0});
    const int d = to > from ? 1 : -1;
    c.axis(Axis::table) = order(from, to, 1, to - d * 100, to - d * 50, 1);
    return c;
}

// The pulses detector 10 has given by time t (an independent press).
long count_at(const axes::PressProfile& p, double t) {
    axes::Press press(p);
    while (press.next_event_time() <= t) {
        press.advance_to(press.next_event_time());
    }
    return press.count();
}

// The first time a signal changes to `value`, or -1.
double first_time(const Recorder& r, const std::string& signal, std::uint32_t value) {
    for (const auto& c : r.of(signal)) {
        if (c.new_value == value) {
            return c.t;
        }
    }
    return -1;
}

// The n-th time (1 = the first) a signal changes to `value`, or -1.
double nth_time(const Recorder& r, const std::string& signal, std::uint32_t value, int n) {
    for (const auto& c : r.of(signal)) {
        if (c.new_value == value && --n == 0) {
            return c.t;
        }
    }
    return -1;
}

// The time of the edge that brings the count to `count`.
double edge_time(const axes::PressProfile& p, long count) {
    axes::Press press(p);
    double last = 0;
    while (press.count() < count) {
        const double t = press.next_event_time();
        REQUIRE(t != axes::kNever);
        if (press.advance_to(t)) {
            last = t;
        }
    }
    return last;
}

// Detector pulses an independent press gives in (a, b].
long pulses_between(const axes::PressProfile& p, double a, double b) {
    axes::Press press(p);
    long at_a = press.count();
    bool passed_a = false;
    while (true) {
        const double t = press.next_event_time();
        if (t > b) {
            break;
        }
        if (!passed_a && t > a) {
            at_a = press.count();
            passed_a = true;
        }
        press.advance_to(t);
    }
    if (!passed_a) {
        at_a = press.count();
    }
    return std::labs(press.count() - at_a);
}

} // namespace parsons::test
