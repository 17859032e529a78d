// The every-condition: an addition beyond EP 0640901's claims (after Siemens' later synchronized
// actions WHENEVER/EVERY; docs/condition-cards.md, "A condition that stays armed"). It stays in
// buffer PFR across motion cards, is armed on each and fires on each card whose counter steps
// onto its position in its sense, until a cancel ends it. Worked by hand: the table runs out and
// back over 0.200; the every-condition watches it counting up.
#include "tests/condition_support.hpp"
#include "tests/machine_support.hpp"
#include "tests/test_support.hpp"

#include "cardreader/condition_card.hpp"
#include "cardreader/deck_error.hpp"
#include "cardreader/deck_review.hpp"
#include "cardreader/listing_format.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <sstream>

using namespace parsons;
using namespace parsons::cardreader;
using namespace parsons::relaylogic;
using parsons::test::cond;
using parsons::test::condition_card;
using parsons::test::idle_card;
using parsons::test::punched;
using parsons::test::table_move;

namespace {

ConditionOrder every(ConditionOrder c) {
    c.mode = ConditionMode::every;
    return c;
}

ConditionOrder cancel(int event) {
    ConditionOrder c;
    c.event = event;
    c.mode = ConditionMode::cancel;
    return c;
}

class Firings : public test::Recorder {
public:
    void on_condition(double /*t*/, const ConditionEvent& e) override {
        if (e.kind == ConditionEventKind::met) {
            met_on.push_back(e.card);
            firing.push_back(e.firing);
        }
    }
    std::vector<std::int64_t> met_on;
    std::vector<int> firing;
};

// Event 1: every time the table's counter steps onto 0.200 counting up, light lamp 1. The table
// crosses 0.200 upward on cards 2, 4 and 6 (0 -> 0.300, 0.100 -> 0.300, 0.100 -> 0.250) and
// downward on 3, 5 and 8; card 7 is the cancel (or, in `kept`, an idle card that moves nothing);
// card 9 crosses upward once more.
std::vector<CardOrders> out_and_back(bool cancelled) {
    return {condition_card(
                1, {every(cond(1, Axis::table, 200, PassingSense::forward, ActionKind::lamp, 1))}),
            table_move(2, 0, 300),
            table_move(3, 300, 100),
            table_move(4, 100, 300),
            table_move(5, 300, 100),
            table_move(6, 100, 250),
            cancelled ? condition_card(7, {cancel(1)}) : idle_card(7, {250, 0, 0, 0, 0}),
            table_move(8, 250, 100),
            table_move(9, 100, 300)};
}

} // namespace

TEST_CASE("Every-condition: fires on each crossing in its sense, N times on N crossings, and not "
          "on a card after its cancel",
          "[conditions][every]") {
    const Pace pace = GENERATE(Pace::fast_forward, Pace::impulse_level);
    INFO("pace " << static_cast<int>(pace));
    const axes::MachineProfile profile = axes::extended_profile();
    Firings cancelled_watch;
    const RunResult cancelled = test::run_conditions(out_and_back(true), pace, &cancelled_watch);
    REQUIRE(cancelled.completed);
    // Three upward crossings before the cancel: cards 2, 4, 6; none on the downward cards 3, 5,
    // 8, none on card 9 after the cancel.
    CHECK(cancelled_watch.met_on == std::vector<std::int64_t>{2, 4, 6});
    CHECK(cancelled_watch.firing == std::vector<int>{1, 2, 3});
    REQUIRE(cancelled.actions.size() == 3);
    for (std::size_t i = 0; i < 3; ++i) {
        const ActionRecord& a = cancelled.actions.at(i);
        CHECK(a.every);
        CHECK(a.firing == static_cast<int>(i) + 1);
        CHECK(a.event == 1);
        CHECK(a.condition_card == 1);
        CHECK(a.motion_card == static_cast<std::int64_t>(2 * i + 2));
        // Each firing is acknowledged as the once-condition's action is: lamp_s after its trip.
        CHECK(a.acknowledged_s - a.tripped_s == Approx(profile.actions.lamp_s));
    }
    // Without the cancel (card 7 an idle card, which leaves the table standing: no error for
    // an every-condition) it stays armed and fires a fourth time on card 9.
    Firings kept_watch;
    const RunResult kept = test::run_conditions(out_and_back(false), pace, &kept_watch);
    REQUIRE(kept.completed);
    CHECK(kept_watch.met_on == std::vector<std::int64_t>{2, 4, 6, 9});
    REQUIRE(kept.actions.size() == 4);
    CHECK(kept.actions.at(3).firing == 4);
    // The same condition once (the seed's) fires on card 2 only.
    std::vector<CardOrders> once = out_and_back(false);
    once.at(0).conditions.at(0).mode = ConditionMode::once;
    const RunResult single = test::run_conditions(once, pace);
    REQUIRE(single.completed);
    REQUIRE(single.actions.size() == 1);
    CHECK_FALSE(single.actions.at(0).every);
    CHECK(single.actions.at(0).motion_card == 2);
}

TEST_CASE("Every-condition: the cabinet refuses a cancel with no every-condition and an "
          "identifier reused while it stands",
          "[conditions][every]") {
    const std::vector<CardOrders> stray = {condition_card(1, {cancel(4)}), table_move(2, 0, 300)};
    const RunResult r = test::run_conditions(stray, Pace::fast_forward);
    REQUIRE(r.stop);
    CHECK(r.stop->reason == StopReason::condition_refused);
    CHECK_THAT(r.stop->message, Catch::Contains("card 1, column 14: a cancel of event 4"));
    const std::vector<CardOrders> reused = {
        condition_card(
            1, {every(cond(1, Axis::table, 200, PassingSense::forward, ActionKind::lamp, 1))}),
        table_move(2, 0, 300),
        condition_card(3, {cond(1, Axis::table, 100, PassingSense::reverse, ActionKind::lamp, 2)}),
        table_move(4, 300, 50)};
    const RunResult again = test::run_conditions(reused, Pace::fast_forward);
    REQUIRE(again.stop);
    CHECK(again.stop->reason == StopReason::condition_refused);
    CHECK(again.stop->card == 3);
    CHECK_THAT(again.stop->message, Catch::Contains("event 1 stands as an every-condition"));
    // The deck review says both before anything moves, by card and column.
    DeckReviewer reviewer;
    reviewer.allow_conditions(true, "parsons-extended");
    std::vector<ReviewNote> notes;
    for (const CardOrders& o : {stray.at(0), stray.at(1)}) {
        for (auto& n : reviewer.review(o)) {
            notes.push_back(n);
        }
    }
    DeckReviewer second;
    second.allow_conditions(true, "parsons-extended");
    for (const CardOrders& o : reused) {
        for (auto& n : second.review(o)) {
            notes.push_back(n);
        }
    }
    // An every-condition standing at the deck's end is no error; one never armed is (claim 4).
    for (auto& n : second.finish()) {
        notes.push_back(n);
    }
    REQUIRE(notes.size() == 2);
    CHECK(notes.at(0).card == 1);
    CHECK(notes.at(0).column == 14);
    CHECK(notes.at(1).card == 3);
    CHECK(notes.at(1).column == 1);
    DeckReviewer last;
    last.allow_conditions(true, "parsons-extended");
    CHECK(last.review(out_and_back(true).at(0)).empty());
    const auto end = last.finish();
    REQUIRE(end.size() == 1);
    CHECK(end.at(0).column == 76);
}

TEST_CASE("Every-condition: punched in column 14 (row 1 every, row 2 cancel), listed with its "
          "mode and read back, and a bad mode or a cancel with more punched is a bad punch",
          "[conditions][every][card]") {
    const CardOrders card = condition_card(
        7, {every(cond(1, Axis::table, 200, PassingSense::forward, ActionKind::lamp, 1)), cancel(3),
            cond(4, Axis::cross, 100, PassingSense::either, ActionKind::coolant_on)});
    const EncodeResult e = encode(card, fig8_layout());
    REQUIRE(e);
    const Card& c = e.card;
    CHECK(c.column(14) == row_bit(Row::r1)); // slot 1: every
    CHECK(c.column(15) == 0);
    CHECK(c.punched(16, Row::r0)); // slot 2: event 03 ...
    CHECK(c.punched(17, Row::r3));
    for (int col = 18; col <= 28; ++col) {
        CHECK(c.column(col) == 0); // ... and nothing else but its mode
    }
    CHECK(c.column(29) == row_bit(Row::r2)); // slot 2: cancel
    CHECK(c.column(44) == 0);                // slot 3: once, blank
    const DecodeResult d = decode(c, fig8_layout());
    REQUIRE(d);
    CHECK(d.orders == card);
    std::ostringstream text;
    {
        DeckOptions options;
        options.format = DeckFormat::listing;
        auto sink = open_card_sink(text, options);
        sink->write(c);
    }
    CHECK_THAT(text.str(), Catch::Contains("7,if,1,table,+,0.200,lamp,1,every\n7,if,3,cancel\n"
                                           "7,if,4,cross,*,0.100,coolant-on,\n"));
    std::istringstream in(text.str());
    ListingReader reader(in, "t.csv");
    const auto back = reader.next();
    REQUIRE(back);
    CHECK(back->orders == card);

    // Bad punches, by column.
    struct Case {
        std::function<void(Card&)> spoil;
        int column;
        std::string says;
    };
    const std::vector<Case> cases = {
        {[](Card& k) { k.set_column(14, row_bit(Row::r3)); }, 14, "condition 1 mode is 3"},
        {[](Card& k) { k.set_column(14, row_bit(Row::r1) | row_bit(Row::r2)); }, 14,
         "condition 1 mode is punched in rows"},
        {[](Card& k) { k.punch(20, Row::r5); }, 20, "condition 2 is a cancel"},
        {[](Card& k) { k.set_column(45, row_bit(Row::r1)); }, 45, "column 45"},
    };
    for (const Case& k : cases) {
        INFO(k.says);
        Card bad = c;
        k.spoil(bad);
        const DecodeResult r = decode(bad, fig8_layout());
        REQUIRE(r.bad_punch);
        CHECK(r.bad_punch->column == k.column);
        CHECK_THAT(r.bad_punch->what, Catch::Contains(k.says));
    }
    // The listing's: a mode that is not once or every, a cancel row with more fields.
    for (const auto& [rows, says] : std::vector<std::pair<std::string, std::string>>{
             {"1,if,7,table,+,1.000,lamp,1,always\n", "t.csv:2: mode 'always'"},
             {"1,if,7,cancel,1\n", "or 4 for a cancel"}}) {
        INFO(rows);
        std::istringstream bad(std::string(kListingHeader) + "\n" + rows);
        ListingReader r(bad, "t.csv");
        std::string message = "no error";
        try {
            while (r.next()) {
            }
        } catch (const DeckError& x) {
            message = x.what();
        }
        CHECK_THAT(message, Catch::Contains(says));
    }
}

TEST_CASE("Every-condition: a saved state keeps it armed with its firings, and the resumed run "
          "fires as a run straight through",
          "[conditions][every][resume]") {
    const Pace pace = GENERATE(Pace::fast_forward, Pace::impulse_level);
    INFO("pace " << static_cast<int>(pace));
    const std::vector<CardOrders> good = out_and_back(true);
    std::vector<CardOrders> bad = good;
    bad.at(4).axis(Axis::table).check = 199; // card 5 one short: the machine stops on it
    const axes::MachineProfile profile = axes::extended_profile();
    test::VectorDeck faulty(punched(bad));
    ControlCabinet first(profile, fig8_layout());
    first.set_pace(pace);
    first.record_card_times(true);
    first.keep_resume_point(true);
    const RunResult stopped = first.run(faulty);
    REQUIRE(stopped.stop);
    CHECK(stopped.stop->card == 5);
    const auto saved = nlohmann::json::parse(first.resume_point().dump());
    const auto& pair = saved.at("conditions").at("buffer_pfr").at(0);
    CHECK(pair.at("state") == 1); // stored again for card 5
    CHECK(pair.at("every") == true);
    CHECK(pair.at("firings") == 2); // fired on cards 2 and 4

    const RunResult whole = test::run_conditions(good, pace);
    REQUIRE(whole.completed);
    test::VectorDeck again(punched(good));
    ControlCabinet resumed(profile, fig8_layout());
    resumed.set_pace(pace);
    resumed.record_card_times(true);
    resumed.resume(saved);
    const RunResult rest = resumed.run(again);
    REQUIRE(rest.completed);
    CHECK(rest.machine_seconds == whole.machine_seconds);
    REQUIRE(rest.actions.size() == 3);
    for (std::size_t i = 0; i < 3; ++i) {
        CHECK(rest.actions.at(i).firing == whole.actions.at(i).firing);
        CHECK(rest.actions.at(i).tripped_s == whole.actions.at(i).tripped_s);
    }
}

TEST_CASE("Every-condition: the sample deck fires twice, punch and show keep its mode, and run "
          "refuses a stray cancel with exit 2 naming card and column",
          "[conditions][every][cli]") {
    test::TempDir dir;
    const std::string deck = test::source_path("decks/samples/every-condition.csv");
    const auto ran = test::run_parsons("run " + test::q(deck) + " --profile parsons-extended");
    CHECK(ran.exit_code == 0);
    CHECK_THAT(ran.output, Catch::Contains("card 2, every: firing 1"));
    CHECK_THAT(ran.output, Catch::Contains("card 4, every: firing 2"));
    CHECK_THAT(ran.output, !Catch::Contains("firing 3"));
    const auto punched_deck =
        test::run_parsons("punch " + test::q(deck) + " -o " + test::q(dir.str("every.cbn")));
    REQUIRE(punched_deck.exit_code == 0);
    const auto shown =
        test::run_parsons("show " + test::q(dir.str("every.cbn")) + " --profile parsons-extended");
    CHECK(shown.exit_code == 0);
    CHECK_THAT(shown.output,
               Catch::Contains("every (column 14 row 1): armed for every motion card"));
    CHECK_THAT(shown.output, Catch::Contains("cancel (column 14 row 2): ends every-condition 1"));
    std::string text = test::read_bytes(deck);
    const auto at = text.find("6,if,1,cancel");
    REQUIRE(at != std::string::npos);
    text.replace(at, 13, "6,if,4,cancel");
    test::write_bytes(dir.path("stray.csv"), text);
    const auto refused = test::run_parsons("run " + test::q(dir.str("stray.csv")) +
                                           " -q --profile parsons-extended");
    CHECK(refused.exit_code == 2);
    CHECK_THAT(refused.output,
               Catch::Contains("stray.csv: card 6, column 14: condition 1: a cancel "
                               "of event 4"));
}
