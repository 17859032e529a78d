// Rigid tapping (additions after LinuxCNC G33.1 and the Fanuc G84 family, on the tapping
// attachment of EP 0360190; docs/tapping.md, "Rigid tapping"): the feed's wait for encoder 32's
// index, worked by hand on the built-in profile.
#include "tests/machine_support.hpp"

#include "cardreader/cbn_format.hpp"
#include "cardreader/tap_card.hpp"
#include "cardreader/tap_listing.hpp"
#include "cardreader/tap_review.hpp"
#include "outputs/proofs/thread_proof.hpp"
#include "tests/tap_support.hpp"
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>

using namespace parsons;
using namespace parsons::cardreader;
using namespace parsons::relaylogic;
using parsons::cli::measure_thread;
using parsons::cli::ThreadGauge;
using parsons::cli::ThreadMeasure;
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

// One tap into 0.400 in at S 120 with tool 1, out at k x S: 0.100 in of clearance above the
// plate (the motor's run-up and run-down there), a thread 0.300 in deep.
std::vector<CardOrders> one_hole(int retract) {
    const std::array<int, 5> home = {0, 0, 0, 0, 0};
    CardOrders t = tap(2, 400, 120, false);
    t.tap.retract = retract;
    return {idle_card(1, home), t, idle_card(3, home)};
}

constexpr double kClearanceIn = 0.100;

// The sample at which the tool last turned: motor 27 at rest at the top.
double at_rest_s(const HoleRecord& h) {
    double rest = 0;
    for (std::size_t i = 1; i < h.samples.size(); ++i) {
        if (h.samples[i].tool_revs != h.samples[i - 1].tool_revs) {
            rest = h.samples[i].t;
        }
    }
    return rest;
}

// The thread the tap leaves on its way out, measured by the thread proof's own arithmetic: the
// samples from the bottom to the end, taken backwards (the tool's turns then climb as going in).
ThreadMeasure way_out(const HoleRecord& h) {
    std::vector<TapSample> out;
    for (auto it = h.samples.rbegin(); it != h.samples.rend() && it->t >= h.reverse_s; ++it) {
        out.push_back(*it);
    }
    ThreadGauge g;
    g.surface_in = h.start_in + h.sense * kClearanceIn;
    g.sense = h.sense;
    g.tap_pitch_in = test::kPitch1;
    g.thread_depth_in = h.depth_in - kClearanceIn;
    return measure_thread(out, g);
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
    const std::string shown = test::tap_row_round_trip(dir, row);
    CHECK_THAT(shown,
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

TEST_CASE("Rigid tapping: the faster retract comes out at k x S with the pitch held, the hole "
          "shorter by the time worked by hand",
          "[tapping][rigid]") {
    // By hand (the built-in profile: motor 27 runs up at 240 rev/min a second, 4 rev/s^2, and
    // down at 320, 16/3 rev/s^2; tool 1: ratio 1/4, pitch 0.05 in, 0.0125 in a motor revolution):
    // 0.400 in is 32 motor revolutions. Going in is the same for both. Out at v rev/s the motor
    // runs up from rest to v (v / 4 s, v^2 / 8 rev), turns at v, and runs down to rest at the
    // top (3v / 16 s, 3v^2 / 32 rev): 32 / v + v / 8 + 3v / 32 s. At S 120 (2 rev/s): 16.4375 s;
    // out at 2 x S (4 rev/s): 8.875 s; the hole 7.5625 s shorter.
    const double saved_by_hand = (32.0 / 2 + 2.0 / 8 + 6.0 / 32) - (32.0 / 4 + 4.0 / 8 + 12.0 / 32);
    CHECK(saved_by_hand == Approx(7.5625));
    for (Pace pace : {Pace::fast_forward, Pace::impulse_level}) {
        const RunResult same = rigid::run(rigid::one_hole(1), pace);
        const RunResult fast = rigid::run(rigid::one_hole(2), pace);
        INFO((fast.stop ? fast.stop->message : std::string("completed")));
        REQUIRE(same.completed);
        REQUIRE(fast.completed);
        const HoleRecord& a = same.tapping->holes.at(0);
        const HoleRecord& b = fast.tapping->holes.at(0);
        REQUIRE(a.completed);
        REQUIRE(b.completed);
        CHECK(a.retract == 1);
        CHECK(b.retract == 2);
        // Going in is the same machine: the reversal at the same instant, the same depth.
        CHECK(b.reverse_s == a.reverse_s);
        CHECK(b.deepest_in == a.deepest_in);
        CHECK(b.deepest_in == Approx(0.400).margin(0.002));
        // Motor 27 comes to rest at the top sooner by the figure by hand, within a sample of
        // interface 33 (the stop near the top is judged at a sample, and the samples tell rest).
        const double motor_saved = rigid::at_rest_s(a) - rigid::at_rest_s(b);
        CHECK(motor_saved == Approx(saved_by_hand).margin(0.05));
        // The hole (tool ready to the feed on its count) within three: the feed then creeps the
        // last of the way at feed_gain_per_s, from a stop called half a sample's turn early
        // (0.15 s here at S, 0.25 s at 2 x S).
        const double saved = (a.end_s - a.start_s) - (b.end_s - b.start_s);
        INFO("hole " << (a.end_s - a.start_s) << " s at S, " << (b.end_s - b.start_s)
                     << " s out at 2 x S; motor " << motor_saved << " s sooner at rest");
        CHECK(saved == Approx(saved_by_hand).margin(0.15));
        CHECK(fast.machine_seconds < same.machine_seconds - 7.4);
        // And back onto its count.
        CHECK(std::abs(b.end_in - b.start_in) < 0.0006);
        // The pitch on the way out: every whole revolution within the proof's 5 %, out at S and
        // at 2 x S alike (the feed follows encoder 32's edges, so it holds at any speed).
        for (const HoleRecord* h : {&a, &b}) {
            const ThreadMeasure m = rigid::way_out(*h);
            INFO("retract " << h->retract << ": worst " << m.worst_error_percent << " % at rev "
                            << m.worst_revolution << "; " << m.not_measured);
            REQUIRE(m.measured);
            CHECK(m.per_revolution_in.size() >= 2); // 0.150 in of full thread: 3 turns
            CHECK(std::abs(m.worst_error_percent) < 5.0);
            CHECK(std::abs(m.mean_error_percent) < 1.0);
        }
    }
    // Impulse level and fast-forward are the same machine out at 2 x S too.
    const RunResult x = rigid::run(rigid::one_hole(2), Pace::fast_forward);
    const RunResult y = rigid::run(rigid::one_hole(2), Pace::impulse_level);
    CHECK(x.machine_seconds == y.machine_seconds);
    CHECK(x.tapping->holes.at(0).end_s == y.tapping->holes.at(0).end_s);
}

TEST_CASE("Rigid tapping: the retract multiple round-trips through the card (column 20) and the "
          "listing (retract=K), and one past motor 27's or the drive's fastest is refused",
          "[tapping][rigid][card]") {
    CardOrders o = rigid::tap(7, 600, 120, true);
    o.tap.retract = 2;
    const EncodeResult e = encode(o, fig8_layout());
    REQUIRE(e);
    CHECK(e.card.column(20) == row_bit(Row::r2));
    const DecodeResult d = decode(e.card, fig8_layout());
    REQUIRE(d);
    CHECK(d.orders.tap == o.tap);
    CHECK(tap_row(d.orders) == "7,tap,1,vertical,forward,0.600,0.05000,120,index,retract=2");
    CHECK(read_tap_row(tap_row(d.orders), "deck.csv", 3).second == o.tap);
    CHECK(read_tap_row("7,tap,1,vertical,forward,0.600,0.05000,120,retract=1", "d.csv", 3)
              .second.retract == 1);
    o.tap.retract = 1; // blank: as before the addition
    CHECK(encode(o, fig8_layout()).card.column(20) == 0);
    CHECK(decode(encode(o, fig8_layout()).card, fig8_layout()).orders.tap.retract == 1);
    CHECK_THROWS_WITH(
        read_tap_row("7,tap,1,vertical,forward,0.600,0.05000,120,retract=5", "deck.csv", 3),
        Catch::Contains("deck.csv:3") && Catch::Contains("retract multiple '5' is not 1..4"));
    CHECK_THROWS_WITH(read_tap_row("7,tap,1,vertical,forward,0.600,0.05000,120,retract=2,"
                                   "retract=3",
                                   "deck.csv", 3),
                      Catch::Contains("'retract=' given twice"));
    o.tap.retract = 5;
    CHECK_FALSE(encode(o, fig8_layout()));

    Card five = encode(rigid::tap(7, 600, 120, false), fig8_layout()).card;
    five.punch(20, Row::r5);
    const DecodeResult d5 = decode(five, fig8_layout());
    REQUIRE(d5.bad_punch);
    CHECK(d5.bad_punch->column == 20);
    CHECK_THAT(d5.bad_punch->what, Catch::Contains("tap retract multiple is 5"));
    Card zero = encode(rigid::tap(7, 600, 120, false), fig8_layout()).card;
    zero.punch(20, Row::r0);
    CHECK(decode(zero, fig8_layout()).bad_punch->column == 20);

    // The review: out at k x S above motor 27's fastest (240), or the feed out above the
    // drive's (5.4 in/min), each at column 20.
    const TapReview review;
    CardOrders fast = rigid::tap(8, 600, 120, false);
    fast.tap.retract = 2; // 240 rev/min, 3.00 in/min: fine
    CHECK(review.card(2, fast).empty());
    fast.tap.retract = 3; // 360 rev/min
    auto found = review.card(2, fast);
    REQUIRE(found.size() == 1);
    CHECK(found.front().column == 20);
    CHECK_THAT(found.front().message,
               Catch::Contains("out at 3 x S 120 = 360 rev/min, above spindle motor 27's "
                               "fastest, 240 rev/min") &&
                   Catch::Contains("at most 2 at that speed"));
    SpindleLimits quick; // a motor twice as fast, the same drive
    quick.max_rpm = 480;
    const TapReview quick_review(true, "quick", quick);
    CardOrders feed = rigid::tap(8, 600, 120, false, 2); // 0.0625 x 1/3 x 120 = 2.50 in/min
    feed.tap.retract = 3;                                // out 7.50 in/min
    found = quick_review.card(2, feed);
    REQUIRE(found.size() == 1);
    CHECK(found.front().column == 20);
    CHECK_THAT(found.front().message, Catch::Contains("out at 360 rev/min the vertical axis must "
                                                      "follow at 7.50 in/min"));
    feed.tap.retract = 2; // 5.00 in/min
    CHECK(quick_review.card(2, feed).empty());

    // The cabinet refuses such a card itself (tap_refused), the review aside.
    CardOrders over = rigid::tap(2, 300, 120, false);
    over.tap.retract = 3;
    const RunResult r = rigid::run({idle_card(1, {0, 0, 0, 0, 0}), over}, Pace::fast_forward);
    REQUIRE(r.stop);
    CHECK(r.stop->reason == StopReason::tap_refused);
    CHECK_THAT(r.stop->message, Catch::Contains("retract multiple 3: out at 360 rev/min"));
}

TEST_CASE("Rigid tapping: the retract multiple through punch, convert, show, check and gen "
          "tapping",
          "[tapping][rigid][cli]") {
    test::TempDir dir;
    const std::string row = "2,tap,1,vertical,reverse,0.600,0.05000,120,retract=2\n";
    const std::string shown = test::tap_row_round_trip(dir, row);
    CHECK_THAT(shown, Catch::Contains("20       tap retract multiple 2: out at 2 x S = 240 "
                                      "rev/min, the feed following"));

    // Out at 3 x S: run and check refuse it by card and column, exit 2.
    test::write_bytes(dir.path("bad.csv"),
                      test::deck_with("2,tap,1,vertical,reverse,0.600,0.05000,120,retract=3\n"));
    for (const char* command : {"run", "check"}) {
        INFO(command);
        const auto out =
            test::run_parsons(std::string(command) + " " + test::q(dir.str("bad.csv")) +
                              " --profile parsons-extended");
        CHECK(out.exit_code == 2);
        CHECK_THAT(out.output, Catch::Contains("bad.csv: card 2, column 20: tap retract multiple "
                                               "3: out at 3 x S 120 = 360 rev/min"));
    }

    // gen tapping --retract 2: S the fastest that comes out within motor 27's 240 rev/min.
    const auto gen = test::run_parsons("gen tapping --profile parsons-extended --retract 2 -o " +
                                       test::q(dir.str("job.csv")));
    INFO(gen.output);
    REQUIRE(gen.exit_code == 0);
    CHECK_THAT(gen.output, Catch::Contains("retract        every tap comes out at 2 x S"));
    const std::string deck = test::read_bytes(dir.path("job.csv"));
    CHECK_THAT(deck, Catch::Contains(",120,retract=2"));
    const auto bad_gen = test::run_parsons("gen tapping --profile parsons-extended --retract 2 "
                                           "--rpm 200 -o " +
                                           test::q(dir.str("job2.csv")));
    CHECK(bad_gen.exit_code == 2);
    CHECK_THAT(bad_gen.output, Catch::Contains("--rpm 200 (out at --retract 2 x S = 400 rev/min)"));
}
