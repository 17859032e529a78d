// Speed switch 236, stepping relay 256, delay 258 and lamps 270 / 272 as the patent words them
// (docs/design-rules.md rules 5 and 6), and the earlier readings kept as named interpretations.
#include "tests/machine_support.hpp"

#include "axes/profile_json.hpp"

#include <catch2/catch.hpp>

using namespace parsons::cardreader;
using namespace parsons::relaylogic;
using namespace parsons::test;
using parsons::axes::default_profile;
using parsons::axes::MachineProfile;

namespace {

// The table counter reading at each change of `signal`, with the value it changed to.
std::vector<std::pair<int, std::uint32_t>> counter_at(const Recorder& r,
                                                      const std::string& signal) {
    std::map<std::string, std::uint32_t> v;
    std::vector<std::pair<int, std::uint32_t>> out;
    for (const auto& c : r.changes) {
        v[c.signal] = c.new_value;
        if (c.signal == signal) {
            out.emplace_back(static_cast<int>(v["table.absolute_counter_104"] * 1000 +
                                              v["table.absolute_counter_106"] * 100 +
                                              v["table.absolute_counter_108"] * 10 +
                                              v["table.absolute_counter_110"]),
                             c.new_value);
        }
    }
    return out;
}

// The steps of the table's speed switch after the card set it: (counter, new position).
std::vector<std::pair<int, std::uint32_t>> comparer_steps(const Recorder& r, int start_speed) {
    auto all = counter_at(r, "table.speed_switch_236");
    REQUIRE(all.size() >= static_cast<std::size_t>(start_speed));
    return {all.begin() + start_speed, all.end()};
}

using Steps = std::vector<std::pair<int, std::uint32_t>>;

CardOrders table_card(int speed, std::optional<int> slow1, std::optional<int> slow2, int stop,
                      int check) {
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::table) = order(0, stop, speed, slow1, slow2, 1);
    c.axis(Axis::table).check = static_cast<Thousandths>(check);
    return c;
}

const std::string kLamp270 = "table lamp 270 (absolute comparer 122' conducting)";
const std::string kLamp272 = "table lamp 272 (incremental comparer 122'' conducting)";

} // namespace

TEST_CASE("Speed switch 236: an incremental equality at speed 1 steps it one speed slower, like "
          "a slow-down, and only the step from 3 to off is the stop (rule 6)",
          "[speed-switch][fig10]") {
    // Check 1.000 is wrong: the increment counter reaches it long before the slow-downs.
    const CardOrders c = table_card(1, 2785, 2885, 2985, 1000);
    Recorder rec;
    RunResult r = run_orders({c}, default_profile(), &rec);
    CHECK(comparer_steps(rec, 1) == Steps{{1000, 2}, {2785, 3}, {2885, 0}});
    REQUIRE(r.stop);
    CHECK(r.stop->reason == StopReason::check_mismatch);
    CHECK(r.stop->lamps == std::vector<std::string>{"indicator 268", kLamp270});
    CHECK(r.axes.at(0).counter_in == Approx(2.885));
}

TEST_CASE("Interpretation incremental_equality_stops_at_any_speed: the earlier reading sends the "
          "switch from speed 1 straight to off",
          "[speed-switch][fig10][interpretation]") {
    MachineProfile p = default_profile();
    p.incremental_equality_stops_at_any_speed = true;
    const CardOrders c = table_card(1, 2785, 2885, 2985, 1000);
    Recorder rec;
    RunResult r = run_orders({c}, p, &rec);
    CHECK(comparer_steps(rec, 1) == Steps{{1000, 0}});
    REQUIRE(r.stop);
    CHECK(r.stop->reason == StopReason::check_mismatch);
    CHECK(r.axes.at(0).counter_in == Approx(1.020).margin(0.002)); // it coasts from speed 1
    // Lamp 272 lit at the stop, and went dark as the table coasted off 1.000: the report
    // gives the panel at the end, as the trace shows it.
    CHECK(rec.of("table.lamp_272").size() == 2);
    CHECK(rec.value.at("table.lamp_272") == 0);
    CHECK(r.stop->lamps == std::vector<std::string>{"indicator 268"});
}

TEST_CASE("Check: a check equal to the travel to a slow-down is caught on its own card, lamp 270 "
          "lit and 272 dark (rule 6)",
          "[speed-switch][check][fig10]") {
    // Check 2.785 (the travel to the first slow-down) instead of 2.985.
    CardOrders one = table_card(1, 2785, 2885, 2985, 2785);
    CardOrders two = idle_card(2, {2985, 0, 0, 0, 0});
    two.axis(Axis::table) = order(2985, 3985, 3, {}, {}, 1);
    Recorder rec;
    RunResult r = run_orders({one, two}, default_profile(), &rec);
    // Both comparers conduct at 2.785: one impulse, one step, and the card goes on.
    CHECK(comparer_steps(rec, 1) == Steps{{2785, 2}, {2885, 3}, {2985, 0}});
    REQUIRE(r.stop);
    CHECK(r.stop->reason == StopReason::check_mismatch);
    CHECK(r.stop->card == 1);
    CHECK(r.stop->axis == Axis::table);
    CHECK(r.stop->lamps == std::vector<std::string>{"indicator 268", kLamp270});
    CHECK(rec.value.at("table.lamp_270") == 1);
    CHECK(rec.value.at("table.lamp_272") == 0);
    CHECK(r.axes.at(0).counter_in == Approx(2.985));

    SECTION("the earlier reading accepts the card at 2.785 and stops only on the next one") {
        MachineProfile p = default_profile();
        p.incremental_equality_stops_at_any_speed = true;
        RunResult old = run_orders({one, two}, p);
        REQUIRE(old.stop);
        CHECK(old.stop->card == 2);
    }
}

TEST_CASE("Delay 258: a hold too short for the equality steps the switch twice on one equality "
          "(why 258 exists, rule 5)",
          "[speed-switch][delay-258][fig10]") {
    // Speed 2, one slow-down at 2.885: the switch should step to 3 there and stop at 2.985.
    const CardOrders c = table_card(2, 2885, std::nullopt, 2985, 2985);
    MachineProfile short_hold = default_profile();
    short_hold.delay_258_s = 0.005; // the equality lasts ~35 ms as the motor leaves speed 2
    Recorder rec;
    RunResult r = run_orders({c}, short_hold, &rec);
    // Both steps at 2.885: to speed 3, and 5 ms later, the equality still standing, to off.
    CHECK(comparer_steps(rec, 2) == Steps{{2885, 3}, {2885, 0}});
    const auto steps = rec.of("table.speed_switch_236");
    REQUIRE(steps.size() == 4);
    CHECK(steps[3].t - steps[2].t == Approx(0.005));
    REQUIRE(r.stop);
    CHECK(r.stop->reason == StopReason::check_mismatch);
    // Lamp 270 lit at the stop and went dark as the table coasted off 2.885 from speed 2.
    CHECK(rec.value.at("table.lamp_270") == 0);
    CHECK(r.stop->lamps == std::vector<std::string>{"indicator 268"});

    SECTION("the default hold outlasts an equality at the slowest speed, and the card completes") {
        const MachineProfile p = default_profile();
        const double slowest_in_per_s = p.axes.at(0).speed_in_per_min.at(2) / 60;
        CHECK(p.delay_258_s > 0.001 / slowest_in_per_s);
        Recorder ok;
        RunResult done = run_orders({c}, p, &ok);
        CHECK(done.completed);
        CHECK(comparer_steps(ok, 2) == Steps{{2885, 3}, {2985, 0}});
    }
    SECTION("the interpretation delay_258_waits_for_equality_to_leave never steps twice") {
        MachineProfile p = short_hold;
        p.delay_258_waits_for_equality_to_leave = true;
        RunResult done = run_orders({c}, p);
        CHECK(done.completed);
    }
}

TEST_CASE("Delay 258: numbers passed while it holds channel 257 open are missed: slow-downs "
          "0.001 apart at speed 1 run the table to its limit switch",
          "[speed-switch][delay-258]") {
    const CardOrders c = table_card(1, 2983, 2984, 2985, 2985);
    RunResult r = run_orders({c});
    REQUIRE(r.stop);
    CHECK(r.stop->reason == StopReason::limit_switch);
    CHECK(r.axes.at(0).real_in > 10.0);
}

TEST_CASE("Lamps 270 and 272: both light on a good stop while 236 stands on off, until zeroizing "
          "(rule 6)",
          "[speed-switch][lamps][fig10]") {
    const CardOrders c = table_card(3, std::nullopt, std::nullopt, 100, 100);
    Recorder rec;
    RunResult r = run_orders({c}, default_profile(), &rec);
    REQUIRE(r.completed);
    REQUIRE_FALSE(rec.at_zeroize.empty());
    CHECK(rec.at_zeroize.front().at("table.lamp_270") == 1);
    CHECK(rec.at_zeroize.front().at("table.lamp_272") == 1);
    CHECK(rec.value.at("table.lamp_270") == 0); // zeroizing cleared the storage
    const auto lit = rec.of("table.lamp_270");
    const auto off = rec.of("table.speed_switch_236");
    REQUIRE(!lit.empty());
    CHECK(lit.back().new_value == 0);
    // Lit at the instant the switch reached off, not before.
    double stop_t = -1;
    for (const auto& ch : off) {
        if (ch.new_value == 0 && ch.old_value == 3) {
            stop_t = ch.t;
        }
    }
    double lit_t = -1;
    for (const auto& ch : lit) {
        if (ch.new_value == 1 && ch.t > 0.5) {
            lit_t = ch.t;
        }
    }
    CHECK(lit_t == stop_t);

    SECTION("never lit while 236 stands on a speed, not even at a slow-down's equality") {
        Recorder slow;
        REQUIRE(run_orders({table_card(1, 2785, 2885, 2985, 2985)}, default_profile(), &slow)
                    .completed);
        std::uint32_t position = 0;
        int rises = 0;
        for (const auto& ch : slow.changes) {
            if (ch.signal == "table.speed_switch_236") {
                position = ch.new_value;
            }
            if (ch.signal == "table.lamp_270" && ch.new_value == 1) {
                CHECK(position == 0);
                ++rises;
            }
        }
        CHECK(rises == 1); // at the stop only
    }
    SECTION("the interpretation lamps_only_on_trip keeps them dark on a good stop, lit on a trip") {
        MachineProfile p = default_profile();
        p.lamps_only_on_trip = true;
        Recorder quiet;
        CHECK(run_orders({c}, p, &quiet).completed);
        for (const auto& snapshot : quiet.at_zeroize) {
            CHECK(snapshot.at("table.lamp_270") == 0);
            CHECK(snapshot.at("table.lamp_272") == 0);
        }
        const CardOrders wrong = table_card(3, std::nullopt, std::nullopt, 100, 110);
        Recorder trip;
        RunResult tr = run_orders({wrong}, p, &trip);
        REQUIRE(tr.stop);
        CHECK(trip.value.at("table.lamp_270") == 1);
        CHECK(trip.value.at("table.lamp_272") == 0);
    }
}

TEST_CASE("Profile: the readings and additions round-trip through JSON and a built-in base",
          "[speed-switch][profile]") {
    const MachineProfile p = parsons::axes::profile_from_json(
        R"({"base": "parsons-safe", "incremental_equality_stops_at_any_speed": true,
            "delay_258_waits_for_equality_to_leave": true, "lamps_only_on_trip": true})",
        default_profile());
    CHECK(p.name == "parsons-safe");
    CHECK(p.refuse_double_punch);
    CHECK(p.incremental_equality_stops_at_any_speed);
    CHECK(p.delay_258_waits_for_equality_to_leave);
    CHECK(p.lamps_only_on_trip);
    const MachineProfile back =
        parsons::axes::profile_from_json(parsons::axes::profile_to_json(p), default_profile());
    CHECK(back.refuse_double_punch);
    CHECK(back.incremental_equality_stops_at_any_speed);
    CHECK(back.delay_258_waits_for_equality_to_leave);
    CHECK(back.lamps_only_on_trip);
    CHECK_FALSE(default_profile().refuse_double_punch);
    CHECK(default_profile().name == "parsons-1952");
    CHECK_THROWS_WITH(
        parsons::axes::profile_from_json(R"({"lamps_only_on_trip": 1})", default_profile()),
        Catch::Contains("lamps_only_on_trip: expected true or false"));
    CHECK_THROWS_WITH(
        parsons::axes::profile_from_json(R"({"base": "parsons-1953"})", default_profile()),
        Catch::Contains("base: expected"));
}

TEST_CASE("Interpretation delay_258_waits_for_equality_to_leave: relays 256 and 258 hold while "
          "the equality stands, past the hold time, and drop when the counter leaves it",
          "[speed-switch][delay-258][interpretation][mutation]") {
    // Speed 2, slow-down 2.885: the equality at 2.885 lasts ~35 ms as the motor leaves speed 2,
    // far longer than a 5-ms hold. Under this reading 258 keeps channel 257 open (and 256
    // picked) until the counter has stepped off 2.885, not when the 5 ms have passed.
    MachineProfile p = default_profile();
    p.delay_258_s = 0.005;
    p.delay_258_waits_for_equality_to_leave = true;
    const CardOrders c = table_card(2, 2885, std::nullopt, 2985, 2985);
    Recorder rec;
    REQUIRE(run_orders({c}, p, &rec).completed);
    const auto delay = counter_at(rec, "table.delay_device_258");
    const auto relay = counter_at(rec, "table.stepping_relay_256");
    // The slow-down's step: picked at 2.885, dropped with the counter on 2.886.
    REQUIRE(delay.size() >= 2);
    CHECK(delay.at(0) == std::pair<int, std::uint32_t>{2885, 1});
    CHECK(delay.at(1) == std::pair<int, std::uint32_t>{2886, 0});
    REQUIRE(relay.size() >= 2);
    CHECK(relay.at(0) == std::pair<int, std::uint32_t>{2885, 1});
    CHECK(relay.at(1) == std::pair<int, std::uint32_t>{2886, 0});
    // And the drop came well after the hold time: the equality outlasted it.
    const auto held = rec.of("table.delay_device_258");
    REQUIRE(held.size() >= 2);
    CHECK(held.at(1).t - held.at(0).t > 4 * p.delay_258_s);

    SECTION("the patent's timed hold drops them when the hold runs out, the equality standing") {
        MachineProfile timed = p;
        timed.delay_258_waits_for_equality_to_leave = false;
        Recorder t;
        run_orders({c}, timed, &t);
        const auto d = counter_at(t, "table.delay_device_258");
        REQUIRE(d.size() >= 2);
        CHECK(d.at(1) == std::pair<int, std::uint32_t>{2885, 0});
        const auto h = t.of("table.delay_device_258");
        CHECK(h.at(1).t - h.at(0).t == Approx(0.005));
    }
}
