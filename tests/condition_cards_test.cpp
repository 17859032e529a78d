// Condition cards, an addition after EP 0640901 (Siemens): the seed's units in the cabinet —
// converter UMS and buffer PFR, monitoring unit PRG, tripping unit ALE — claim by claim, at both
// paces, with the errors and the actions' effects (the card itself: condition_card_test.cpp).
#include "tests/condition_support.hpp"
#include "tests/machine_support.hpp"
#include "tests/test_support.hpp"

#include "axes/state_json.hpp"
#include "cardreader/card_svg.hpp"
#include "cardreader/condition_card.hpp"
#include "cardreader/condition_review.hpp"
#include "cardreader/deck_error.hpp"
#include "cardreader/deck_review.hpp"
#include "cardreader/listing_format.hpp"
#include "outputs/plots/plot_svg.hpp"
#include "outputs/traces/trace_outputs.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <sstream>

using namespace parsons;
using namespace parsons::cardreader;
using namespace parsons::relaylogic;
using parsons::test::cond;
using parsons::test::condition_card;
using parsons::test::idle_card;
using parsons::test::order;
using parsons::test::punched;
using parsons::test::table_move;

namespace {

// Every signal by name, and what the counter of the watched axis read at each condition met.
class Watch : public test::Recorder {
public:
    void on_condition(double t, const ConditionEvent& e) override {
        events.push_back(e);
        times.push_back(t);
        if (e.kind == ConditionEventKind::met) {
            counter_at_met.push_back(counter(value, std::string(axis_name(e.axis))));
            status_at_met.push_back(value.at("conditions.monitoring_prg.status"));
        }
    }
    std::vector<ConditionEvent> events;
    std::vector<double> times;
    std::vector<int> counter_at_met;
    std::vector<std::uint32_t> status_at_met;
};

RunResult run(const std::vector<CardOrders>& cards, Pace pace, MachineObserver* observer = nullptr,
              const axes::MachineProfile& profile = axes::extended_profile()) {
    return test::run_conditions(cards, pace, observer, profile);
}

} // namespace

TEST_CASE("Condition cards (claim 1): PRG reports when the counter steps onto the position in "
          "its sense, ALE initiates the action at once, and it is acknowledged when done",
          "[conditions][claims]") {
    const Pace pace = GENERATE(Pace::fast_forward, Pace::impulse_level);
    INFO("pace " << static_cast<int>(pace));
    const axes::MachineProfile profile = axes::extended_profile();
    // Card 2 moves the table 0 -> 0.400 in forward; a tool change trips at 0.150 and a lamp
    // at 0.399, one thousandth before the stop.
    const std::vector<CardOrders> deck = {
        condition_card(
            1, {cond(4, Axis::table, 150, PassingSense::forward, ActionKind::tool_change, 2),
                cond(5, Axis::table, 399, PassingSense::either, ActionKind::lamp, 3)}),
        table_move(2, 0, 400), table_move(3, 400, 300)};
    Watch watch;
    const RunResult r = run(deck, pace, &watch);
    REQUIRE(r.completed);
    REQUIRE(watch.counter_at_met == std::vector<int>{150, 399});
    REQUIRE(r.actions.size() == 2);
    const ActionRecord& tool = r.actions.at(0);
    CHECK(tool.event == 4);
    CHECK(tool.acknowledged_s - tool.tripped_s == Approx(profile.actions.tool_change_s));
    CHECK(r.actions.at(1).acknowledged_s - r.actions.at(1).tripped_s ==
          Approx(profile.actions.lamp_s));
    CHECK(r.tool_in_spindle == 2);
    // At speed 3 (0.6 in/min from rest at 0.2 in/s2) the tool change trips while the table
    // still has 0.250 in to go, some 25 s: it overlaps the move whole.
    CHECK(tool.overlap_s() == Approx(profile.actions.tool_change_s));
    CHECK(tool.tripped_s < tool.motion_end_s);
    // The move is not disturbed: card 2 takes as long as without the condition card (whose
    // reader cycle the plain deck spends on an idle card), and ends at the same place.
    const RunResult plain =
        run({idle_card(1, {0, 0, 0, 0, 0}), table_move(2, 0, 400), table_move(3, 400, 300)}, pace);
    REQUIRE(plain.completed);
    CHECK(r.cards.at(1).end_s - r.cards.at(1).start_s ==
          Approx(plain.cards.at(1).end_s - plain.cards.at(1).start_s).margin(1e-9));
    CHECK(r.axes.at(0).real_in == plain.axes.at(0).real_in);
}

TEST_CASE("Condition cards (claim 1): the sense of passing, a position the counter already "
          "stands on, and a move across 9.999 / 0.000",
          "[conditions][claims]") {
    const Pace pace = GENERATE(Pace::fast_forward, Pace::impulse_level);
    INFO("pace " << static_cast<int>(pace));
    SECTION("forward move, a reverse condition: never met, the machine stops") {
        Watch watch;
        const RunResult r = run({table_move(1, 0, 200),
                                 condition_card(2, {cond(8, Axis::table, 300, PassingSense::reverse,
                                                         ActionKind::lamp, 1)}),
                                 table_move(3, 200, 400)},
                                pace, &watch);
        REQUIRE(r.stop);
        CHECK(r.stop->reason == StopReason::condition_not_met);
        CHECK(r.stop->card == 3);
        CHECK(r.stop->axis == Axis::table);
        CHECK_THAT(r.stop->message, Catch::Contains("event 8 (condition card 2)"));
        CHECK_THAT(r.stop->message, Catch::Contains("0.300"));
        CHECK(watch.counter_at_met.empty());
        // Stopped as shaft 280 came home: the table reached its stop.
        CHECK(r.axes.at(0).counter_in == Approx(0.400));
    }
    SECTION("the same in its sense (forward): met") {
        const RunResult r = run({table_move(1, 0, 200),
                                 condition_card(2, {cond(8, Axis::table, 300, PassingSense::forward,
                                                         ActionKind::lamp, 1)}),
                                 table_move(3, 200, 400)},
                                pace);
        CHECK(r.completed);
        CHECK(r.actions.size() == 1);
    }
    SECTION("a position the counter stands on when the card is read is not passed") {
        const RunResult r = run({table_move(1, 0, 200),
                                 condition_card(2, {cond(8, Axis::table, 200, PassingSense::either,
                                                         ActionKind::lamp, 1)}),
                                 table_move(3, 200, 400)},
                                pace);
        REQUIRE(r.stop);
        CHECK(r.stop->reason == StopReason::condition_not_met);
    }
    SECTION("the stop itself is passed: a condition on the stop position trips with the stop") {
        Watch watch;
        const RunResult r = run({table_move(1, 0, 200),
                                 condition_card(2, {cond(8, Axis::table, 400, PassingSense::forward,
                                                         ActionKind::lamp, 1)}),
                                 table_move(3, 200, 400)},
                                pace, &watch);
        CHECK(r.completed);
        REQUIRE(r.actions.size() == 1);
        CHECK(watch.counter_at_met == std::vector<int>{400});
        // The same impulse stepped speed switch 236 to off: the table's stop.
        const auto off = watch.of("table.speed_switch_236");
        REQUIRE_FALSE(off.empty());
        CHECK(std::any_of(off.begin(), off.end(), [&](const test::Change& c) {
            return c.new_value == 0 && c.t == r.actions.at(0).tripped_s;
        }));
    }
    SECTION("across the counters' wrap: 9.950 -> 0.050 forward passes 9.990 and 0.010") {
        CardOrders there = idle_card(1, {0, 0, 0, 0, 0});
        there.axis(Axis::table) = order(0, 9950, 1, 9750, 9850, 1);
        CardOrders across = idle_card(3, {9950, 0, 0, 0, 0});
        across.axis(Axis::table).motion = Motion::forward;
        across.axis(Axis::table).stop = 50;
        across.axis(Axis::table).check = 100;
        across.axis(Axis::table).start_speed = 3;
        Watch watch;
        const RunResult r =
            run({there,
                 condition_card(
                     2, {cond(1, Axis::table, 9990, PassingSense::forward, ActionKind::lamp, 1),
                         cond(2, Axis::table, 10, PassingSense::forward, ActionKind::lamp, 2)}),
                 across},
                pace, &watch);
        CHECK(r.completed);
        CHECK(watch.counter_at_met == std::vector<int>{9990, 10});
    }
}

TEST_CASE("Condition cards (claim 2): several condition cards before one motion card, and the next "
          "card is fed only when every action is acknowledged",
          "[conditions][claims]") {
    const Pace pace = GENERATE(Pace::fast_forward, Pace::impulse_level);
    INFO("pace " << static_cast<int>(pace));
    axes::MachineProfile profile = axes::extended_profile();
    const std::vector<CardOrders> plain = {table_move(1, 0, 300), table_move(2, 300, 100)};
    const RunResult without = run(plain, pace, nullptr, profile);
    REQUIRE(without.completed);
    auto with_conditions = [](const std::vector<CardOrders>& motion) {
        std::vector<CardOrders> deck = {
            condition_card(
                1, {cond(1, Axis::table, 100, PassingSense::forward, ActionKind::lamp, 1),
                    cond(2, Axis::table, 200, PassingSense::forward, ActionKind::coolant_on)}),
            condition_card(
                2, {cond(3, Axis::table, 250, PassingSense::forward, ActionKind::tool_change, 2)})};
        CardOrders a = motion.at(0);
        a.number = 3;
        CardOrders b = motion.at(1);
        b.number = 4;
        deck.push_back(a);
        deck.push_back(b);
        return deck;
    };
    SECTION("short actions, done before the move ends: the deck takes exactly the two condition "
            "cards' reader cycles longer") {
        profile.actions.tool_change_s = 2.0;
        const RunResult r = run(with_conditions(plain), pace, nullptr, profile);
        REQUIRE(r.completed);
        CHECK(r.actions.size() == 3);
        CHECK(r.machine_seconds ==
              Approx(without.machine_seconds + 2 * profile.reader_cycle_s).margin(1e-9));
    }
    SECTION("a tool change that outlasts the move holds the zeroizing circuit: the next card is "
            "fed a relay release after its acknowledgement") {
        profile.actions.tool_change_s = 120.0;
        Watch watch;
        const RunResult r = run(with_conditions(plain), pace, &watch, profile);
        REQUIRE(r.completed);
        REQUIRE(r.actions.size() == 3);
        const ActionRecord& tool = r.actions.at(2);
        CHECK(tool.action == ActionKind::tool_change);
        REQUIRE(r.cards.size() == 4);
        CHECK(r.cards.at(2).end_s == tool.acknowledged_s);
        CHECK(r.cards.at(3).start_s == Approx(tool.acknowledged_s + profile.relay_release_s));
        CHECK(tool.acknowledged_s > tool.motion_end_s + 60);
        // The wait is traced: ALE holds the zeroizing circuit until the acknowledgement.
        const auto waits = watch.of("conditions.tripping_ale.waiting");
        REQUIRE(waits.size() == 2);
        CHECK(waits.at(0).new_value == 1);
        CHECK(waits.at(1).t == tool.acknowledged_s);
    }
}

TEST_CASE("Condition cards (claim 3): a condition and its action carry one identifier, PRG's "
          "status signal is that identifier, and an identifier given twice is refused",
          "[conditions][claims]") {
    const Pace pace = GENERATE(Pace::fast_forward, Pace::impulse_level);
    INFO("pace " << static_cast<int>(pace));
    Watch watch;
    CardOrders move = table_move(2, 0, 200);
    move.spindle = Spindle::off; // column 1 blank: the spindle stands until the action
    const RunResult r =
        run({condition_card(
                 1, {cond(17, Axis::table, 120, PassingSense::forward, ActionKind::spindle_forward),
                     cond(23, Axis::table, 180, PassingSense::forward, ActionKind::lamp, 4)}),
             move},
            pace, &watch);
    REQUIRE(r.completed);
    REQUIRE(watch.events.size() == 6);
    CHECK(watch.status_at_met == std::vector<std::uint32_t>{17, 23});
    for (std::size_t i = 0; i < 3; ++i) {
        CHECK(watch.events.at(i).event == 17);
    }
    CHECK(watch.events.at(0).kind == ConditionEventKind::met);
    CHECK(watch.events.at(1).kind == ConditionEventKind::action_started);
    CHECK(watch.events.at(1).action == ActionKind::spindle_forward);
    // The spindle runs up in the profile's run-up time: acknowledged then.
    const auto& times = watch.times;
    auto ack = std::find_if(watch.events.begin(), watch.events.end(), [](const auto& e) {
        return e.kind == ConditionEventKind::acknowledged && e.event == 17;
    });
    REQUIRE(ack != watch.events.end());
    CHECK(times.at(static_cast<std::size_t>(ack - watch.events.begin())) - times.at(0) ==
          Approx(axes::extended_profile().actions.spindle_run_up_s));
    // The same identifier twice for one motion card: UMS refuses it.
    const RunResult twice =
        run({condition_card(
                 1, {cond(17, Axis::table, 120, PassingSense::forward, ActionKind::lamp, 1)}),
             condition_card(
                 2, {cond(17, Axis::table, 150, PassingSense::forward, ActionKind::lamp, 2)}),
             table_move(3, 0, 200)},
            pace);
    REQUIRE(twice.stop);
    CHECK(twice.stop->reason == StopReason::condition_refused);
    CHECK(twice.stop->card == 2);
    CHECK_THAT(twice.stop->message, Catch::Contains("event 17 is already stored"));
    CHECK(twice.axes.at(0).impulses == 0);
}

TEST_CASE("Condition cards (claim 4): a condition card watches the motion card after it, and "
          "one with no motion card after it is refused",
          "[conditions][claims]") {
    const Pace pace = GENERATE(Pace::fast_forward, Pace::impulse_level);
    INFO("pace " << static_cast<int>(pace));
    // 0.150 is passed on card 1, not on card 3 (0.200 -> 0.300): the condition before card 3
    // is not met.
    const RunResult r = run(
        {table_move(1, 0, 200),
         condition_card(2, {cond(9, Axis::table, 150, PassingSense::either, ActionKind::lamp, 1)}),
         table_move(3, 200, 300)},
        pace);
    REQUIRE(r.stop);
    CHECK(r.stop->reason == StopReason::condition_not_met);
    CHECK(r.stop->card == 3);
    const RunResult trailing = run(
        {table_move(1, 0, 200),
         condition_card(2, {cond(9, Axis::table, 150, PassingSense::either, ActionKind::lamp, 1)})},
        pace);
    REQUIRE(trailing.stop);
    CHECK(trailing.stop->reason == StopReason::condition_refused);
    CHECK_THAT(trailing.stop->message, Catch::Contains("card 2 (number 0002): a condition card "
                                                       "with no motion card after it"));
}

TEST_CASE("Condition cards: a condition on an axis the motion card does not move, or any "
          "condition card under parsons-1952, is refused before the card moves",
          "[conditions][errors]") {
    const Pace pace = GENERATE(Pace::fast_forward, Pace::impulse_level);
    INFO("pace " << static_cast<int>(pace));
    const RunResult idle = run(
        {condition_card(1, {cond(9, Axis::cross, 150, PassingSense::either, ActionKind::lamp, 1)}),
         table_move(2, 0, 200)},
        pace);
    REQUIRE(idle.stop);
    CHECK(idle.stop->reason == StopReason::condition_refused);
    CHECK(idle.stop->card == 2);
    CHECK_THAT(idle.stop->message, Catch::Contains("the cross axis, which this motion card does "
                                                   "not move"));
    CHECK(idle.axes.at(0).impulses == 0);
    const RunResult faithful = run(
        {table_move(1, 0, 200),
         condition_card(2, {cond(9, Axis::table, 250, PassingSense::either, ActionKind::lamp, 1)}),
         table_move(3, 200, 300)},
        pace, nullptr, axes::default_profile());
    REQUIRE(faithful.stop);
    CHECK(faithful.stop->reason == StopReason::condition_refused);
    CHECK(faithful.stop->card == 2);
    CHECK_THAT(faithful.stop->message, Catch::Contains("profile parsons-1952 has no condition "
                                                       "units"));
    CHECK_THAT(faithful.stop->message, Catch::Contains("parsons-extended"));
    CHECK(faithful.axes.at(0).counter_in == Approx(0.200));
}

TEST_CASE("Condition cards: the actions act on the plant — dwell holds its axis, the spindle "
          "runs down and up, coolant, and a lamp lit until zeroizing",
          "[conditions][actions]") {
    const Pace pace = GENERATE(Pace::fast_forward, Pace::impulse_level);
    INFO("pace " << static_cast<int>(pace));
    const axes::MachineProfile profile = axes::extended_profile();
    const std::vector<CardOrders> plain = {idle_card(1, {0, 0, 0, 0, 0}), table_move(2, 0, 300)};
    const RunResult without = run(plain, pace);
    Watch watch;
    const RunResult r =
        run({condition_card(
                 1, {cond(1, Axis::table, 100, PassingSense::forward, ActionKind::dwell, 1),
                     cond(2, Axis::table, 50, PassingSense::forward, ActionKind::spindle_reverse),
                     cond(3, Axis::table, 60, PassingSense::forward, ActionKind::coolant_on),
                     cond(4, Axis::table, 290, PassingSense::forward, ActionKind::lamp, 3)}),
             table_move(2, 0, 300)},
            pace, &watch);
    REQUIRE(r.completed);
    // The hold relay opened the table's motor circuit for the dwell: it coasted to rest and
    // ran up again, so the move took longer, by more than the dwell.
    const auto hold = watch.of("conditions.tripping_ale.hold_table");
    REQUIRE(hold.size() == 2);
    CHECK(hold.at(1).t - hold.at(0).t == Approx(profile.actions.dwell_s));
    const auto motor = watch.of("table.motor_38");
    CHECK(std::any_of(motor.begin(), motor.end(), [&](const test::Change& c) {
        return c.t == hold.at(0).t && c.new_value == 0;
    }));
    CHECK(r.machine_seconds > without.machine_seconds - 0.6 + profile.actions.dwell_s);
    CHECK(r.axes.at(0).counter_in == Approx(0.300));
    // Spindle: forward from column 1 (run up at relays pick), then reversed: run down and up.
    const auto spindle = watch.of("conditions.spindle_motor");
    REQUIRE_FALSE(spindle.empty());
    CHECK(spindle.back().new_value == 2);
    const ActionRecord& reversal = r.actions.at(0);
    REQUIRE(reversal.action == ActionKind::spindle_reverse);
    CHECK(reversal.acknowledged_s - reversal.tripped_s >= profile.actions.spindle_run_up_s);
    // The machine has one spindle motor: the action drives the motor column 1 commands, and
    // the cabinet's signal shows it changing from the trip until the acknowledgement.
    const auto one = watch.of("cabinet.spindle_motor");
    auto at = [&one](double t, std::uint32_t v) {
        return std::any_of(one.begin(), one.end(),
                           [&](const test::Change& c) { return c.t == t && c.new_value == v; });
    };
    CHECK(at(reversal.tripped_s, 3));
    CHECK(at(reversal.acknowledged_s, 2));
    CHECK(watch.of("conditions.coolant_valve").back().new_value == 1);
    // The lamp (bit 2 for lamp 3) lit at the trip and went out with zeroizing.
    const auto lamps = watch.of("conditions.output_lamps");
    REQUIRE(lamps.size() == 2);
    CHECK(lamps.at(0).new_value == 4);
    CHECK(lamps.at(1).new_value == 0);
    CHECK(lamps.at(1).t == r.cards.at(1).end_s);
}

TEST_CASE("Condition cards: a state saved as the motion card is fed carries the stored "
          "conditions, and the resumed run ends as a run straight through",
          "[conditions][resume]") {
    const Pace pace = GENERATE(Pace::fast_forward, Pace::impulse_level);
    INFO("pace " << static_cast<int>(pace));
    std::vector<CardOrders> good = {
        table_move(1, 0, 300),
        condition_card(
            2, {cond(5, Axis::table, 250, PassingSense::reverse, ActionKind::tool_change, 2),
                cond(6, Axis::table, 120, PassingSense::reverse, ActionKind::lamp, 1)}),
        table_move(3, 300, 100), table_move(4, 100, 200)};
    std::vector<CardOrders> bad = good;
    bad.at(2).axis(Axis::table).check = 199; // one short: the machine stops on card 3
    const axes::MachineProfile profile = axes::extended_profile();

    test::VectorDeck faulty(punched(bad));
    ControlCabinet first(profile, fig8_layout());
    first.set_pace(pace);
    first.record_card_times(true);
    first.keep_resume_point(true);
    const RunResult stopped = first.run(faulty);
    REQUIRE(stopped.stop);
    CHECK(stopped.stop->card == 3);
    const auto saved = nlohmann::json::parse(first.resume_point().dump());
    // The saved buffer holds both conditions, stored for the card being fed.
    const auto& pairs = saved.at("conditions").at("buffer_pfr");
    CHECK(pairs.at(0).at("state") == 1);
    CHECK(pairs.at(0).at("event") == 5);
    CHECK(pairs.at(1).at("event") == 6);

    const RunResult whole = run(good, pace);
    REQUIRE(whole.completed);
    test::VectorDeck again(punched(good));
    ControlCabinet resumed(profile, fig8_layout());
    resumed.set_pace(pace);
    resumed.record_card_times(true);
    resumed.resume(saved);
    const RunResult rest = resumed.run(again);
    REQUIRE(rest.completed);
    CHECK(rest.machine_seconds == whole.machine_seconds);
    CHECK(rest.axes.at(0).real_in == whole.axes.at(0).real_in);
    CHECK(rest.tool_in_spindle == 2);
    REQUIRE(rest.actions.size() == whole.actions.size());
    for (std::size_t i = 0; i < rest.actions.size(); ++i) {
        CHECK(rest.actions.at(i).tripped_s == whole.actions.at(i).tripped_s);
        CHECK(rest.actions.at(i).acknowledged_s == whole.actions.at(i).acknowledged_s);
    }
    // A state whose buffer was tampered with is refused, not half loaded.
    auto broken = saved;
    broken["conditions"]["buffer_pfr"][0]["axis"] = 7;
    ControlCabinet refused(profile, fig8_layout());
    CHECK_THROWS_AS(refused.resume(broken), axes::StateError);
}

TEST_CASE("Condition cards: the deck review names each deck error by card and column and "
          "foresees condition_not_met",
          "[conditions][review]") {
    DeckReviewer reviewer;
    reviewer.allow_conditions(true, "parsons-extended");
    std::vector<ReviewNote> notes;
    auto review = [&](const CardOrders& o) {
        for (auto& n : reviewer.review(o)) {
            notes.push_back(n);
        }
    };
    review(table_move(1, 0, 200));
    review(
        condition_card(2, {cond(3, Axis::cross, 100, PassingSense::forward, ActionKind::lamp, 1),
                           cond(3, Axis::table, 100, PassingSense::forward, ActionKind::lamp, 2),
                           cond(4, Axis::table, 100, PassingSense::forward, ActionKind::lamp, 2)}));
    review(table_move(3, 200, 400));
    review(
        condition_card(4, {cond(5, Axis::table, 1, PassingSense::forward, ActionKind::lamp, 1)}));
    for (auto& n : reviewer.finish()) {
        notes.push_back(n);
    }
    REQUIRE(notes.size() == 3);
    // The duplicate identifier: card 2, condition 2's event columns 16-17.
    CHECK(notes.at(0).deck_error);
    CHECK(notes.at(0).card == 2);
    CHECK(notes.at(0).column == 16);
    // The cross does not move on card 3: card 2, condition 1's axis column 3.
    CHECK(notes.at(1).deck_error);
    CHECK(notes.at(1).card == 2);
    CHECK(notes.at(1).column == 3);
    // Event 4 (table 0.100) is behind the table on card 3 (0.200 -> 0.400): no note here, the
    // run finds it (check runs the deck and says condition_not_met).
    // Card 4 has no motion card after it: its column 76.
    CHECK(notes.at(2).deck_error);
    CHECK(notes.at(2).card == 4);
    CHECK(notes.at(2).column == 76);

    // A tool change to a tool the changer does not hold: its parameter columns (slot 1: 10).
    DeckReviewer tools;
    tools.allow_conditions(true, "parsons-extended", {1, 2});
    auto found = tools.review(condition_card(
        1, {cond(1, Axis::table, 100, PassingSense::forward, ActionKind::tool_change, 7)}));
    REQUIRE(found.size() == 1);
    CHECK(found.at(0).deck_error);
    CHECK(found.at(0).column == 10);
    CHECK_THAT(found.at(0).message, Catch::Contains("tool 7 is not in the tool changer"));
    CHECK(tools
              .review(condition_card(2, {cond(2, Axis::table, 100, PassingSense::forward,
                                              ActionKind::tool_change, 2)}))
              .empty());
    // ... and a condition card under parsons-1952: its column 76.
    DeckReviewer faithful;
    faithful.allow_conditions(false, "parsons-1952");
    found = faithful.review(
        condition_card(1, {cond(1, Axis::table, 100, PassingSense::forward, ActionKind::lamp, 1)}));
    REQUIRE(found.size() == 1);
    CHECK(found.at(0).column == 76);
    CHECK_THAT(found.at(0).message, Catch::Contains("profile parsons-1952 has no condition units"));
}

TEST_CASE("Condition cards: run refuses a deck error with exit 2 before any motion, check and "
          "show name card and column, and a condition never met is exit 3",
          "[conditions][cli]") {
    test::TempDir dir;
    const std::string header = std::string(kListingHeader) + "\n";
    auto motion = [](int card, const char* table) {
        std::string rows = fmt::format("{},0,table,{}\n", card, table);
        for (const char* axis : {"cross", "vertical", "swivel", "tilt"}) {
            rows += fmt::format("{},0,{},+,3,,,0.000,0.000,{}\n", card, axis,
                                std::string(axis) == "cross" ? 2 : 3);
        }
        return rows;
    };
    const std::string good = header + "1,if,1,table,+,0.100,lamp,2\n" +
                             motion(2, "+,3,,,0.200,0.200,1") + "3,if,2,table,-,0.100,lamp,3\n" +
                             motion(4, "-,3,,,0.050,0.150,1");
    test::write_bytes(dir.path("good.csv"), good);
    const auto faithful = test::run_parsons("run " + test::q(dir.str("good.csv")) + " -q");
    CHECK(faithful.exit_code == 2);
    CHECK_THAT(faithful.output, Catch::Contains("good.csv: card 1, column 76: a condition card"));
    CHECK_THAT(faithful.output, Catch::Contains("parsons-extended"));
    const auto extended =
        test::run_parsons("run " + test::q(dir.str("good.csv")) +
                          " -q --profile parsons-extended --report " + test::q(dir.str("r.json")));
    CHECK(extended.exit_code == 0);
    const auto report = nlohmann::json::parse(test::read_bytes(dir.path("r.json")));
    CHECK(report.at("actions").size() == 2);
    CHECK(report.at("actions").at(1).at("event") == 2);

    // Event 2 twice for card 4's... no: a duplicate within one motion card.
    const std::string twice = header +
                              "1,if,1,table,+,0.100,lamp,2\n1,if,1,table,+,0.150,lamp,3\n" +
                              motion(2, "+,3,,,0.200,0.200,1");
    test::write_bytes(dir.path("twice.csv"), twice);
    const auto refused =
        test::run_parsons("run " + test::q(dir.str("twice.csv")) +
                          " --profile parsons-extended --events " + test::q(dir.str("e.jsonl")));
    CHECK(refused.exit_code == 2);
    CHECK_THAT(refused.output, Catch::Contains("twice.csv: card 1, column 16: condition 2: event 1 "
                                               "is given twice"));
    CHECK_FALSE(std::filesystem::exists(dir.path("e.jsonl"))); // refused before anything ran
    for (const char* command : {"check", "show"}) {
        INFO(command);
        const auto listed =
            test::run_parsons(std::string(command) + " " + test::q(dir.str("twice.csv")) +
                              " --profile parsons-extended");
        CHECK(listed.exit_code == 2);
        CHECK_THAT(listed.output, Catch::Contains("column 16"));
    }
    // The condition on card 3 is behind the table: check foresees it (exit 3), run stops on
    // it (exit 3, condition_not_met).
    const std::string behind = header + motion(1, "+,3,,,0.200,0.200,1") +
                               "2,if,5,table,+,0.100,lamp,2\n" + motion(3, "+,3,,,0.300,0.100,1");
    test::write_bytes(dir.path("behind.csv"), behind);
    const auto checked = test::run_parsons("check " + test::q(dir.str("behind.csv")) +
                                           " --profile parsons-extended");
    CHECK(checked.exit_code == 3);
    CHECK_THAT(checked.output, Catch::Contains("condition_not_met"));
    const auto stopped = test::run_parsons("run " + test::q(dir.str("behind.csv")) +
                                           " -q --profile parsons-extended");
    CHECK(stopped.exit_code == 3);
    CHECK_THAT(stopped.output, Catch::Contains("condition_not_met: card 3 (number 0003): event 5"));
}

TEST_CASE("Condition card: its picture names the five condition slots and the extension mark, a "
          "motion card's does not",
          "[conditions][card]") {
    const Card c = encode(condition_card(3, {cond(7, Axis::cross, 1250, PassingSense::reverse,
                                                  ActionKind::tool_change, 2)}),
                          fig8_layout())
                       .card;
    const std::string svg = card_svg(c, fig8_layout(), {});
    for (const char* label :
         {"CONDITION 1", "CONDITION 5", "EXTENSION", "POSITION", "PARAM.", "CARD NO."}) {
        CHECK_THAT(svg, Catch::Contains(label));
    }
    CHECK_THAT(svg, !Catch::Contains("TABLE"));
    const std::string motion =
        card_svg(encode(table_move(1, 0, 100), fig8_layout()).card, fig8_layout(), {});
    CHECK_THAT(motion, Catch::Contains("TABLE"));
    CHECK_THAT(motion, !Catch::Contains("CONDITION"));
}

TEST_CASE("Condition cards: the plot marks where each condition was met and the events stream "
          "carries each condition, action and acknowledgement by its identifier",
          "[conditions][outputs]") {
    const std::vector<CardOrders> deck = {
        condition_card(1,
                       {cond(31, Axis::table, 150, PassingSense::forward, ActionKind::coolant_on)}),
        table_move(2, 0, 300)};
    cli::PlotSvgRecorder plot("t");
    std::ostringstream lines;
    RunResult r;
    {
        cli::EventsJsonlWriter events(lines);
        relaylogic::ObserverFanOut both;
        both.add(&plot);
        both.add(&events);
        r = run(deck, Pace::fast_forward, &both);
    }
    REQUIRE(r.actions.size() == 1);
    REQUIRE(plot.trips(Axis::table).size() == 1);
    CHECK(plot.trips(Axis::table).at(0).t == r.actions.at(0).tripped_s);
    CHECK(plot.trips(Axis::cross).empty());
    const std::string svg = plot.svg();
    CHECK_THAT(svg, Catch::Contains("class=\"condition-marker\" data-axis=\"table\""));
    CHECK_THAT(svg, Catch::Contains("condition met (EP 0640901)"));
    int met = 0;
    int started = 0;
    int acknowledged = 0;
    std::istringstream in(lines.str());
    for (std::string line; std::getline(in, line);) {
        const auto j = nlohmann::json::parse(line);
        if (!j.contains("id")) {
            continue;
        }
        CHECK(j.at("id") == 31);
        CHECK(j.at("axis") == "table");
        CHECK(j.at("action") == "coolant-on");
        met += j.at("event") == "condition_met" ? 1 : 0;
        started += j.at("event") == "action_started" ? 1 : 0;
        acknowledged += j.at("event") == "action_acknowledged" ? 1 : 0;
    }
    CHECK(met == 1);
    CHECK(started == 1);
    CHECK(acknowledged == 1);
    // A run with no condition met draws no such legend entry.
    cli::PlotSvgRecorder plain("p");
    run({table_move(1, 0, 100)}, Pace::fast_forward, &plain);
    CHECK_THAT(plain.svg(), !Catch::Contains("condition met"));
}
