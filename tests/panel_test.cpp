// The stop and its check (docs/design-rules.md rule 6), end to end: the two comparers at the
// stop, balancing circuit 266 through contact 238, indicator 268 and lamps 270 and 272, and the
// panel the report shows at the end.
#include "tests/machine_support.hpp"
#include "tests/test_support.hpp"

#include "relaylogic/balancing_circuit.hpp"

#include <catch2/catch.hpp>

using namespace parsons::cardreader;
using namespace parsons::relaylogic;
using namespace parsons::test;

TEST_CASE("Checks: a check too large stops with only the absolute comparer conducting: lamp 270",
          "[cabinet][check][fig10]") {
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::table) = order(0, 100, 3, {}, {}, 1);
    c.axis(Axis::table).check = 110;
    RunResult r = run_orders({c});
    REQUIRE(r.stop);
    CHECK(r.stop->reason == StopReason::check_mismatch);
    CHECK(r.stop->axis == Axis::table);
    CHECK(r.stop->lamps == std::vector<std::string>{"indicator 268", "table lamp 270 (absolute "
                                                                     "comparer 122' conducting)"});
    CHECK(r.axes.at(0).counter_in == Approx(0.100));
}

TEST_CASE("Checks: a check too small stops early with only the incremental comparer: lamp 272",
          "[cabinet][check][fig10]") {
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::table) = order(0, 100, 3, {}, {}, 1);
    c.axis(Axis::table).check = 90;
    RunResult r = run_orders({c});
    REQUIRE(r.stop);
    CHECK(r.stop->reason == StopReason::check_mismatch);
    CHECK(r.stop->lamps == std::vector<std::string>{"indicator 268",
                                                    "table lamp 272 (incremental comparer "
                                                    "122'' conducting)"});
    CHECK(r.axes.at(0).counter_in == Approx(0.090));
}

TEST_CASE("Balancing circuit 266: when it trips, indicator 268 is listed first and the "
          "comparer's lamp after it, and 266 acts before 265, 204 and 268",
          "[cabinet][lamps][fig10][mutation]") {
    for (bool absolute : {true, false}) {
        INFO("absolute conducting " << absolute);
        Tracer tracer;
        Recorder rec;
        BalancingCircuit b(tracer);
        tracer.attach(&rec);
        CHECK_FALSE(b.check_at_stop(absolute, !absolute));
        CHECK_FALSE(b.master_switch_closed());
        // The circuit sounds indicator 268; the comparer's lamp is its axis's (270 or 272,
        // AxisCircuit::lamp_270_lit), which the cabinet's panel lists after the indicator.
        CHECK(b.lamps() == std::vector<std::string>{"indicator 268"});
        std::vector<std::string> order;
        for (const auto& ch : rec.changes) {
            order.push_back(ch.signal);
        }
        CHECK(order ==
              std::vector<std::string>{"cabinet.balancing_circuit_266", "cabinet.electromagnet_265",
                                       "cabinet.master_switch_204", "cabinet.indicator_268"});
    }
    // Balanced (both or neither conducting): nothing trips, nothing lights.
    Tracer tracer;
    BalancingCircuit b(tracer);
    CHECK(b.check_at_stop(true, true));
    CHECK(b.master_switch_closed());
    CHECK(b.lamps().empty());
    // A lamp lit before the trip still comes after the indicator: 268 sounds first.
    b.light("limit-switch lamp (table; an addition)");
    b.trip();
    CHECK(b.lamps() ==
          std::vector<std::string>{"indicator 268", "limit-switch lamp (table; an addition)"});
}

TEST_CASE("Lamps: the report's lamps are the panel at the end, as the trace shows it: every "
          "axis's lamps 270 and 272, and a lamp gone dark as its axis coasted off the number",
          "[cabinet][lamps][mutation]") {
    // The table trips at its stop 0.100 (check 0.200: only 122' conducts); the other axes
    // stand still (check 0).
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::table) = order(0, 100, 3, {}, {}, 1);
    c.axis(Axis::table).check = 200;
    auto coasting = parsons::axes::default_profile();
    coasting.axes.at(0).braking_in_per_s2 = 0.002; // a heavy table: it coasts off 0.100
    for (const auto& profile : {parsons::axes::default_profile(), coasting}) {
        Recorder rec;
        const RunResult r = run_orders({c}, profile, &rec);
        REQUIRE(r.stop);
        REQUIRE(r.stop->reason == StopReason::check_mismatch);
        // The lamps the trace shows lit at the end, in the report's words.
        std::vector<std::string> lit;
        if (rec.value.at("cabinet.indicator_268") == 1) {
            lit.emplace_back("indicator 268");
        }
        for (Axis a : kAxes) {
            const std::string axis(axis_name(a));
            if (rec.value.at(axis + ".lamp_270") == 1) {
                lit.push_back(axis + " lamp 270 (absolute comparer 122' conducting)");
            }
            if (rec.value.at(axis + ".lamp_272") == 1) {
                lit.push_back(axis + " lamp 272 (incremental comparer 122'' conducting)");
            }
        }
        CHECK(r.stop->lamps == lit);
        const bool coasted = profile.axes.at(0).braking_in_per_s2 < 0.01;
        INFO("coasting " << coasted);
        CHECK(r.axes.at(0).counter_in > (coasted ? 0.11 : 0.0995));
        // The table's lamp 270: lit where it stopped on 0.100, dark once it coasted off.
        const bool table_270 =
            std::find(lit.begin(), lit.end(),
                      "table lamp 270 (absolute comparer 122' conducting)") != lit.end();
        CHECK(table_270 == !coasted);
        // The same lamps without an observer (the cabinet reads its panel, not the trace).
        CHECK(run_orders({c}, profile).stop->lamps == lit);
    }
}

TEST_CASE("Balancing circuit 266 through contact 238: a card whose numbers make one comparer "
          "conduct where its axis stands trips the machine as it is read, before any motor "
          "starts",
          "[cabinet][check][fig10][mutation]") {
    // The table stands at 0.000, its stop 0.000 but its check 0.100: comparer 122' conducts
    // as the relays pick, 122'' does not. The cross would move 0.100 (each axis at its own
    // position, as idle_card punches them).
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::table).check = 100;
    c.axis(Axis::cross) = order(0, 100, 3, {}, {}, idle_card(1, {}).axis(Axis::cross).sequence);
    Recorder rec;
    const auto profile = parsons::axes::default_profile();
    const RunResult r = run_orders({c}, profile, &rec);
    REQUIRE(r.stop);
    CHECK(r.stop->reason == StopReason::check_mismatch);
    CHECK(r.stop->axis == Axis::table);
    CHECK(r.stop->card == 1);
    CHECK_THAT(r.stop->message, Catch::Contains("as the card was read, before any motor started, "
                                                "with speed switch 236 on off (contact 238), only "
                                                "the absolute comparer 122' conducted"));
    const auto tripped = rec.of("cabinet.balancing_circuit_266");
    REQUIRE(tripped.size() == 1);
    CHECK(tripped.front().t == Approx(profile.first_bank_s + profile.relay_operate_s));
    CHECK(r.axes.at(1).impulses == 0); // the cross never ran
    for (const char* motor : {"table.motor_38", "cross.motor_50"}) {
        CHECK(rec.of(motor).empty());
    }
    // A card in balance (check 0 where the table stands) runs through.
    c.axis(Axis::table).check = 0;
    CHECK(run_orders({c}).completed);
}
