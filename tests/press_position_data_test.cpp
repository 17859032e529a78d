// Press synchronisation, an addition after EP 0436887 (Mitsubishi): the position data, at both
// paces. Claim 7: with position sync ordered, processor 63's position loop keeps a synchronised
// axis on its reference travel. Claim 5: a sync card's reset order operates switch 16A, and R
// and setter 15's revolution count from where register 14 was cleared.
#include "tests/press_support.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <string>
#include <vector>

using namespace parsons;
using namespace parsons::cardreader;
using namespace parsons::relaylogic;
using namespace parsons::test;

namespace {

// How far behind its reference travel the table was at the last reference block before `t`
// (processor 63's signal, ten-thousandths of an inch).
std::uint32_t behind_at(const Recorder& r, double t) {
    std::uint32_t v = 0;
    for (const Change& c : r.of("press.processor_63.table.behind")) {
        if (c.t > t) {
            break;
        }
        v = c.new_value;
    }
    return v;
}

} // namespace

TEST_CASE("Press sync (position data, claim 7): with position sync ordered, processor 63's "
          "position loop takes out the offset the drive's start and a change of the press's "
          "speed leave, which speed sync alone keeps",
          "[press_sync][speed][position-loop]") {
    const Pace pace = GENERATE(Pace::impulse_level, Pace::fast_forward);
    INFO("pace " << static_cast<int>(pace));
    axes::MachineProfile p = press_profile();
    p.press.change_cycle = 1; // the press speeds up by half at 120 deg (10 s), mid-move
    p.press.change_angle_deg = 120;
    p.press.change_factor = 1.5;
    auto run = [&](bool with_position) {
        SyncOrder o = speed_sync(Axis::table, 100); // 2.88 in/min
        if (with_position) {
            o.position_sync = true;
            o.angle_deg = 30;
        }
        SparseRecorder sparse;
        Recorder full;
        Recorder& rec = pace == Pace::fast_forward ? static_cast<Recorder&>(sparse) : full;
        const RunResult r =
            test::run_orders({sync_card(1, o), table_move(2, 0, 1000)}, p, &rec, {}, pace);
        INFO((r.stop ? r.stop->message : std::string()));
        REQUIRE(r.completed);
        REQUIRE(r.press);
        // Well after the change, before the slow-downs (0.900 in: 0.048 in/s, then 0.072).
        return std::tuple{behind_at(rec, 14.0), r.press->max_lag_position_sync_in,
                          r.press->max_lag_speed_only_in};
    };
    const auto [loop_behind, loop_max, loop_speed_only] = run(true);
    const auto [speed_behind, speed_max, speed_speed_only] = run(false);
    // Speed alone: the drive's start left the table 0.0023 in behind (0.048 in/s reached at
    // 0.5 in/s^2), the change a little more (0.024 in/s more, reached a block and a pulse
    // late), and nothing takes it out.
    CHECK(speed_behind >= 20);
    CHECK(speed_speed_only >= 0.0015);
    CHECK(speed_max == 0.0);
    // With position data the loop has it back within the counters' thousandth.
    CHECK(loop_behind <= 10);
    CHECK(loop_speed_only == 0.0);
    CHECK(loop_max > 0.0);
}

TEST_CASE("Press sync (claim 5): a sync card's reset order clears register 14 where the crank "
          "stands, and R and setter 15's revolution count from there, at both paces",
          "[press_sync][position][reset]") {
    const Pace pace = GENERATE(Pace::impulse_level, Pace::fast_forward);
    INFO("pace " << static_cast<int>(pace));
    const axes::MachineProfile p = press_profile();
    SyncOrder reset_and_wait = position_sync(90);
    reset_and_wait.register_reset = true;
    // Card 1 takes the crank well past top dead centre first: the reset comes where no edge of
    // a revolution would put register 14 at 0.
    const std::vector<CardOrders> deck = {table_move(1, 0, 300), sync_card(2, reset_and_wait),
                                          table_move(3, 300, 0), sync_card(4, position_sync(90)),
                                          table_move(5, 0, 300)};
    SparseRecorder sparse;
    Recorder full;
    Recorder& rec = pace == Pace::fast_forward ? static_cast<Recorder&>(sparse) : full;
    const RunResult r = test::run_orders(deck, p, &rec, {}, pace);
    INFO((r.stop ? r.stop->message : std::string()));
    REQUIRE(r.completed);
    REQUIRE(r.press);
    CHECK(r.press->register_resets == 1);
    // Switch 16A operates as card 2 is read, once.
    const double reset_t = first_time(rec, "press.switch_16A", 1);
    REQUIRE(reset_t > 0);
    CHECK(nth_time(rec, "press.switch_16A", 1, 2) < 0);
    const long at_reset = count_at(p.press, reset_t);
    REQUIRE(at_reset % 1440 > 360); // not a place where the crank's own angle would do
    bool cleared = false;
    for (const auto& c : rec.of("press.position_register_14")) {
        cleared = cleared || (c.t == reset_t && c.new_value == 0);
    }
    CHECK(cleared);
    // Card 3 starts on the edge 90 degrees (360 pulses) past the reset, not at the crank's 90.
    const double start3 = edge_time(p.press, at_reset + 360) + p.relay_operate_s;
    CHECK(nth_time(rec, "table.motor_38", 1, 2) == Approx(start3).margin(1e-9));
    const double start5 = nth_time(rec, "table.motor_38", 1, 3);
    // Card 5, with no reset of its own, keeps the reference: a whole revolution later.
    CHECK(start5 ==
          Approx(edge_time(p.press, at_reset + 360 + 1440) + p.relay_operate_s).margin(1e-9));
    // Setter 15 now operates a revolution after the reset, not at top dead centre.
    // (Edges nobody waits on are taken in jumps at the reference blocks: the relay is seen to
    // operate at the block that takes the edge.)
    const double setter = first_time(rec, "press.setter_15", 1);
    const double revolution = edge_time(p.press, at_reset + 1440);
    CHECK(setter >= revolution - 1e-9);
    CHECK(setter <= revolution + p.speed_sample_s + 1e-9);
    CHECK(setter > 30.0 + 1.0); // the crank's own revolution ends at 30 s

    // Without the reset the same deck starts card 3 at the crank's own 90 degrees.
    std::vector<CardOrders> plain = deck;
    plain.at(1) = sync_card(2, position_sync(90));
    Recorder again;
    const RunResult q = test::run_orders(plain, p, &again, {}, Pace::impulse_level);
    REQUIRE(q.completed);
    CHECK(q.press->register_resets == 0);
    const double plain3 = nth_time(again, "table.motor_38", 1, 2);
    const long turns = at_reset / 1440 + (at_reset % 1440 >= 360 ? 1 : 0);
    CHECK(plain3 ==
          Approx(edge_time(p.press, turns * 1440 + 360) + p.relay_operate_s).margin(1e-9));
}

TEST_CASE("Press sync (claim 5): a card of the reset alone holds nothing and needs no motion card, "
          "and after a waiting sync card it is refused as a second one",
          "[press_sync][reset][errors]") {
    const axes::MachineProfile p = press_profile();
    SyncOrder reset;
    reset.register_reset = true;
    const RunResult alone = test::run_orders(
        {table_move(1, 0, 300), sync_card(2, reset), table_move(3, 300, 0), sync_card(4, reset)},
        p);
    INFO((alone.stop ? alone.stop->message : std::string()));
    REQUIRE(alone.completed);
    CHECK(alone.press->register_resets == 2);
    CHECK(alone.press->waited_s == 0.0);
    const RunResult second = test::run_orders(
        {sync_card(1, position_sync(30)), sync_card(2, reset), table_move(3, 0, 300)}, p);
    REQUIRE(second.stop);
    CHECK(second.stop->reason == StopReason::sync_refused);
    CHECK_THAT(second.stop->message, Catch::Contains("a second sync card before one motion card"));
    CHECK(second.press->register_resets == 0);
}
