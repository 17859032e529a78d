// The feeder's interlock, an addition after EP 0436887 (Mitsubishi): the feeder holds the press
// (press.feeder_hold_lag_in; docs/press-sync.md, "The feeder holds the press"). A held crank
// stands and turns on at the speed of its angle; processor 17's relay picks past the limit,
// drops at half of it, and reaches the press a block later; on the press-feeder job with a
// press that drifts faster than the sync drive can follow, the interlock keeps the feeder within
// its bound of the crank where without it the machine falls behind and stops, and the proof
// follows the machine's holds.
#include "tests/machine_support.hpp"
#include "tests/test_support.hpp"

#include "axes/press.hpp"
#include "cli/gen_press_feeder.hpp"
#include "outputs/proofs/press_proof.hpp"
#include "relaylogic/press/feeder_interlock.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <fstream>

using namespace parsons;
using parsons::test::q;
using parsons::test::run_parsons;
using parsons::test::TempDir;

namespace {

// The job of docs/press-sync.md's interlock figures: insert and take-out over 35 deg (the drive
// follows them at the rated speed, 4.94 in/min, not at 1.5 times it), the press drifting 10 %
// faster a revolution (x 1.46 by revolution 5, then held at x 1.5 by its governor).
struct Interlocked {
    relaylogic::RunResult result;
    std::optional<cli::PressProof::Instant> collision;
    std::int64_t cycles = 0;
    test::Recorder trace;
};

decks::PressFeederOptions drifting_job() {
    decks::PressFeederOptions o;
    o.insert_deg = 35;
    o.takeout_deg = 35;
    return o;
}

std::unique_ptr<Interlocked> run_job(double limit_in, bool observed) {
    const decks::PressFeederOptions o = drifting_job();
    const cli::GeneratedPressJob g = cli::generate_press_job(o, axes::extended_profile(), "", "");
    axes::MachineProfile p = g.profile;
    p.press.drift_per_cycle = 0.1;
    p.press.feeder_hold_lag_in = limit_in;
    auto r = std::make_unique<Interlocked>();
    cli::PressProof proof(p.press, o.zone_edge_x_in, o.safe_height_in, g.deck.cycle_card);
    relaylogic::ObserverFanOut both;
    both.add(&proof);
    if (observed) {
        both.add(&r->trace); // impulse level: the recorder follows every impulse
    }
    r->result = cli::run_cards(g.deck.cards, p, both.attachable());
    r->collision = proof.collision();
    r->cycles = proof.cycles();
    return r;
}

} // namespace

TEST_CASE("Press interlock: a held crank stands and gives no pulse, and let go it turns on at the "
          "speed of its angle, every later edge exactly the hold's length later",
          "[press_sync][press-interlock]") {
    axes::PressProfile pp;
    pp.strokes_per_min = 2.0; // 12 deg/s, 48 pulses/s
    pp.pressing_slowdown = 0.2;
    pp.drift_per_cycle = 0.05;
    axes::Press free(pp);
    axes::Press held(pp);
    // Both to 100 edges; then the held one stands 2.5 s from a tenth of a pulse later.
    for (int i = 0; i < 100; ++i) {
        free.advance_to(free.next_event_time());
        held.advance_to(held.next_event_time());
    }
    const double t_hold = held.time_s() + 0.1 / 48;
    const double angle = held.angle_deg_at(t_hold);
    held.hold(t_hold);
    CHECK(held.held());
    CHECK(held.next_event_time() == axes::kNever);
    CHECK(held.pulses_by(t_hold + 2.0) == 0);
    held.advance_to(t_hold + 2.0);
    CHECK(held.angle_deg() == angle);
    // Saved and loaded while held, it is the same press.
    axes::Press loaded(pp);
    loaded.load(held.save());
    CHECK(loaded.held());
    CHECK(loaded.save() == held.save());
    nlohmann::json moving = held.save();
    moving["w_deg_per_s"] = 12.0;
    CHECK_THROWS_AS(loaded.load(moving), axes::StateError);
    const double hold_s = 2.5;
    held.release(t_hold + hold_s);
    loaded.release(t_hold + hold_s);
    CHECK_FALSE(held.held());
    // 2000 edges on: across the pressing slow-down and a top dead centre's drift.
    for (int i = 0; i < 2000; ++i) {
        const double tf = free.next_event_time();
        const double th = held.next_event_time();
        REQUIRE(th == Approx(tf + hold_s).margin(1e-9));
        REQUIRE(loaded.next_event_time() == th);
        const auto ef = free.advance_to(tf);
        const auto eh = held.advance_to(th);
        loaded.advance_to(th);
        REQUIRE(ef.has_value() == eh.has_value());
        if (ef) {
            REQUIRE(ef->count == eh->count);
        }
    }
    CHECK(free.revolution() >= 2);
}

TEST_CASE("Press interlock: processor 17's relay picks past press.feeder_hold_lag_in, drops at "
          "half of it or when no synchronised axis runs, and holds the press one block later",
          "[press_sync][press-interlock]") {
    relaylogic::Tracer tracer;
    relaylogic::FeederInterlock fi(tracer, 0.02);
    double t = 0;
    auto block = [&](std::optional<double> behind) { return fi.block(behind, t += 0.01); };
    CHECK_FALSE(block(0.02));  // at the limit: nothing
    CHECK_FALSE(block(0.021)); // past it: the relay picks, the press still free this block
    CHECK(block(0.015));       // held from the next block, the relay still up (0.015 > 0.01)
    CHECK(fi.holding());
    CHECK(block(0.0101));       // above half: the relay stays up
    CHECK(block(0.0100));       // at half: it drops, the press still held this block
    CHECK_FALSE(block(0.0150)); // let go (0.015 is not past the limit: it stays down)
    CHECK(fi.holds() == 1);
    CHECK(fi.held_s(t) == Approx(0.03));
    CHECK_FALSE(block(0.03));   // picks again
    CHECK(block(std::nullopt)); // held; no axis runs: the relay drops
    CHECK_FALSE(block(0.03));   // let go (and picked again)
    CHECK(fi.holds() == 2);
    CHECK(fi.longest_s(t) == Approx(0.03));
}

TEST_CASE("Press interlock: on the press-feeder job with a press drifting faster than the sync "
          "drive follows, the feeder falls 0.1 in behind and the machine stops without the "
          "interlock, and with it runs through within its bound, the press held and the proof "
          "clear",
          "[press_sync][press-interlock][press_feeder]") {
    const auto without = run_job(0, false);
    REQUIRE(without->result.stop);
    CHECK(without->result.stop->reason == relaylogic::StopReason::check_mismatch);
    REQUIRE(without->result.press);
    CHECK(without->result.press->max_lag_position_sync_in > 0.1);
    CHECK_FALSE(without->result.press->feeder_interlock);

    const double limit = 0.02;
    const auto with = run_job(limit, true);
    REQUIRE_FALSE(with->result.stop);
    CHECK(with->cycles == 4);
    CHECK_FALSE(with->collision);
    const relaylogic::PressResult& p = *with->result.press;
    REQUIRE(p.feeder_interlock);
    CHECK(p.feeder_interlock->holds > 10);
    CHECK(p.feeder_interlock->held_s > 10);
    CHECK_FALSE(p.feeder_interlock->holding);
    // The bound: the limit, what the crank asks in the two blocks before the press stands (the
    // relay's block and the hold's; at x 1.5 the insert's 0.4 in / 140 pulses x 43.2 pulses a
    // second = 0.123 in/s, 0.0025 in) and the counters' thousandth.
    const double bound = limit + 2 * 0.01 * (0.4 / 140) * 43.2 + 0.001;
    CHECK(p.max_lag_position_sync_in <= bound);
    CHECK(p.max_lag_speed_only_in <= bound);
    CHECK(p.max_lag_position_sync_in > limit / 2); // it was reached: the holds were needed
    // The crank stands through every hold (no edge, no angle change), and each hold is a
    // reference block after one where a table lag past the limit was read.
    const auto holds = with->trace.of("press.feeder_interlock.hold");
    REQUIRE(holds.size() >= 2);
    const auto crank = with->trace.of("press.crank_21.angle");
    std::size_t checked = 0;
    for (std::size_t i = 0; i + 1 < holds.size(); ++i) {
        if (holds[i].new_value != 1) {
            continue;
        }
        const double from = holds[i].t;
        const double to = holds[i + 1].t;
        const auto inside = std::find_if(crank.begin(), crank.end(), [&](const test::Change& c) {
            return c.t > from && c.t < to;
        });
        INFO("hold from " << from << " to " << to << ", crank changed at "
                          << (inside == crank.end() ? -1.0 : inside->t));
        REQUIRE(inside == crank.end());
        ++checked;
    }
    CHECK(checked == static_cast<std::size_t>(p.feeder_interlock->holds));
    // Fast-forward and impulse level agree, holds and all.
    const auto fast = run_job(limit, false);
    test::require_same(fast->result, with->result);
    CHECK(fast->result.press->feeder_interlock->holds == p.feeder_interlock->holds);
    CHECK(fast->result.press->feeder_interlock->held_s == p.feeder_interlock->held_s);
}

TEST_CASE("Press interlock: the command line runs the job with the key, says the holds in the "
          "summary and the report, and refuses a limit under the counters' thousandth",
          "[press_sync][press-interlock][cli]") {
    TempDir dir;
    const std::string deck = dir.str("pf.csv");
    REQUIRE(
        run_parsons("gen press-feeder --insert-deg 35 --takeout-deg 35 -o " + q(deck)).exit_code ==
        0);
    nlohmann::json profile;
    std::ifstream(deck + ".profile.json") >> profile;
    profile["press"]["drift_per_cycle"] = 0.1;
    profile["press"]["feeder_hold_lag_in"] = 0.02;
    test::write_bytes(dir.str("held.json"), profile.dump(1));
    const auto run = run_parsons("run " + q(deck) + " --profile " + q(dir.str("held.json")) +
                                 " --press-proof " + q(deck + ".job.json") + " --report " +
                                 q(dir.str("r.json")) + " --plot " + q(dir.str("p.svg")));
    INFO(run.output);
    REQUIRE(run.exit_code == 0);
    CHECK(run.output.find("interlock      the feeder held the press ") != std::string::npos);
    const nlohmann::json r = nlohmann::json::parse(test::read_bytes(dir.str("r.json")));
    CHECK(r.at("press").at("feeder_interlock").at("holds").get<int>() > 10);
    CHECK(r.at("press").at("feeder_interlock").at("lag_limit_in").get<double>() == 0.02);
    CHECK(r.at("press").at("collision").is_null());
    // The plot draws a band over the crank's lane for each hold, and says what it is.
    const std::string svg = test::read_bytes(dir.str("p.svg"));
    CHECK(test::count(svg, "<rect class=\"interlock-hold\"") ==
          r.at("press").at("feeder_interlock").at("holds").get<std::size_t>());
    CHECK(test::count(svg, "the feeder's interlock holds the press") >= 2);

    profile["press"]["feeder_hold_lag_in"] = 0.0005;
    test::write_bytes(dir.str("tiny.json"), profile.dump(1));
    const auto tiny = run_parsons("run " + q(deck) + " --profile " + q(dir.str("tiny.json")));
    CHECK(tiny.exit_code == 2);
    CHECK(tiny.output.find("press.feeder_hold_lag_in: 0.0005 in is under the counters' "
                           "thousandth") != std::string::npos);
}

TEST_CASE("Press interlock: a slipping drive holds the press while the part stands, and a hold "
          "that lasts sync_timeout_s stops the machine",
          "[press_sync][press-interlock][cli]") {
    TempDir dir;
    test::write_bytes(dir.str("il.json"),
                      R"({"base":"parsons-extended","press":{"feeder_hold_lag_in":0.005}})");
    const std::string run = "run " + q(test::source_path("decks/samples/press-sync.csv")) +
                            " --profile " + q(dir.str("il.json"));
    // 0.300 in of screw travel with the part standing: the counters (instrument shaft 74 follows
    // the part) see the table fall behind, the press stands, and the drive makes the slip up at
    // its least speed, 0.5 in/min: 0.3 / (0.5 / 60) = 36 s, less the lag it was let go at.
    const auto slip =
        run_parsons(run + " --fault slip:table:20:300 --report " + q(dir.str("r.json")));
    INFO(slip.output);
    REQUIRE(slip.exit_code == 0);
    const nlohmann::json r = nlohmann::json::parse(test::read_bytes(dir.str("r.json")));
    const double longest =
        r.at("press").at("feeder_interlock").at("longest_hold_seconds").get<double>();
    CHECK(longest > 33);
    CHECK(longest < 36);
    // 1.000 in would take 120 s: processor 17 gives up at sync_timeout_s (90 s).
    const auto stuck = run_parsons(run + " --fault slip:table:20:1000");
    INFO(stuck.output);
    CHECK(stuck.exit_code == 3);
    CHECK(stuck.output.find("sync_timeout: card 2 (number 0002): the feeder's interlock held the "
                            "press 90.0 s") != std::string::npos);
}
