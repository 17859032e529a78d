// Press synchronisation, an addition after EP 0436887 (Mitsubishi): the seed's units
// in the cabinet — direction judging device 13, position register 14 with setter 15, device 16
// and switch 16A, speed register 11, synchronisation control processor 17 (60-63) — and the
// cabinet's position hold, speed following, loop (M99) and sync_timeout, at both paces. The
// position data of claims 5 and 7 (the register's reset, the position loop) are
// tests/press_position_data_test.cpp.
#include "tests/press_support.hpp"

#include "axes/press.hpp"
#include "relaylogic/press/direction_judging_device.hpp"
#include "relaylogic/press/position_register.hpp"
#include "relaylogic/press/speed_register.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <cmath>
#include <csignal>
#include <tuple>

using namespace parsons;
using namespace parsons::cardreader;
using namespace parsons::relaylogic;
using namespace parsons::test;

TEST_CASE("Press sync: direction judging device 13 counts up for the forward sequence of "
          "phases, down for the backward one, and not at all when both phases change",
          "[press_sync][units]") {
    Tracer tracer;
    DirectionJudgingDevice device(tracer, 0);
    for (long c = 1; c <= 9; ++c) {
        CHECK(device.judge(axes::phases_at(c)) == +1);
    }
    for (long c = 8; c >= -5; --c) {
        CHECK(device.judge(axes::phases_at(c)) == -1);
    }
    // From count -5 (phases of 3 mod 4 = 01) straight to the phases of -3 (1 mod 4 = 10): both
    // phases changed, no sense can be told.
    CHECK(device.judge(axes::phases_at(-3)) == 0);
    CHECK(device.last_sense() == -1);
}

TEST_CASE("Press sync: position register 14 counts up and down, setter 15 presets it at "
          "device 16's value (0) and below zero (device 16 - 1), switch 16A clears it",
          "[press_sync][units]") {
    Tracer tracer;
    PositionRegister r(tracer, 1440);
    r.preset(1437);
    r.count(+1);
    r.count(+1);
    CHECK(r.value() == 1439);
    CHECK(r.presets() == 0);
    r.count(+1); // reaches 1440 = device 16: setter 15 presets 0
    CHECK(r.value() == 0);
    CHECK(r.presets() == 1);
    r.count(-1); // below zero: setter 15 presets 1439
    CHECK(r.value() == 1439);
    CHECK(r.presets() == 2);
    r.preset(725);
    CHECK(r.digits() == Digits{0, 7, 2, 5});
    r.switch_16A();
    CHECK(r.value() == 0);
    CHECK(r.resets() == 1);
    CHECK(r.presets() == 2); // the switch is not setter 15
    // Many counts at once leave what single counts leave.
    for (int sense : {+1, -1}) {
        for (long n : {1L, 9L, 1439L, 1440L, 1441L, 5000L}) {
            PositionRegister one(tracer, 1440);
            PositionRegister many(tracer, 1440);
            one.preset(3);
            many.preset(3);
            for (long k = 0; k < n; ++k) {
                one.count(sense);
            }
            many.count_many(n, sense);
            CHECK(one.value() == many.value());
            CHECK(one.presets() == many.presets());
        }
    }
}

TEST_CASE("Press sync: speed register 11 stores the pulses of each sampling interval, as the "
          "press slows while pressing",
          "[press_sync][units]") {
    const Pace pace = GENERATE(Pace::impulse_level, Pace::fast_forward);
    INFO("pace " << static_cast<int>(pace));
    axes::MachineProfile p = press_profile();
    p.press.pressing_slowdown = 0.3;
    p.speed_sample_s = 0.5; // long blocks: whole counts of pulses to check (24 at the full speed)
    p.press.pressing_from_deg = 30;
    p.press.pressing_to_deg = 60;
    SparseRecorder rec;
    Recorder full;
    MachineObserver* observer =
        pace == Pace::fast_forward ? static_cast<MachineObserver*>(&rec) : &full;
    // A long, slow move keeps the deck running for a while.
    const RunResult r = test::run_orders({table_move(1, 0, 400)}, p, observer, {}, pace);
    REQUIRE(r.completed);
    const Recorder& seen = pace == Pace::fast_forward ? rec : full;
    std::vector<Change> stored = seen.of("press.speed_register_11.stored");
    // Every block stores: a change only when the count differs; check each change.
    REQUIRE(stored.size() >= 3);
    bool slower = false;
    for (const Change& c : stored) {
        const double block = c.t;
        const long expected = pulses_between(p.press, block - p.speed_sample_s, block);
        CHECK(c.new_value == static_cast<std::uint32_t>(expected));
        slower = slower || c.new_value < 24;
    }
    CHECK(first_time(seen, "press.speed_register_11.stored", 24) ==
          Approx(p.speed_sample_s).margin(1e-12)); // 12 deg/s x 4 x 0.5 s
    CHECK(slower);                                 // while pressing, fewer pulses an interval
    // The crank and the register at the end agree with the press.
    REQUIRE(r.press);
    CHECK(r.press->position_register ==
          static_cast<int>(std::lround(std::floor(r.press->crank_angle_deg * 4 + 1e-9))) % 1440);
}

TEST_CASE("Press sync: position register 14 counts down when the crank turns backwards",
          "[press_sync][units]") {
    const Pace pace = GENERATE(Pace::impulse_level, Pace::fast_forward);
    axes::MachineProfile p = press_profile();
    p.press.reverse = true;
    p.press.start_angle_deg = 100;
    const RunResult r = test::run_orders({table_move(1, 0, 300)}, p, nullptr, {}, pace);
    REQUIRE(r.completed);
    REQUIRE(r.press);
    // The crank went back 12 deg/s for the run's time (and round past the top); the register
    // followed it down: standing on an edge m / ppd passed backwards, it reads m - 1.
    const double back = 12.0 * r.machine_seconds;
    CHECK(back > 100.0);
    const double angle = r.press->crank_angle_deg;
    CHECK(std::fmod(100.0 - angle + 720.0, 360.0) <= std::fmod(back, 360.0) + 1e-9);
    CHECK(r.press->position_register ==
          ((static_cast<int>(std::lround(angle * 4)) - 1) % 1440 + 1440) % 1440);
}

TEST_CASE("Press sync (position, G101): a card's motion waits for the crank and starts when "
          "register 14 reaches R, to within one detector pulse, at both paces",
          "[press_sync][position]") {
    const Pace pace = GENERATE(Pace::impulse_level, Pace::fast_forward);
    INFO("pace " << static_cast<int>(pace));
    const axes::MachineProfile p = press_profile();
    SparseRecorder sparse;
    Recorder full;
    Recorder& rec = pace == Pace::fast_forward ? static_cast<Recorder&>(sparse) : full;
    const RunResult r = test::run_orders({sync_card(1, position_sync(90)), table_move(2, 0, 300)},
                                         p, &rec, {}, pace);
    REQUIRE(r.completed);
    const double reached = edge_time(p.press, 90 * 4); // the edge that brings 14 onto R
    CHECK(reached == Approx(7.5).margin(1e-9));        // 90 deg at 12 deg/s
    const double start = first_time(rec, "table.motor_38", 1);
    CHECK(start == Approx(reached + p.relay_operate_s).margin(1e-12));
    // Within one pulse: the crank stood between R and R + 1/ppd when the motor started.
    const double angle_at_start = 12.0 * start;
    CHECK(angle_at_start >= 90.0);
    CHECK(angle_at_start - 90.0 <= 0.25 + 12.0 * p.relay_operate_s + 1e-9);
    // Before that, the hold relay held: on from the card's reading until the start.
    const double held = first_time(rec, "press.position_reader_60.hold", 1);
    CHECK(held == Approx(2 * p.reader_cycle_s).margin(1e-9));
    CHECK(first_time(rec, "press.position_reader_60.hold", 0) == Approx(start).margin(1e-12));
    REQUIRE(r.press);
    CHECK(r.press->waited_s == Approx(start - held).margin(1e-9));
}

TEST_CASE("Press sync (position): a card whose angle the register stands on already starts at "
          "once, one the crank has just passed waits a whole revolution",
          "[press_sync][position]") {
    const Pace pace = GENERATE(Pace::impulse_level, Pace::fast_forward);
    axes::MachineProfile p = press_profile();
    // The reading completes at 1.2 s: the crank at 14.4 deg, register 57 (14.25 deg).
    p.press.start_angle_deg = 0;
    auto start_of = [&](int angle) {
        Recorder rec;
        SparseRecorder sparse;
        Recorder& seen = pace == Pace::fast_forward ? static_cast<Recorder&>(sparse) : rec;
        const RunResult r = test::run_orders(
            {sync_card(1, position_sync(angle)), table_move(2, 0, 300)}, p, &seen, {}, pace);
        REQUIRE(r.completed);
        return first_time(seen, "table.motor_38", 1);
    };
    p.press.start_angle_deg = 14.0 - 1.2 * 12.0 + 0.01; // register stands on 14 deg at 1.2 s
    CHECK(start_of(14) == Approx(1.2).margin(1e-9));
    p.press.start_angle_deg = 0;
    const double next_turn = start_of(14);
    CHECK(next_turn == Approx(30.0 + 14.0 / 12.0 + p.relay_operate_s).margin(1e-6));
}

TEST_CASE("Press sync (speed, G95): a synchronised axis travels F per detector pulse and "
          "follows the press when it slows",
          "[press_sync][speed]") {
    axes::MachineProfile p = press_profile();
    const int travel = 100; // 0.00100 in a pulse: 0.048 in/s at 48 pulses/s (2.88 in/min)
    auto run = [&](double factor, Pace pace) {
        axes::MachineProfile q = p;
        if (factor != 1.0) {
            q.press.change_cycle = 1;
            q.press.change_angle_deg = 0.001;
            q.press.change_factor = factor;
        }
        return test::run_orders(
            {sync_card(1, speed_sync(Axis::table, travel)), table_move(2, 0, 1000)}, q, nullptr, {},
            pace);
    };
    for (Pace pace : {Pace::impulse_level, Pace::fast_forward}) {
        INFO("pace " << static_cast<int>(pace));
        const RunResult full = run(1.0, pace);
        const RunResult half = run(0.5, pace);
        INFO((full.stop ? full.stop->message : std::string()));
        INFO((half.stop ? half.stop->message : std::string()));
        REQUIRE(full.completed);
        REQUIRE(half.completed);
        // Every speed of switch 236 follows: 0.900 in on speed 1 at F a pulse (0.048 or 0.024
        // in/s), 0.050 in on speed 2 at the 1952 1.8 in/min at the rated 48 pulses a second
        // (0.030 or 0.015 in/s) and 0.050 in on speed 3 at its 0.6 in/min (0.010 in/s, or
        // 0.005: under the drive's least 0.5 in/min, by stop and go, not held at the least).
        // Tails on the 1952 motor would make the slower press only 18.75 s longer.
        const double longer = half.machine_seconds - full.machine_seconds;
        CHECK(longer == Approx(0.900 / 0.024 - 0.900 / 0.048 + 0.050 / 0.015 - 0.050 / 0.030 +
                               0.050 / 0.005 - 0.050 / 0.010)
                            .epsilon(0.03));
        // Not the three-speed motor: speed 1 would cover 0.850 in in 9.4 s.
        CHECK(full.machine_seconds > 1.2 + 0.900 / 0.09 + 5);
        CHECK(full.axes.at(0).counter_in == Approx(1.0));
    }
}

TEST_CASE("Press sync: a press that stops while a card waits for its angle, or while an axis "
          "follows it, stops the machine with sync_timeout after the profile's time",
          "[press_sync][errors]") {
    const Pace pace = GENERATE(Pace::impulse_level, Pace::fast_forward);
    axes::MachineProfile p = press_profile();
    p.sync_timeout_s = 20;
    p.press.stop_cycle = 1;
    p.press.stop_angle_deg = 45; // at 3.75 s
    SECTION("waiting for its angle") {
        const RunResult r = test::run_orders(
            {sync_card(1, position_sync(90)), table_move(2, 0, 300)}, p, nullptr, {}, pace);
        REQUIRE(r.stop);
        CHECK(r.stop->reason == StopReason::sync_timeout);
        CHECK(r.stop->card == 2);
        CHECK_THAT(r.stop->message, Catch::Contains("90 deg") && Catch::Contains("motor 22"));
        // Held from 1.2 s; given up at the first reference block 20 s later.
        CHECK(r.machine_seconds >= 1.2 + 20);
        CHECK(r.machine_seconds <= 1.2 + 20 + p.speed_sample_s + 1e-9);
        CHECK(r.axes.at(0).impulses == 0);
    }
    SECTION("following it") {
        const RunResult r =
            test::run_orders({sync_card(1, speed_sync(Axis::table, 100)), table_move(2, 0, 1000)},
                             p, nullptr, {}, pace);
        REQUIRE(r.stop);
        CHECK(r.stop->reason == StopReason::sync_timeout);
        CHECK(r.stop->axis == Axis::table);
        CHECK(r.machine_seconds >= 3.75 + 20);
        CHECK(r.machine_seconds <= 3.75 + 20 + p.speed_sample_s + 1e-9);
        CHECK(r.axes.at(0).counter_in < 1.0);
    }
}

TEST_CASE("Press sync (M99): a loop card sends the reader back to a card so many times, with "
          "position synchronisation each cycle locks to the crank's revolution",
          "[press_sync][loop]") {
    const Pace pace = GENERATE(Pace::impulse_level, Pace::fast_forward);
    const axes::MachineProfile p = press_profile();
    const std::vector<CardOrders> deck = {sync_card(1, position_sync(30)), table_move(2, 0, 300),
                                          table_move(3, 300, 0), sync_card(4, loop_to(1, 3))};
    const RunResult r = test::run_orders(deck, p, nullptr, {}, pace);
    INFO((r.stop ? r.stop->message : std::string()));
    REQUIRE(r.completed);
    CHECK(r.cards_read == 16);
    REQUIRE(r.press);
    CHECK(r.press->cycles == 4);
    CHECK(r.press->loop_backs == 3);
    REQUIRE(r.press->mean_cycle_s);
    // One revolution a cycle, to within a detector pulse (the part coasts a little differently
    // into each cycle, so each cycle's last card ends a few milliseconds apart).
    CHECK(*r.press->mean_cycle_s == Approx(30.0).margin(1.0 / 48));
    CHECK(*r.press->shortest_cycle_s == Approx(30.0).margin(1.0 / 48));
    CHECK(*r.press->longest_cycle_s == Approx(30.0).margin(1.0 / 48));
    CHECK(r.axes.at(0).counter_in == Approx(0.0));
    // Without position sync the cycle is the cards' own time, not the crank's.
    std::vector<CardOrders> loose = deck;
    loose.at(0) = sync_card(1, speed_sync(Axis::table, 50));
    const RunResult q = test::run_orders(loose, p, nullptr, {}, pace);
    REQUIRE(q.completed);
    REQUIRE(q.press->mean_cycle_s);
    CHECK(std::abs(*q.press->mean_cycle_s - 30.0) > 1.0);
}

TEST_CASE("Press sync: the cabinet refuses a sync card under a profile without press "
          "synchronisation, a loop to a card it does not hold, and a sync card at the deck's end",
          "[press_sync][errors]") {
    const RunResult faithful = test::run_orders(
        {sync_card(1, position_sync(30)), table_move(2, 0, 300)}, axes::default_profile());
    REQUIRE(faithful.stop);
    CHECK(faithful.stop->reason == StopReason::sync_refused);
    CHECK_THAT(faithful.stop->message,
               Catch::Contains("column 76") && Catch::Contains("parsons-extended"));
    CHECK(faithful.axes.at(0).impulses == 0);
    const RunResult nowhere =
        test::run_orders({table_move(1, 0, 300), sync_card(2, loop_to(7, 2))}, press_profile());
    REQUIRE(nowhere.stop);
    CHECK(nowhere.stop->reason == StopReason::sync_refused);
    CHECK_THAT(nowhere.stop->message, Catch::Contains("0007"));
    const RunResult trailing =
        test::run_orders({table_move(1, 0, 300), sync_card(2, position_sync(30))}, press_profile());
    REQUIRE(trailing.stop);
    CHECK(trailing.stop->reason == StopReason::sync_refused);
}

namespace {

// Stops the run (as the operator's signal would) once the reader has taken card `at`.
class Interrupter : public MachineObserver {
public:
    Interrupter(volatile std::sig_atomic_t& flag, long at) : flag_(flag), at_(at) {}
    void on_card(double, long index, const CardOrders&) override {
        if (index == at_) {
            flag_ = 1;
        }
    }

private:
    volatile std::sig_atomic_t& flag_;
    long at_;
};

} // namespace

TEST_CASE("Press sync: a run saved in the middle of a looped job resumes to the same end, bit "
          "for bit",
          "[press_sync][resume]") {
    const Pace pace = GENERATE(Pace::impulse_level, Pace::fast_forward);
    const axes::MachineProfile p = press_profile();
    const std::vector<CardOrders> deck = {sync_card(1, position_sync(30)), table_move(2, 0, 300),
                                          sync_card(3, speed_sync(Axis::table, 60)),
                                          table_move(4, 300, 0), sync_card(5, loop_to(1, 2))};
    std::vector<Card> punched;
    for (const auto& o : deck) {
        punched.push_back(encode(o, fig8_layout()).card);
    }
    test::VectorDeck whole(punched);
    ControlCabinet reference(p, fig8_layout());
    reference.set_pace(pace);
    const RunResult end = reference.run(whole);
    INFO((end.stop ? end.stop->message : std::string()));
    REQUIRE(end.completed);
    REQUIRE(end.cards_read == 15);
    for (long at : {2L, 4L, 9L, 14L}) {
        INFO("interrupted at card " << at);
        volatile std::sig_atomic_t flag = 0;
        Interrupter stop(flag, at);
        test::VectorDeck first(punched);
        ControlCabinet saving(p, fig8_layout());
        saving.keep_resume_point(true);
        saving.watch_interrupt(&flag);
        saving.attach(&stop);
        const RunResult partial = saving.run(first);
        REQUIRE(partial.stop);
        REQUIRE(partial.stop->reason == StopReason::interrupted);
        const nlohmann::json state = nlohmann::json::parse(saving.resume_point().dump());
        ControlCabinet resumed(p, fig8_layout());
        resumed.set_pace(pace);
        resumed.resume(state);
        test::VectorDeck again(punched);
        const RunResult r = resumed.run(again);
        CHECK(r.completed);
        CHECK(r.machine_seconds == end.machine_seconds);
        CHECK(r.cards_read == end.cards_read);
        REQUIRE(r.press);
        CHECK(r.press->loop_backs == end.press->loop_backs);
        CHECK(r.press->cycles == end.press->cycles);
        CHECK(r.press->mean_cycle_s == end.press->mean_cycle_s);
        CHECK(r.press->position_register == end.press->position_register);
        CHECK(r.press->crank_angle_deg == end.press->crank_angle_deg);
        CHECK(r.axes.at(0).real_in == end.axes.at(0).real_in);
        CHECK(r.axes.at(0).impulses == end.axes.at(0).impulses);
    }
}

TEST_CASE("Press sync: the press's signals start where the crank stands when the run starts",
          "[press_sync][units]") {
    axes::MachineProfile p = press_profile();
    p.press.start_angle_deg = 100.1; // register 14 at 400 pulses, the crank at 1001 tenths
    Recorder rec;
    const RunResult r = test::run_orders({table_move(1, 0, 300)}, p, &rec);
    REQUIRE(r.completed);
    const std::vector<Change> reg = rec.of("press.position_register_14");
    REQUIRE_FALSE(reg.empty());
    CHECK(reg.front().old_value == 400);
    CHECK(reg.front().new_value == 401);
    const std::vector<Change> crank = rec.of("press.crank_21.angle");
    REQUIRE_FALSE(crank.empty());
    CHECK(crank.front().old_value == 1001);
    const std::vector<Change> die = rec.of("press.die_20.height");
    REQUIRE_FALSE(die.empty());
    axes::Press press(p.press);
    CHECK(die.front().old_value ==
          static_cast<std::uint32_t>(std::lround(press.die_height_in() * 1000)));
}

TEST_CASE("Press sync (speed): processor 63's speed goes to the drive one reference block after "
          "the sample it comes from (Fig. 6), within 20 ms of the register's reading",
          "[press_sync][speed]") {
    const Pace pace = GENERATE(Pace::impulse_level, Pace::fast_forward);
    axes::MachineProfile p = press_profile();
    REQUIRE(p.speed_sample_s <= 0.020); // the seed: "generally less than 20ms"
    p.press.change_cycle = 1;           // the press halves its speed at 60 deg (5 s)
    p.press.change_angle_deg = 60;
    p.press.change_factor = 0.5;
    SparseRecorder sparse;
    Recorder full;
    Recorder& rec = pace == Pace::fast_forward ? static_cast<Recorder&>(sparse) : full;
    const RunResult r = test::run_orders(
        {sync_card(1, speed_sync(Axis::table, 100)), table_move(2, 0, 1000)}, p, &rec, {}, pace);
    REQUIRE(r.completed);
    // Register 11 times its pulses: 48 a second exactly once two have come, 24 after the change.
    CHECK(first_time(rec, "press.speed_register_11.speed", 4800) <= 2.5 / 48 + p.speed_sample_s);
    const double read = first_time(rec, "press.speed_register_11.speed", 2400);
    REQUIRE(read > 5.0);
    CHECK(read <= 5.0 + 2.0 / 24 + p.speed_sample_s); // two pulses at the new speed and a block
    // 63 sends F x 24 pulses a second (1440 thousandths of an inch a minute) one block later.
    const double sent = first_time(rec, "press.processor_63.table", 1440);
    CHECK(sent == Approx(read + p.speed_sample_s).margin(1e-9));
    // Before the change the drive ran at F x 48 pulses a second.
    const std::vector<Change> out = rec.of("press.processor_63.table");
    REQUIRE_FALSE(out.empty());
    CHECK(out.front().new_value == 2880);
}

TEST_CASE("Press sync (speed): processor 63 never asks more of the drive than its fastest speed, "
          "max_in_per_min, and a feed below it is followed as computed",
          "[press_sync][speed][mutation]") {
    const Pace pace = GENERATE(Pace::impulse_level, Pace::fast_forward);
    axes::MachineProfile p = press_profile();
    REQUIRE(p.sync_drive.max_in_per_min == 5.4);
    auto outputs = [&](int travel) {
        SparseRecorder sparse;
        Recorder full;
        Recorder& rec = pace == Pace::fast_forward ? static_cast<Recorder&>(sparse) : full;
        const RunResult r = test::run_orders(
            {sync_card(1, speed_sync(Axis::table, travel)), table_move(2, 0, 1000)}, p, &rec, {},
            pace);
        INFO((r.stop ? r.stop->message : std::string()));
        REQUIRE(r.completed);
        std::uint32_t most = 0;
        for (const Change& c : rec.of("press.processor_63.table")) {
            most = std::max(most, c.new_value);
        }
        return std::pair{most, r.machine_seconds};
    };
    // 0.00500 in a pulse at 48 pulses/s asks 14.4 in/min: the drive gets its 5.4 in/min.
    const auto [fast, fast_s] = outputs(500);
    CHECK(fast == 5400);
    // 0.00150 in a pulse asks 4.32 in/min, under the drive's fastest: followed as asked.
    const auto [slow, slow_s] = outputs(150);
    CHECK(slow == 4320);
    // The 0.850 in followed at 5.4 rather than 4.32 in/min: about 2.4 s sooner, not 6.
    CHECK(slow_s - fast_s == Approx(0.850 / (4.32 / 60) - 0.850 / (5.4 / 60)).epsilon(0.15));
}

TEST_CASE("Press sync (speed): the cross slide follows the press too, on the speed its card "
          "starts it on (speed 2) and its slow-down",
          "[press_sync][speed]") {
    const Pace pace = GENERATE(Pace::impulse_level, Pace::fast_forward);
    INFO("pace " << static_cast<int>(pace));
    axes::MachineProfile p = press_profile();
    // 0.00060 in a pulse: 0.0288 in/s at 48 pulses a second (1.73 in/min, under speed 2's 1.8).
    auto run = [&](double factor) {
        axes::MachineProfile q = p;
        if (factor != 1.0) {
            q.press.change_cycle = 1;
            q.press.change_angle_deg = 0.001;
            q.press.change_factor = factor;
        }
        CardOrders c = idle_card(2, {0, 0, 0, 0, 0});
        c.axis(Axis::cross) = order(0, 300, 2, 250, std::nullopt, 0b11111);
        return test::run_orders({sync_card(1, speed_sync(Axis::cross, 60)), c}, q, nullptr, {},
                                pace);
    };
    const RunResult full = run(1.0);
    const RunResult half = run(0.5);
    INFO((full.stop ? full.stop->message : std::string()));
    INFO((half.stop ? half.stop->message : std::string()));
    REQUIRE(full.completed);
    REQUIRE(half.completed);
    CHECK(full.axes.at(1).counter_in == Approx(0.300));
    // 0.250 in on speed 2 at F a pulse (0.0288 or 0.0144 in/s), 0.050 in on speed 3 at the 1952
    // 0.6 in/min at the rated speed (0.010 in/s, or 0.005 by the drive's stop and go under its
    // least 0.5 in/min). On the three-speed motor the half-speed press would change nothing.
    const double longer = half.machine_seconds - full.machine_seconds;
    CHECK(longer ==
          Approx(0.250 / 0.0144 - 0.250 / 0.0288 + 0.050 / 0.005 - 0.050 / 0.010).epsilon(0.04));
}
