// Rigid tapping (additions after LinuxCNC G33.1 and the Fanuc G84 family, on the tapping
// attachment of EP 0360190; docs/tapping.md, "Rigid tapping"): the feed's wait for encoder 32's
// index, worked by hand on the built-in profile.
#include "tests/machine_support.hpp"

#include "cardreader/cbn_format.hpp"
#include "cardreader/tap_card.hpp"
#include "cardreader/tap_listing.hpp"
#include "cardreader/tap_review.hpp"
#include "tests/tap_support.hpp"
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

using namespace parsons;
using namespace parsons::cardreader;
using namespace parsons::relaylogic;
using parsons::test::idle_card;
using parsons::test::VectorDeck;

namespace rigid {

axes::MachineProfile profile() {
    axes::MachineProfile p = axes::extended_profile();
    p.press_sync = false; // no press beside the machine: these tests are about the spindle
    return p;
}

CardOrders tap(int number, int depth, int rpm, bool index_wait, int tool = 1) {
    CardOrders c;
    c.kind = CardKind::tap;
    c.number = number;
    c.tap.tool = tool;
    c.tap.axis = Axis::vertical;
    c.tap.motion = Motion::forward;
    c.tap.depth = static_cast<Thousandths>(depth);
    c.tap.pitch = tool == 1 ? 5000 : 6250;
    c.tap.rpm = rpm;
    c.tap.index_wait = index_wait;
    return c;
}

RunResult run(const std::vector<CardOrders>& cards, Pace pace) {
    std::vector<Card> punched;
    for (const auto& o : cards) {
        auto e = encode(o, fig8_layout());
        if (!e) {
            throw std::runtime_error(*e.error);
        }
        punched.push_back(e.card);
    }
    VectorDeck deck(punched);
    ControlCabinet cabinet(profile(), fig8_layout());
    cabinet.set_pace(pace);
    cabinet.record_tap_samples(true);
    return cabinet.run(deck);
}

// The tool's angle, a fraction of a revolution in [0, 1).
double angle(double tool_revs) {
    return tool_revs - std::floor(tool_revs);
}

// How far apart two angles are, the short way round, in revolutions.
double apart(double a, double b) {
    const double d = std::abs(angle(a) - angle(b));
    return std::min(d, 1.0 - d);
}

// Three passes on one hole (no axis moves between them): the thread cut to 0.300 in, deepened
// to 0.450 in at another speed, then chased again to 0.300 in.
std::vector<CardOrders> three_passes(bool index_wait) {
    const std::array<int, 5> home = {0, 0, 0, 0, 0};
    return {idle_card(1, home), tap(2, 300, 240, index_wait), tap(3, 450, 180, index_wait),
            tap(4, 300, 240, index_wait), idle_card(5, home)};
}

} // namespace rigid

TEST_CASE("Rigid tapping: with the index wait every pass into a hole starts its feed at the "
          "same tool angle (within an encoder edge), without it they do not",
          "[tapping][rigid]") {
    // One encoder edge is 1/24 of a motor revolution, 1/96 of a tool revolution through head
    // 1's ratio 1/4.
    const double edge_revs = 0.25 / 24;
    for (Pace pace : {Pace::fast_forward, Pace::impulse_level}) {
        const RunResult waited = rigid::run(rigid::three_passes(true), pace);
        INFO((waited.stop ? waited.stop->message : std::string("completed")));
        REQUIRE(waited.completed);
        const auto& w = waited.tapping->holes;
        REQUIRE(w.size() == 3);
        for (const HoleRecord& h : w) {
            REQUIRE(h.completed);
            REQUIRE(h.index_wait);
            // The index the NC took is one onto a multiple of 4 motor revolutions: head 1 (the
            // only one ever on, mounted at 0) has turned a whole number of revolutions there.
            CHECK(std::abs(h.sync_tool_revs - std::round(h.sync_tool_revs)) < 1e-9);
            CHECK(h.sync_s > h.start_s);
        }
        CHECK(rigid::apart(w[0].sync_tool_revs, w[2].sync_tool_revs) < edge_revs);
        CHECK(rigid::apart(w[0].sync_tool_revs, w[1].sync_tool_revs) < edge_revs);
        // By hand, the first pass: motor 27 stands at count 0 (no index comes there) and runs up
        // at 240 rev/min a second: 1 s to S 240, 2 revolutions; the index at 4 revolutions
        // comes 2 revolutions at 4 rev/s later: 1.5 s after the tool was ready.
        CHECK(w[0].sync_s - w[0].start_s == Approx(1.5).margin(1e-9));
        CHECK(w[0].sync_tool_revs == Approx(1.0).margin(1e-9));

        const RunResult free = rigid::run(rigid::three_passes(false), pace);
        REQUIRE(free.completed);
        const auto& f = free.tapping->holes;
        REQUIRE(f.size() == 3);
        for (const HoleRecord& h : f) {
            CHECK_FALSE(h.index_wait);
            CHECK(h.sync_s == h.start_s); // no wait: the feed counts from the tool ready
        }
        // Without the wait the feed counts from wherever the motor stood: the second and third
        // passes start where the motor came to rest after the pass before.
        INFO("without the wait: " << rigid::apart(f[0].sync_tool_revs, f[1].sync_tool_revs) << ", "
                                  << rigid::apart(f[0].sync_tool_revs, f[2].sync_tool_revs));
        CHECK(rigid::apart(f[0].sync_tool_revs, f[2].sync_tool_revs) > edge_revs);
    }
}

TEST_CASE("Rigid tapping: the index wait is the same machine at both paces, and the pitch cut "
          "after it is the tap's",
          "[tapping][rigid]") {
    const RunResult a = rigid::run(rigid::three_passes(true), Pace::fast_forward);
    const RunResult b = rigid::run(rigid::three_passes(true), Pace::impulse_level);
    REQUIRE(a.completed);
    REQUIRE(b.completed);
    CHECK(a.machine_seconds == b.machine_seconds);
    for (std::size_t i = 0; i < 3; ++i) {
        const HoleRecord& x = a.tapping->holes.at(i);
        const HoleRecord& y = b.tapping->holes.at(i);
        CHECK(x.sync_s == y.sync_s);
        CHECK(x.sync_tool_revs == y.sync_tool_revs);
        CHECK(x.reverse_s == y.reverse_s);
        CHECK(x.end_s == y.end_s);
        // It went to its depth within two thousandths and came back onto its count.
        CHECK(x.deepest_in == Approx(x.depth_in).margin(0.002));
        CHECK(std::abs(x.end_in - x.start_in) < 0.0006);
    }
}

TEST_CASE("Rigid tapping: the index wait round-trips through the card (column 19) and the "
          "listing (the word index), and a bad column 19 or ratio is refused",
          "[tapping][rigid][card]") {
    CardOrders o = rigid::tap(7, 600, 240, true);
    const EncodeResult e = encode(o, fig8_layout());
    REQUIRE(e);
    CHECK(e.card.column(19) == row_bit(Row::r1));
    const DecodeResult d = decode(e.card, fig8_layout());
    REQUIRE(d);
    CHECK(d.orders.tap == o.tap);
    CHECK(tap_row(d.orders) == "7,tap,1,vertical,forward,0.600,0.05000,240,index");
    CHECK(read_tap_row(tap_row(d.orders), "deck.csv", 3).second == o.tap);
    o.tap.index_wait = false;
    CHECK(tap_row(o) == "7,tap,1,vertical,forward,0.600,0.05000,240");
    CHECK_THROWS_WITH(
        read_tap_row("7,tap,1,vertical,forward,0.600,0.05000,240,index,index", "deck.csv", 3),
        Catch::Contains("'index' given twice"));
    CHECK_THROWS_WITH(
        read_tap_row("7,tap,1,vertical,forward,0.600,0.05000,240,wait", "deck.csv", 3),
        Catch::Contains("unknown word 'wait'"));

    Card bad = e.card;
    bad.punch(19, Row::r2); // 1 and 2: not one digit
    CHECK(decode(bad, fig8_layout()).bad_punch->column == 19);
    Card two = encode(rigid::tap(7, 600, 240, false), fig8_layout()).card;
    two.punch(19, Row::r2);
    const DecodeResult d2 = decode(two, fig8_layout());
    REQUIRE(d2.bad_punch);
    CHECK(d2.bad_punch->column == 19);
    CHECK_THAT(d2.bad_punch->what, Catch::Contains("blank") && Catch::Contains("or 1"));

    // A head whose ratio is not 1/n: no index puts its tool at one angle.
    CHECK(motor_revs_per_tool_rev(0.25) == 4);
    CHECK(motor_revs_per_tool_rev(1.0 / 3.0) == 3);
    CHECK_FALSE(motor_revs_per_tool_rev(0.3));
    SpindleLimits limits;
    limits.heads.push_back({4, 0.3, true});
    const TapReview review(true, "parsons-extended", limits);
    CardOrders odd = rigid::tap(8, 600, 100, true, 4);
    const auto found = review.card(2, odd);
    REQUIRE(found.size() == 1);
    CHECK(found.front().column == 19);
    odd.tap.index_wait = false;
    CHECK(review.card(2, odd).empty());
}

TEST_CASE("Rigid tapping: the index wait through punch, convert, show and check",
          "[tapping][rigid][cli]") {
    test::TempDir dir;
    const std::string row = "2,tap,1,vertical,reverse,0.600,0.05000,240,index\n";
    test::write_bytes(dir.path("tap.csv"), test::deck_with(row));
    const auto punched = test::run_parsons("punch " + test::q(dir.str("tap.csv")) + " -o " +
                                           test::q(dir.str("tap.cbn")));
    INFO(punched.output);
    REQUIRE(punched.exit_code == 0);
    const auto back = test::run_parsons("convert " + test::q(dir.str("tap.cbn")) + " -o " +
                                        test::q(dir.str("back.csv")));
    REQUIRE(back.exit_code == 0);
    CHECK_THAT(test::read_bytes(dir.path("back.csv")), Catch::Contains(row));
    const auto shown =
        test::run_parsons("show " + test::q(dir.str("tap.cbn")) + " --profile parsons-extended");
    CHECK(shown.exit_code == 0);
    CHECK_THAT(shown.output,
               Catch::Contains("19       tap index wait 1: the feed waits for encoder 32's index"));

    // Column 19 punched 2 instead of 1: `check` names card 1 and column 19, exit 2.
    CardOrders o = rigid::tap(1, 600, 240, false);
    Card bad = encode(o, fig8_layout()).card;
    bad.punch(19, Row::r2);
    {
        std::ofstream out(dir.path("bad.cbn"), std::ios::binary);
        auto sink = make_cbn_sink(out, "bad.cbn");
        sink->write(bad);
    }
    const auto checked =
        test::run_parsons("check " + test::q(dir.str("bad.cbn")) + " --profile parsons-extended");
    INFO(checked.output);
    CHECK(checked.exit_code == 3); // a bad punch: the reader stops the machine, as siblings do
    CHECK_THAT(checked.output, Catch::Contains("bad_punch: card 1, column 19") &&
                                   Catch::Contains("tap index wait is 2: blank (the feed follows "
                                                   "from the tool's first turn) or 1"));
}
