// The tool changer is one machine (condition cards, an addition after EP 0640901; issue 30,
// item 1): a second change waits for the one under way and each acknowledgement puts its own
// tool in the spindle; a change tripped while the spindle is commanded to turn stops the machine
// (tool_change_interlock), one tripped while it runs down waits until it stands; motion cards
// pass through converter UMS and buffer PFR; a condition card's row gives the reader cycle it
// took.
#include "tests/condition_support.hpp"
#include "tests/machine_support.hpp"
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

using namespace parsons;
using namespace parsons::cardreader;
using namespace parsons::relaylogic;
using parsons::test::cond;
using parsons::test::condition_card;
using parsons::test::idle_card;
using parsons::test::table_move;

namespace {

class ChangerWatch : public test::Recorder {
public:
    void on_condition(double t, const ConditionEvent& e) override {
        events.push_back(e);
        times.push_back(t);
    }
    // The tool the acknowledgement of `event` reported in the spindle.
    int tool_at_acknowledgement(int event) const {
        for (const ConditionEvent& e : events) {
            if (e.kind == ConditionEventKind::acknowledged && e.event == event) {
                return e.tool_in_spindle;
            }
        }
        return -1;
    }
    std::vector<ConditionEvent> events;
    std::vector<double> times;
};

RunResult run_changer(const std::vector<CardOrders>& cards, Pace pace,
                      MachineObserver* observer = nullptr) {
    return test::run_conditions(cards, pace, observer);
}

const ActionRecord& action_of(const RunResult& r, int event) {
    const auto it = std::find_if(r.actions.begin(), r.actions.end(),
                                 [event](const ActionRecord& a) { return a.event == event; });
    REQUIRE(it != r.actions.end());
    return *it;
}

} // namespace

TEST_CASE("Tool changer: a second change tripped while the first is under way waits for it, and "
          "each acknowledgement puts its own tool in the spindle",
          "[conditions][tool-changer]") {
    const Pace pace = GENERATE(Pace::fast_forward, Pace::impulse_level);
    INFO("pace " << static_cast<int>(pace));
    const double change_s = axes::extended_profile().actions.tool_change_s;
    // The table runs 0 -> 0.400 at speed 3 (0.01 in/s): tool 2 at 0.150, tool 3 at 0.206,
    // some 5.6 s later, well inside the first change's 8 s.
    ChangerWatch watch;
    const RunResult r = run_changer(
        {condition_card(
             1, {cond(4, Axis::table, 150, PassingSense::forward, ActionKind::tool_change, 2),
                 cond(5, Axis::table, 206, PassingSense::forward, ActionKind::tool_change, 3)}),
         table_move(2, 0, 400), table_move(3, 400, 300)},
        pace, &watch);
    REQUIRE(r.completed);
    const ActionRecord& first = action_of(r, 4);
    const ActionRecord& second = action_of(r, 5);
    REQUIRE(second.tripped_s - first.tripped_s < change_s); // the changer is busy at the trip
    CHECK(second.tripped_s - first.tripped_s == Approx(5.6).margin(0.2));
    CHECK(first.acknowledged_s == Approx(first.tripped_s + change_s).margin(1e-9));
    // The second begins when the changer is free, not at its trip.
    CHECK(second.acknowledged_s == Approx(first.acknowledged_s + change_s).margin(1e-9));
    CHECK(watch.tool_at_acknowledgement(4) == 2);
    CHECK(watch.tool_at_acknowledgement(5) == 3);
    CHECK(r.tool_in_spindle == 3);
    // The trace: tool 3 waits from its trip to the first acknowledgement, then is put in.
    const auto waiting = watch.of("conditions.tool_changer.waiting");
    REQUIRE(waiting.size() >= 2);
    CHECK(waiting.at(0).new_value == 1);
    CHECK(waiting.at(0).t == Approx(second.tripped_s).margin(1e-9));
    CHECK(waiting.at(1).new_value == 0);
    CHECK(waiting.at(1).t == Approx(first.acknowledged_s).margin(1e-9));
    std::vector<std::uint32_t> changing;
    for (const test::Change& c : watch.of("conditions.tool_changer.changing")) {
        changing.push_back(c.new_value);
    }
    CHECK(changing == std::vector<std::uint32_t>{2, 3, 0});
    std::vector<std::uint32_t> in_spindle;
    for (const test::Change& c : watch.of("conditions.tool_changer.in_spindle")) {
        in_spindle.push_back(c.new_value);
    }
    CHECK(in_spindle == std::vector<std::uint32_t>{2, 3});
}

TEST_CASE("Tool changer: a change tripped while the spindle is commanded to turn stops the "
          "machine (tool_change_interlock) with the condition card's column, and one tripped "
          "while it runs down waits until it stands",
          "[conditions][tool-changer]") {
    const Pace pace = GENERATE(Pace::fast_forward, Pace::impulse_level);
    INFO("pace " << static_cast<int>(pace));
    const axes::MachineProfile profile = axes::extended_profile();
    SECTION("column 1 orders the spindle forward: the machine stops at the trip") {
        ChangerWatch watch;
        const RunResult r = run_changer(
            {condition_card(
                 1, {cond(3, Axis::table, 100, PassingSense::forward, ActionKind::lamp, 1),
                     cond(4, Axis::table, 150, PassingSense::forward, ActionKind::tool_change, 2)}),
             table_move(2, 0, 400, Spindle::forward), table_move(3, 400, 300)},
            pace, &watch);
        REQUIRE(r.stop);
        CHECK(r.stop->reason == StopReason::tool_change_interlock);
        CHECK(r.stop->card == 2);
        // The second slot: its action digit is column 1 + 15 + 8.
        CHECK_THAT(r.stop->message, Catch::Contains("event 4 (card 1, column 24: tool change to "
                                                    "tool 2)"));
        CHECK_THAT(r.stop->message, Catch::Contains("column 1 of card 2 orders it forward"));
        CHECK(test::Recorder::counter(watch.value, "table") == 150);
        CHECK(r.tool_in_spindle == profile.first_tool); // the changer never started
        CHECK(watch.value.at("conditions.tool_changer.changing") == 0);
    }
    SECTION("a spindle-stop action before it: the change begins when the spindle stands") {
        ChangerWatch watch;
        // Card 2 orders forward; the stop action trips at 0.100, the change 1 s later at 0.110,
        // inside the motor's 2-s run-down.
        const RunResult r = run_changer(
            {condition_card(
                 1, {cond(3, Axis::table, 100, PassingSense::forward, ActionKind::spindle_stop),
                     cond(4, Axis::table, 110, PassingSense::forward, ActionKind::tool_change, 2)}),
             table_move(2, 0, 400, Spindle::forward), table_move(3, 400, 300)},
            pace, &watch);
        REQUIRE(r.completed);
        const ActionRecord& stop = action_of(r, 3);
        const ActionRecord& change = action_of(r, 4);
        REQUIRE(change.tripped_s < stop.tripped_s + profile.actions.spindle_run_down_s);
        CHECK(change.acknowledged_s == Approx(stop.tripped_s + profile.actions.spindle_run_down_s +
                                              profile.actions.tool_change_s)
                                           .margin(1e-9));
        CHECK(r.tool_in_spindle == 2);
    }
}

TEST_CASE("Tool changer: run and check stop a deck whose tool change trips while the spindle "
          "turns, naming the condition card's column (exit 3)",
          "[conditions][tool-changer][cli]") {
    test::TempDir dir;
    const std::string deck = dir.str("interlock.csv");
    test::write_bytes(deck, std::string(test::kHeader) + "1,if,4,table,+,0.150,tool-change,2\n" +
                                "2,0,table,+,3,,,0.400,0.400,1\n" + test::idle_rest(2));
    for (const char* command : {"run", "check"}) {
        INFO(command);
        const auto r = test::run_parsons(std::string(command) + " " + test::q(deck) +
                                         " --profile parsons-extended");
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.output, Catch::Contains("tool_change_interlock"));
        CHECK_THAT(r.output, Catch::Contains("card 1, column 9"));
    }
}

TEST_CASE("Condition cards (claim 1): every motion card passes through converter UMS and buffer "
          "PFR, entered as it is sensed, supplied as its relays pick, cleared at zeroizing",
          "[conditions][claims]") {
    const Pace pace = GENERATE(Pace::fast_forward, Pace::impulse_level);
    INFO("pace " << static_cast<int>(pace));
    const bool conditions = GENERATE(true, false);
    INFO("a condition card in the deck: " << conditions);
    std::vector<CardOrders> deck;
    if (conditions) {
        deck.push_back(condition_card(
            1, {cond(4, Axis::table, 150, PassingSense::forward, ActionKind::lamp, 2)}));
    } else {
        deck.push_back(idle_card(1, {0, 0, 0, 0, 0}));
    }
    deck.push_back(table_move(2, 0, 400));
    deck.push_back(table_move(3, 400, 300));
    ChangerWatch watch;
    const RunResult r = run_changer(deck, pace, &watch);
    REQUIRE(r.completed);
    std::vector<std::uint32_t> states;
    std::vector<double> at;
    for (const test::Change& c : watch.of("conditions.buffer_pfr.motion.state")) {
        states.push_back(c.new_value);
        at.push_back(c.t);
    }
    // The idle card 1 of the plain deck is a motion card too.
    const std::vector<std::uint32_t> card = {1, 2, 0};
    std::vector<std::uint32_t> expected;
    for (int i = 0; i < (conditions ? 2 : 3); ++i) {
        expected.insert(expected.end(), card.begin(), card.end());
    }
    CHECK(states == expected);
    std::vector<std::uint32_t> numbers;
    for (const test::Change& c : watch.of("conditions.buffer_pfr.motion.card")) {
        if (c.new_value != 0) {
            numbers.push_back(c.new_value);
        }
    }
    CHECK(numbers ==
          (conditions ? std::vector<std::uint32_t>{2, 3} : std::vector<std::uint32_t>{1, 2, 3}));
    // Supplied as the relays pick: the instant the condition is armed on PRG.
    if (conditions) {
        const auto armed = watch.of("conditions.buffer_pfr.pair_0.state");
        REQUIRE(armed.size() >= 2);
        CHECK(armed.at(1).new_value == 2);
        CHECK(armed.at(1).t == at.at(1));
        CHECK(at.at(0) < at.at(1)); // entered at the first bank, before the relays pick
    }
}

TEST_CASE("Condition cards: a condition card's row gives the reader cycle it took, in the run "
          "and in the report",
          "[conditions][report]") {
    const axes::MachineProfile profile = axes::extended_profile();
    const RunResult r = run_changer(
        {condition_card(1, {cond(4, Axis::table, 150, PassingSense::forward, ActionKind::lamp, 2)}),
         table_move(2, 0, 400)},
        Pace::fast_forward);
    REQUIRE(r.completed);
    REQUIRE(r.cards.size() == 2);
    CHECK(r.cards.at(0).end_s - r.cards.at(0).start_s ==
          Approx(profile.reader_cycle_s).margin(1e-9));
    CHECK(r.cards.at(1).start_s == r.cards.at(0).end_s);
    // The report of the shipped sample: every card, condition card included, took time.
    test::TempDir dir;
    const auto run =
        test::run_parsons("run " + test::q(test::source_path("decks/samples/condition-cards.csv")) +
                          " --profile parsons-extended --report " + test::q(dir.str("r.json")));
    REQUIRE(run.exit_code == 0);
    const auto report = nlohmann::json::parse(test::read_bytes(dir.path("r.json")));
    REQUIRE(report["cards"].size() == 5);
    for (const auto& c : report["cards"]) {
        INFO(c.dump());
        CHECK(c["machine_seconds"].get<double>() > 0);
    }
}
