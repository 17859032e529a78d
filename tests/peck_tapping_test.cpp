// Rigid peck tapping (an addition after LinuxCNC and Fanuc G84 with Q, on the tapping attachment
// of EP 0360190; docs/tapping.md, "Peck tapping (columns 21-24)"): in to Q, out to the starting
// count, in to 2Q, ... to the depth, the feed on one helix throughout; worked by hand on the
// built-in profile.
#include "tests/machine_support.hpp"

#include "cardreader/tap_card.hpp"
#include "cardreader/tap_listing.hpp"
#include "outputs/proofs/thread_proof.hpp"
#include "tests/tap_support.hpp"
#include "tests/test_support.hpp"

#include <catch2/catch.hpp>

#include <nlohmann/json.hpp>

#include <cmath>

using namespace parsons;
using namespace parsons::cardreader;
using namespace parsons::relaylogic;
using parsons::test::idle_card;
using parsons::test::VectorDeck;

namespace peck {

axes::MachineProfile profile() {
    axes::MachineProfile p = axes::extended_profile();
    p.press_sync = false; // no press beside the machine: these tests are about the spindle
    return p;
}

// A tap with tool 1 (ratio 1/4, pitch 0.05 in) into `depth` at S, pecking `q` (0: one pass).
CardOrders tap(int number, int depth, int rpm, int q) {
    CardOrders c;
    c.kind = CardKind::tap;
    c.number = number;
    c.tap.tool = 1;
    c.tap.axis = Axis::vertical;
    c.tap.motion = Motion::forward;
    c.tap.depth = static_cast<Thousandths>(depth);
    c.tap.pitch = 5000;
    c.tap.rpm = rpm;
    c.tap.peck = static_cast<Thousandths>(q);
    return c;
}

RunResult run(const CardOrders& card, Pace pace) {
    const std::array<int, 5> home = {0, 0, 0, 0, 0};
    std::vector<Card> punched;
    for (const auto& o : {idle_card(1, home), card, idle_card(3, home)}) {
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

RunResult run(int depth, int q, Pace pace) {
    return run(tap(2, depth, 120, q), pace);
}

// One pass into the hole as the samples show it: from the sample the tool first turned to the
// one it stood again.
struct Pass {
    std::size_t first = 0; // the sample before the tool's first turn of the pass
    std::size_t last = 0;  // the sample it stood again (at rest at the top)
    double deepest_in = 0; // along the sense, from the tap's start
};

std::vector<Pass> passes(const HoleRecord& h) {
    std::vector<Pass> out;
    bool moving = false;
    for (std::size_t i = 1; i < h.samples.size(); ++i) {
        const bool turned = h.samples[i].tool_revs != h.samples[i - 1].tool_revs;
        if (turned && !moving) {
            out.push_back({i - 1, i, 0.0});
        }
        if (turned) {
            out.back().last = i;
            out.back().deepest_in =
                std::max(out.back().deepest_in, h.sense * (h.samples[i].feed_in - h.start_in));
        }
        moving = turned;
    }
    return out;
}

// Where the feed stands (along the sense, from the tap's start) the sample before the pass.
double before(const HoleRecord& h, const Pass& p) {
    return h.sense * (h.samples[p.first].feed_in - h.start_in);
}

// The helix a pass cuts going in: the feed's depth at each sample whose tool turned further in,
// against the tool's revolutions since the tap began.
std::vector<std::pair<double, double>> going_in(const HoleRecord& h, const Pass& p) {
    std::vector<std::pair<double, double>> pts;
    for (std::size_t i = p.first + 1; i <= p.last; ++i) {
        if (h.samples[i].tool_revs > h.samples[i - 1].tool_revs) {
            pts.emplace_back(h.samples[i].tool_revs - h.sync_tool_revs,
                             h.sense * (h.samples[i].feed_in - h.start_in));
        }
    }
    return pts;
}

// The depth pass `pts` had at `revs` (linear between its samples; NaN outside them).
double depth_at(const std::vector<std::pair<double, double>>& pts, double revs) {
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
        const auto& [r0, d0] = pts[i];
        const auto& [r1, d1] = pts[i + 1];
        if (r0 <= revs && revs <= r1 && r1 > r0) {
            return d0 + (revs - r0) / (r1 - r0) * (d1 - d0);
        }
    }
    return std::nan("");
}

// The sample at which the tool last turned: motor 27 at rest at the top.
double at_rest_s(const HoleRecord& h) {
    return h.samples.at(passes(h).back().last).t;
}

} // namespace peck

TEST_CASE("Peck tapping: 0.300 in pecked 0.100 in goes in three times, to 0.1, 0.2 and 0.3, "
          "back on its count between, each pass on the first one's helix",
          "[tapping][rigid][peck]") {
    for (Pace pace : {Pace::fast_forward, Pace::impulse_level}) {
        const RunResult r = peck::run(300, 100, pace);
        INFO((r.stop ? r.stop->message : std::string("completed")));
        REQUIRE(r.completed);
        const HoleRecord& h = r.tapping->holes.at(0);
        REQUIRE(h.completed);
        CHECK(h.peck_in == 0.1);
        CHECK(h.pecks == 3);
        const std::vector<peck::Pass> ps = peck::passes(h);
        REQUIRE(ps.size() == 3);
        for (std::size_t i = 0; i < ps.size(); ++i) {
            INFO("pass " << i + 1 << ": deepest " << ps[i].deepest_in << ", stood at "
                         << peck::before(h, ps[i]));
            // To its depth within the two thousandths of the other rigid-tapping tests, having
            // started from the tap's starting count (the feed settled there between passes).
            CHECK(ps[i].deepest_in == Approx(0.1 * static_cast<double>(i + 1)).margin(0.002));
            CHECK(std::abs(peck::before(h, ps[i])) < 0.0006);
        }
        CHECK(h.deepest_in == Approx(0.300).margin(0.002));
        CHECK(std::abs(h.end_in - h.start_in) < 0.0006);
        // The thread in phase: going in, passes 2 and 3 put the feed where pass 1 (and pass 2)
        // had it at the same turn of the tool, within the 5 % of the pitch the thread on the way
        // out is held to; in fact within a small part of that (the feed's lag, the same each
        // pass, since z_cmd counts on from the tap's start).
        const auto first = peck::going_in(h, ps[0]);
        double worst = 0;
        std::size_t compared = 0;
        for (std::size_t k = 1; k < ps.size(); ++k) {
            const auto before_it = peck::going_in(h, ps[k - 1]);
            for (const auto& [revs, depth] : peck::going_in(h, ps[k])) {
                // Past the run-up (a quarter turn of the tool in), where the earlier pass was
                // also at speed; the earlier pass's run-down to its bottom is left out too.
                const double other = peck::depth_at(before_it, revs);
                if (revs < 0.25 || std::isnan(other) || depth > ps[k - 1].deepest_in - 0.02) {
                    continue;
                }
                worst = std::max(worst, std::abs(depth - other));
                ++compared;
            }
        }
        INFO("pass against pass, going in: worst " << worst << " in over " << compared
                                                   << " samples; pass 1 has " << first.size());
        CHECK(compared > 50);
        CHECK(worst < 0.05 * test::kPitch1);
        // Measured: 0.0006 in (1.2 % of the pitch). A feed that counted afresh from each pass's
        // start would be off by the tool's stop short of the top, 0.0025 in (5 %).
        CHECK(worst < 0.02 * test::kPitch1);
        // The helix itself: the depth is the tool's turns times the pitch, every pass.
        for (const peck::Pass& p : ps) {
            for (const auto& [revs, depth] : peck::going_in(h, p)) {
                if (revs > 0.25 && depth < p.deepest_in - 0.02) {
                    CHECK(std::abs(depth - revs * test::kPitch1) < 0.02 * test::kPitch1);
                }
            }
        }
        // The thread proof, which reads the union of the passes going in: every revolution
        // within its 5 %.
        cli::ThreadGauge g;
        g.surface_in = h.start_in; // the tool at speed within 0.007 in of the start
        g.sense = h.sense;
        g.tap_pitch_in = test::kPitch1;
        g.thread_depth_in = 0.300;
        const cli::ThreadMeasure m = cli::measure_thread(h.samples, g);
        INFO("proof: worst " << m.worst_error_percent << " %, " << m.not_measured);
        REQUIRE(m.measured);
        CHECK(std::abs(m.worst_error_percent) < 5.0);
    }
}

TEST_CASE("Peck tapping: both paces are the same machine, and the pecks cost the extra travel "
          "and run-ups worked by hand",
          "[tapping][rigid][peck]") {
    // By hand (motor 27 runs up at 4 rev/s^2, down at 16/3 rev/s^2; tool 1 feeds 0.0125 in a
    // motor revolution): a pass into D and out at S 120 (v = 2 rev/s) turns the motor N = D /
    // 0.0125 revolutions each way, N / v + v / 8 + 3v / 32 s each way: N + 0.875 s. One pass to
    // 0.300 in (N 24): 24.875 s; pecked 0.100 in (N 8, 16, 24): 50.625 s, 25.75 s more (0.600
    // in more of travel, 24 s, and two more run-ups and run-downs, 1.75 s). Each pass but the
    // last also waits at the top for the feed to settle onto its count, as the last one does
    // before the card ends. The run-out stops the motor short of the top, as it always has:
    // judged at a sample from the edges of the sample (2 or 3 at S 120, read as 2.4 or 3.6 rev/s)
    // it stood 0.2 motor revolution (0.0025 in of feed) short, 0.1 s at v; the next pass starts
    // there, so each extra pass is 0.2 s shorter: 25.75 - 0.4 = 25.35 s.
    const double more_by_hand = (8 + 0.875) + (16 + 0.875) - 2 * (2 * 0.2 / 2);
    CHECK(more_by_hand == Approx(25.35));
    const RunResult one = peck::run(300, 0, Pace::fast_forward);
    const RunResult three = peck::run(300, 100, Pace::fast_forward);
    const RunResult three_b = peck::run(300, 100, Pace::impulse_level);
    REQUIRE(one.completed);
    REQUIRE(three.completed);
    REQUIRE(three_b.completed);
    const HoleRecord& a = one.tapping->holes.at(0);
    const HoleRecord& b = three.tapping->holes.at(0);
    const HoleRecord& c = three_b.tapping->holes.at(0);
    CHECK(a.pecks == 1);
    CHECK(a.peck_in == 0);
    // The same machine at both paces.
    CHECK(three.machine_seconds == three_b.machine_seconds);
    CHECK(b.reverse_s == c.reverse_s);
    CHECK(b.end_s == c.end_s);
    CHECK(b.deepest_in == c.deepest_in);
    CHECK(b.pecks == c.pecks);
    // Motor 27's turning time (tool ready to at rest at the top, less the settles between the
    // passes) longer by the figure by hand, within a sample of interface 33 a pass.
    const auto ps = peck::passes(b);
    REQUIRE(ps.size() == 3);
    double settles = 0;
    for (std::size_t i = 1; i < ps.size(); ++i) {
        settles += b.samples[ps[i].first].t - b.samples[ps[i - 1].last].t;
    }
    const double turning =
        (peck::at_rest_s(b) - b.start_s - settles) - (peck::at_rest_s(a) - a.start_s);
    const double settle_one = a.end_s - peck::at_rest_s(a);
    INFO("turning " << turning << " s more; settles between " << settles << " s (one pass's "
                    << settle_one << " s); the hole " << (b.end_s - b.start_s) << " s against "
                    << (a.end_s - a.start_s) << " s; machine " << three.machine_seconds << " / "
                    << one.machine_seconds);
    // Measured: 25.40 s (the rest told at a sample, 0.05 s).
    CHECK(turning == Approx(more_by_hand).margin(0.1));
    // Each settle between the passes is the last pass's settle (the same creep onto the count):
    // measured 0.20 and 0.15 s, one pass's 0.15 s.
    CHECK(settles == Approx(2 * settle_one).margin(0.1));
    // The hole and the run: 25.80 s longer each.
    CHECK((b.end_s - b.start_s) - (a.end_s - a.start_s) ==
          Approx(more_by_hand + settles).margin(0.15));
    CHECK(three.machine_seconds - one.machine_seconds ==
          Approx(more_by_hand + settles).margin(0.15));
    // The tool stood 0.0025 in short of the top after every pass, and the feed followed it there
    // (z_cmd kept), settling onto its count only while the tool stood.
    for (std::size_t i = 0; i < ps.size(); ++i) {
        const double tool_z = (b.samples[ps[i].last].tool_revs - b.sync_tool_revs) * test::kPitch1;
        CHECK(tool_z == Approx(0.0025).margin(0.0007));
    }
    // A peck at or past the depth is one pass, as with none.
    const RunResult deep = peck::run(300, 300, Pace::fast_forward);
    REQUIRE(deep.completed);
    CHECK(deep.tapping->holes.at(0).pecks == 1);
    CHECK(deep.machine_seconds == one.machine_seconds);
    const RunResult past = peck::run(300, 999, Pace::fast_forward);
    CHECK(past.tapping->holes.at(0).pecks == 1);
    CHECK(past.tapping->holes.at(0).end_s == a.end_s);
}

TEST_CASE("Peck tapping: the peck depth round-trips through the card (columns 21-24) and the "
          "listing (peck=D.DDD), and a punched 0000 is refused",
          "[tapping][rigid][peck][card]") {
    CardOrders o = peck::tap(7, 600, 120, 250);
    o.tap.retract = 2;
    const EncodeResult e = encode(o, fig8_layout());
    REQUIRE(e);
    CHECK(e.card.column(21) == row_bit(Row::r0));
    CHECK(e.card.column(22) == row_bit(Row::r2));
    CHECK(e.card.column(23) == row_bit(Row::r5));
    CHECK(e.card.column(24) == row_bit(Row::r0));
    const DecodeResult d = decode(e.card, fig8_layout());
    REQUIRE(d);
    CHECK(d.orders.tap == o.tap);
    CHECK(tap_row(d.orders) == "7,tap,1,vertical,forward,0.600,0.05000,120,retract=2,peck=0.250");
    CHECK(read_tap_row(tap_row(d.orders), "deck.csv", 3).second == o.tap);
    CHECK(tap_passes(o.tap) == 3);
    o.tap.peck = 0; // blank: one pass, as before the addition
    CHECK(tap_passes(o.tap) == 1);
    const Card blank = encode(o, fig8_layout()).card;
    for (int c = 21; c <= 24; ++c) {
        CHECK(blank.column(c) == 0);
    }
    CHECK(decode(blank, fig8_layout()).orders.tap.peck == 0);
    CHECK(tap_row(o) == "7,tap,1,vertical,forward,0.600,0.05000,120,retract=2");
    CHECK_THROWS_WITH(
        read_tap_row("7,tap,1,vertical,forward,0.600,0.05000,120,peck=0.000", "deck.csv", 3),
        Catch::Contains("deck.csv:3") && Catch::Contains("a peck of 0 taps nothing"));
    CHECK_THROWS_WITH(read_tap_row("7,tap,1,vertical,forward,0.600,0.05000,120,peck=0.100,"
                                   "peck=0.200",
                                   "deck.csv", 3),
                      Catch::Contains("'peck=' given twice"));
    CHECK_THROWS(read_tap_row("7,tap,1,vertical,forward,0.600,0.05000,120,peck=x", "d.csv", 3));
    // Q over the depth is one pass: accepted.
    CHECK(read_tap_row("7,tap,1,vertical,forward,0.600,0.05000,120,peck=9.999", "d.csv", 3)
              .second.peck == 9999);

    Card zero = blank;
    for (int c = 21; c <= 24; ++c) {
        zero.punch(c, Row::r0);
    }
    const DecodeResult dz = decode(zero, fig8_layout());
    REQUIRE(dz.bad_punch);
    CHECK(dz.bad_punch->column == 21);
    CHECK_THAT(dz.bad_punch->what,
               Catch::Contains("tap peck depth is 0000") && Catch::Contains("blank for one pass"));
    Card two = e.card;
    two.punch(22, Row::r1); // 1 and 2: two digits in one column
    CHECK(decode(two, fig8_layout()).bad_punch->column == 22);
}

TEST_CASE("Peck tapping through punch, convert, show, gen tapping, the report and a saved state",
          "[tapping][rigid][peck][cli]") {
    test::TempDir dir;
    const std::string row = "2,tap,1,vertical,reverse,0.600,0.05000,240,peck=0.250\n";
    const std::string shown = test::tap_row_round_trip(dir, row);
    CHECK_THAT(shown, Catch::Contains("21-24    tap peck depth 0.250 in a peck: 3 passes in "
                                      "to 0.600 in"));

    // The report and the saved state carry the peck and the passes; a resumed run reports the
    // hole as the run it goes on from did.
    test::write_bytes(dir.path("deck.csv"),
                      test::deck_with(row) + test::motion_rows(3, "1.100", "0.099"));
    const std::string deck = test::q(dir.str("deck.csv"));
    const auto stopped = test::run_parsons(
        "run " + deck + " --profile parsons-extended --save-state " + test::q(dir.str("s.json")) +
        " --report " + test::q(dir.str("first.json")) + " -q");
    REQUIRE(stopped.exit_code == 3);
    const auto first = nlohmann::json::parse(test::read_bytes(dir.path("first.json")));
    const auto& hole = first["tapping"]["holes"].at(0);
    CHECK(hole["completed"] == true);
    CHECK(hole["peck_in"] == 0.25);
    CHECK(hole["pecks"] == 3);
    const auto state = nlohmann::json::parse(test::read_bytes(dir.path("s.json")));
    CHECK(state["resume"]["tapping"]["holes"].at(0)["pecks"] == 3);
    const auto resumed =
        test::run_parsons("run " + deck + " --resume " + test::q(dir.str("s.json")) + " --report " +
                          test::q(dir.str("again.json")) + " -q");
    CHECK(resumed.exit_code == 3);
    const auto again = nlohmann::json::parse(test::read_bytes(dir.path("again.json")));
    CHECK(again["tapping"] == first["tapping"]);

    // gen tapping --peck: every tap card pecks.
    const auto gen = test::run_parsons("gen tapping --profile parsons-extended --peck 0.2 -o " +
                                       test::q(dir.str("job.csv")));
    INFO(gen.output);
    REQUIRE(gen.exit_code == 0);
    CHECK_THAT(gen.output, Catch::Contains("peck           every tap goes in 0.200 in a pass"));
    CHECK_THAT(test::read_bytes(dir.path("job.csv")), Catch::Contains(",peck=0.200"));
    const auto bad_gen = test::run_parsons("gen tapping --profile parsons-extended --peck 12 -o " +
                                           test::q(dir.str("job2.csv")));
    CHECK(bad_gen.exit_code == 2);
    CHECK_THAT(bad_gen.output, Catch::Contains("--peck 12: give 0.001 to 9.999 in"));
}

TEST_CASE("Peck tapping with the index wait and the faster retract: the wait once, before the "
          "first pass, every pass out at k x S, the same machine at both paces",
          "[tapping][rigid][peck]") {
    CardOrders o = peck::tap(2, 300, 120, 100);
    o.tap.index_wait = true;
    o.tap.retract = 2;
    const RunResult a = peck::run(o, Pace::fast_forward);
    const RunResult b = peck::run(o, Pace::impulse_level);
    INFO((a.stop ? a.stop->message : std::string("completed")));
    REQUIRE(a.completed);
    REQUIRE(b.completed);
    const HoleRecord& h = a.tapping->holes.at(0);
    REQUIRE(h.completed);
    CHECK(h.pecks == 3);
    CHECK(h.retract == 2);
    CHECK(h.index_wait);
    // By hand: motor 27 runs up to 2 rev/s in 0.5 s (0.5 rev), the index at 4 revolutions comes
    // 3.5 revolutions later at 2 rev/s: 2.25 s after the tool was ready; once, not each pass.
    CHECK(h.sync_s - h.start_s == Approx(2.25).margin(1e-9));
    const auto ps = peck::passes(h);
    REQUIRE(ps.size() == 3);
    for (std::size_t i = 0; i < ps.size(); ++i) {
        CHECK(ps[i].deepest_in == Approx(0.1 * static_cast<double>(i + 1)).margin(0.002));
    }
    CHECK(std::abs(h.end_in - h.start_in) < 0.0006);
    CHECK(a.machine_seconds == b.machine_seconds);
    CHECK(h.end_s == b.tapping->holes.at(0).end_s);
    CHECK(h.deepest_in == b.tapping->holes.at(0).deepest_in);
    // Out at 2 x S (4 rev/s) each pass of N motor revolutions comes out in N / 4 + 0.875 s
    // against N / 2 + 0.4375 s at S: N / 4 - 0.4375 s sooner; N 8, 16, 24: 10.6875 s by hand
    // (measured 10.55 s: the stops near the top judged at a sample from the faster speed).
    o.tap.retract = 1;
    const RunResult slow = peck::run(o, Pace::fast_forward);
    REQUIRE(slow.completed);
    INFO("saved " << slow.machine_seconds - a.machine_seconds);
    CHECK(slow.machine_seconds - a.machine_seconds == Approx(10.6875).margin(0.2));
}
