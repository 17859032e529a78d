// Impulse level's quiet stretches (relaylogic/control_cabinet_comparers.cpp, run_impulses): with
// no observer the cabinet works out how many of an axis's coming impulses are quiet and takes
// those without reading the comparers, the limits or the event queue (each switch still steps,
// with its rate check and carries). With an observer attached every impulse goes through
// on_impulse(), which reads everything: that run is the reference nothing is passed by in.
//
// Each deck here is built so that a wrong count of quiet impulses shows: a stored number met
// exactly where absolute counter 104-110 wraps (9.999 -> 0.000 forward, 0.000 -> 9.999 back),
// at the very first impulse of a card, while another axis's relay events fall due in the middle
// of a long stretch, two axes whose impulses come at the same instants, impulses faster than the
// switches can step, a machine stop that leaves the axes coasting, a travel limit and a soft
// limit. Each runs at impulse level with no observer, at impulse level with an observer that
// follows every impulse, and fast-forward; the results must be identical to the last bit.
#include "tests/machine_support.hpp"

#include "relaylogic/faults.hpp"

#include <catch2/catch.hpp>

#include <vector>

using namespace parsons;
using namespace parsons::cardreader;
using namespace parsons::relaylogic;
using parsons::test::idle_card;
using parsons::test::order;
using parsons::test::run_orders;

namespace {

// An observer that follows every impulse and records nothing: the run takes every impulse
// through on_impulse().
class QsEveryImpulse : public MachineObserver {
public:
    void on_signal_defined(const SignalInfo&, std::uint32_t) override {}
    void on_signal(double, SignalId, std::uint32_t, std::uint32_t) override {}
};

// The three runs of a deck; returns the quiet one (impulse level, no observer).
RunResult qs_three_ways(const std::vector<CardOrders>& cards,
                        const axes::MachineProfile& profile = axes::default_profile(),
                        const std::vector<Fault>& faults = {}) {
    const RunResult quiet = run_orders(cards, profile, nullptr, faults, Pace::impulse_level);
    QsEveryImpulse every;
    const RunResult reference = run_orders(cards, profile, &every, faults, Pace::impulse_level);
    const RunResult jumped = run_orders(cards, profile, nullptr, faults, Pace::fast_forward);
    parsons::test::require_same(reference, quiet);
    parsons::test::require_same(reference, jumped);
    return quiet;
}

// A card that moves the table alone.
CardOrders qs_table_card(int number, const std::array<int, 5>& at, const AxisOrder& table) {
    CardOrders c = idle_card(number, at);
    c.axis(Axis::table) = table;
    return c;
}

AxisOrder qs_move(Motion motion, int speed, std::optional<int> slow1, int stop, int check) {
    AxisOrder o;
    o.motion = motion;
    o.start_speed = speed;
    if (slow1) {
        o.slow_down[0] = static_cast<Thousandths>(*slow1);
    }
    o.stop = static_cast<Thousandths>(stop);
    o.check = static_cast<Thousandths>(check);
    o.sequence = 1;
    return o;
}

} // namespace

TEST_CASE("Quiet stretches: a slow-down met where the counter wraps, 9.999 -> 0.000 forward and "
          "0.000 -> 9.999 back, stops the table on the same impulse as one by one",
          "[quietstretch][cabinet]") {
    const std::array<int, 5> home{0, 0, 0, 0, 0};
    const std::vector<CardOrders> cards = {
        qs_table_card(1, home, order(0, 9800, 1, 9600, 9700)),
        // From 9.800 up: the slow-down on 0.000 is the impulse that wraps the counter.
        qs_table_card(2, {9800, 0, 0, 0, 0}, qs_move(Motion::forward, 2, 0, 100, 300)),
        // And back down: the stop on 9.999 is the impulse that wraps it back.
        qs_table_card(3, {100, 0, 0, 0, 0}, qs_move(Motion::reverse, 3, {}, 9999, 101)),
    };
    const RunResult r = qs_three_ways(cards);
    INFO((r.stop ? r.stop->message : std::string()));
    REQUIRE(r.completed);
    CHECK(r.axes.at(0).counter_in == Approx(9.999));
    CHECK(r.axes.at(0).counted_in == Approx(9.999));
}

TEST_CASE("Quiet stretches: a stored number met at the very first impulse of a card, and a "
          "stretch that begins on an equality, are read as one by one",
          "[quietstretch][cabinet]") {
    const std::vector<CardOrders> cards = {
        qs_table_card(1, {0, 0, 0, 0, 0}, order(0, 500, 2, 400)),
        // The stop one thousandth away: the first impulse closes both comparers.
        qs_table_card(2, {500, 0, 0, 0, 0}, order(500, 501, 3)),
        // The slow-down at the first impulse, the stop at the second.
        qs_table_card(3, {501, 0, 0, 0, 0}, order(501, 503, 2, 502)),
        // After the slow-down the comparer still conducts on its reading: the stretch that
        // follows begins on an equality.
        qs_table_card(4, {503, 0, 0, 0, 0}, order(503, 600, 2, 590)),
    };
    const RunResult r = qs_three_ways(cards);
    INFO((r.stop ? r.stop->message : std::string()));
    REQUIRE(r.completed);
    CHECK(r.axes.at(0).counter_in == Approx(0.6));
}

TEST_CASE("Quiet stretches: the cross slide's relay events fall due in the middle of the table's "
          "stretches, and two axes' impulses come at the same instants",
          "[quietstretch][cabinet]") {
    // Two steps of the sequence each (the benchmark's patterns): table and cross 1-2, vertical
    // and swivel 3-4, tilt 5.
    const SequencePattern first_two = 0b00011;
    const SequencePattern middle_two = 0b01100;
    CardOrders apart = idle_card(1, {0, 0, 0, 0, 0});
    apart.axis(Axis::table) = order(0, 2985, 1, 2785, 2885, first_two);
    apart.axis(Axis::cross) = order(0, 450, 2, 350, {}, first_two);
    apart.axis(Axis::vertical) = order(0, 120, 3, {}, {}, middle_two);
    apart.axis(Axis::swivel).sequence = middle_two;
    CardOrders together = idle_card(2, {2985, 450, 120, 0, 0});
    together.axis(Axis::table) = order(2985, 1485, 2, 1585, {}, first_two);
    // The same speed and length as the table's: their impulses come at the same instants.
    together.axis(Axis::cross) = order(450, 1950, 2, 1850, {}, first_two);
    together.axis(Axis::vertical).sequence = middle_two;
    together.axis(Axis::swivel).sequence = middle_two;
    const RunResult r = qs_three_ways({apart, together});
    INFO((r.stop ? r.stop->message : std::string()));
    REQUIRE(r.completed);
    CHECK(r.axes.at(0).counter_in == Approx(1.485));
    CHECK(r.axes.at(1).counter_in == Approx(1.95));
}

TEST_CASE("Quiet stretches: impulses faster than the switches can step lose the same steps as "
          "one by one",
          "[quietstretch][cabinet]") {
    axes::MachineProfile p = axes::default_profile();
    p.max_stepping_rate_per_s = 60; // speed 1 gives 90 impulses a second
    const std::vector<CardOrders> cards = {
        qs_table_card(1, {0, 0, 0, 0, 0}, order(0, 2000, 1, 1800, 1900)),
        qs_table_card(2, {2000, 0, 0, 0, 0}, order(2000, 2400, 2, 2300)),
    };
    const RunResult r = qs_three_ways(cards, p);
    CHECK(r.axes.at(0).lost_steps > 0);
}

TEST_CASE("Quiet stretches: a dropped impulse stops the machine mid-stretch and the axes coast "
          "on, counting, as one by one",
          "[quietstretch][cabinet]") {
    Fault drop;
    drop.kind = FaultKind::drop_impulse;
    drop.axis = Axis::table;
    drop.n = 1234;
    const std::vector<CardOrders> cards = {
        qs_table_card(1, {0, 0, 0, 0, 0}, order(0, 2985, 1, 2785, 2885)),
    };
    const RunResult r = qs_three_ways(cards, axes::default_profile(), {drop});
    REQUIRE(r.stop);
    CHECK(r.stop->reason == StopReason::missed_impulse);
    CHECK(r.axes.at(0).impulses > 1234); // the coast after the stop was counted
}

TEST_CASE("Quiet stretches: the travel limit and the soft limit stop the table on the same "
          "impulse as one by one",
          "[quietstretch][cabinet]") {
    // A stop beyond the limit switch at 10.5 in: reading 0.600 after the wrap.
    const std::vector<CardOrders> to_limit = {
        qs_table_card(1, {0, 0, 0, 0, 0}, order(0, 9900, 1, 9700, 9800)),
        qs_table_card(2, {9900, 0, 0, 0, 0}, qs_move(Motion::forward, 3, {}, 700, 800)),
    };
    const RunResult limited = qs_three_ways(to_limit);
    REQUIRE(limited.stop);
    CHECK(limited.stop->reason == StopReason::limit_switch);

    axes::MachineProfile p = axes::default_profile();
    p.axes.at(0).soft_limits = true;
    p.axes.at(0).soft_min_in = -0.2;
    p.axes.at(0).soft_max_in = 1.234;
    // A check short of the stop passes the review on the card; the soft-limit watch stops the
    // table on its way to the stop.
    AxisOrder past = order(0, 2985, 1, 2785, 2885);
    past.check = 1000;
    const std::vector<CardOrders> to_soft = {qs_table_card(1, {0, 0, 0, 0, 0}, past)};
    const RunResult soft = qs_three_ways(to_soft, p);
    REQUIRE(soft.stop);
    CHECK(soft.stop->reason == StopReason::soft_limit);
}
