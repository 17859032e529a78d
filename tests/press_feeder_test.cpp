// The press-feeder job and its proof (decks/press_feeder_job.hpp, outputs/proofs/press_proof.hpp):
// the point of EP 0436887 (Mitsubishi) against its Fig. 7 — with the press slowing 25 % mid-cycle,
// position + speed sync keeps the feeder clear of the die on every cycle, speed sync alone does not
// — and the job's deck review, nominal runs, the clearance by hand, bad geometry.
#include "tests/test_support.hpp"

#include "axes/press.hpp"
#include "cli/gen_press_feeder.hpp"
#include "outputs/proofs/press_proof.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>

using namespace parsons;
using parsons::test::q;
using parsons::test::run_parsons;
using parsons::test::TempDir;

namespace {

struct ProvedFeeder {
    relaylogic::RunResult result;
    std::optional<cli::PressProof::Instant> collision;
    std::vector<double> per_cycle;
    double min_clearance = 0;
    long cycles = 0;
};

// Generates the job (variant), runs it under its profile changed by `change`, proves it.
template <typename Change>
ProvedFeeder prove(bool speed_only, int cycles, Change change,
                   const axes::MachineProfile& base = axes::extended_profile()) {
    decks::PressFeederOptions o;
    o.speed_only = speed_only;
    o.cycles = cycles;
    const cli::GeneratedPressJob g = cli::generate_press_job(o, base, "", "");
    axes::MachineProfile p = g.profile;
    change(p.press);
    cli::PressProof proof(p.press, o.zone_edge_x_in, o.safe_height_in, g.deck.cycle_card);
    ProvedFeeder r;
    r.result = cli::run_cards(g.deck.cards, p, &proof);
    r.collision = proof.collision();
    r.per_cycle = proof.cycle_clearance_in();
    r.min_clearance = proof.closest().clearance_in;
    r.cycles = proof.cycles();
    return r;
}

// When the job's press (nominal, from the generated profile) reaches revolution 2 at 180 deg.
double change_time() {
    decks::PressFeederOptions o;
    const cli::GeneratedPressJob g = cli::generate_press_job(o, axes::extended_profile(), "", "");
    axes::Press press(g.profile.press);
    while (press.theta_deg() < 360.0 + 180.0) {
        press.advance_to(press.next_event_time());
    }
    return press.time_s();
}

void slow_mid_cycle(axes::PressProfile& press) {
    press.change_cycle = 2;
    press.change_angle_deg = 180;
    press.change_factor = 0.75;
}

} // namespace

TEST_CASE("Press feeder: with the press slowing 25 % mid-cycle, position + speed sync keeps a "
          "positive clearance on every cycle and speed sync alone (Fig. 7) collides, named by "
          "cycle and instant",
          "[press_feeder]") {
    const ProvedFeeder both = prove(false, 4, slow_mid_cycle);
    const ProvedFeeder speed = prove(true, 4, slow_mid_cycle);
    REQUIRE_FALSE(both.result.stop);
    REQUIRE_FALSE(speed.result.stop);
    CHECK(both.cycles == 4);
    CHECK(speed.cycles == 4);
    REQUIRE(both.per_cycle.size() == 4);
    for (double c : both.per_cycle) {
        CHECK(c > 0.05);
    }
    CHECK_FALSE(both.collision);
    REQUIRE(speed.collision);
    // Every move follows the press; what does not (the reader's card cycles, the relays' and
    // the sequence shaft's times, the drive's least speed) keeps its seconds and puts the
    // feeder ahead of the crank a little more each cycle once the press has slowed, until it
    // enters the zone early. At the nominal speed it never does (below).
    CHECK(speed.collision->cycle >= 1);
    CHECK(speed.collision->t > change_time());
    CHECK(speed.collision->clearance_in < 0);
    CHECK(speed.collision->feeder_x_in > 0.700);
    CHECK(speed.collision->die_height_in < 0.25);
    CHECK(speed.min_clearance < 0);
}

TEST_CASE("Press feeder: at nominal speed both variants keep clear on the first cycle",
          "[press_feeder]") {
    for (bool speed_only : {false, true}) {
        INFO("speed only " << speed_only);
        const ProvedFeeder r = prove(speed_only, 2, [](axes::PressProfile&) {});
        REQUIRE_FALSE(r.result.stop);
        REQUIRE_FALSE(r.per_cycle.empty());
        CHECK(r.per_cycle.front() > 0.05);
        CHECK_FALSE(r.collision);
    }
}

TEST_CASE("Press feeder: the proof's clearance at one instant is the hand calculation",
          "[press_feeder]") {
    // Crank at 160 deg: the slider crank with r = 2, L = 8 puts the die at
    // 2 cos 160 + sqrt(64 - 4 sin^2 160) - 6 = -1.879385 + 7.970702 - 6 = 0.091317 in.
    axes::PressProfile press;
    press.strokes_per_min = 1.0;
    press.start_angle_deg = 160.0;
    const axes::Press p(press);
    const double h = p.die_height_in();
    CHECK(h == Approx(0.091317).margin(1e-6));
    // Feeder at 0.750 (inside the zone past 0.700), safe height 0.25: max(0.091317 - 0.25,
    // 0.700 - 0.750) = max(-0.158683, -0.050) = -0.050 in: a collision by 0.050 in.
    CHECK(cli::PressProof::clearance(h, 0.25, 0.700, 0.750) == Approx(-0.050));
    // The observer at t = 0 with the table standing at 0.750.
    cli::PressProof proof(press, 0.700, 0.25, 2);
    proof.on_motion(0.0, {0.750, 0, 0, 0, 0});
    REQUIRE(proof.collision());
    CHECK(proof.collision()->crank_deg == Approx(160.0));
    CHECK(proof.collision()->die_height_in == Approx(0.091317).margin(1e-6));
    CHECK(proof.closest().clearance_in == Approx(-0.050));
    // Retracted to 0.400: the clearance is 0.700 - 0.400 = 0.300 in.
    CHECK(cli::PressProof::clearance(h, 0.25, 0.700, 0.400) == Approx(0.300));
}

TEST_CASE("Press feeder: the generated deck passes check under the job's profile with no "
          "warnings, run --press-proof reports the press block, and a collision is exit 3",
          "[press_feeder][cli]") {
    TempDir dir;
    const std::string deck = dir.str("feeder.csv");
    const auto gen = run_parsons("gen press-feeder --cycles 2 -o " + q(deck));
    REQUIRE(gen.exit_code == 0);
    const auto check = run_parsons("check " + q(deck) + " --profile " + q(deck + ".profile.json"));
    INFO(check.output);
    CHECK(check.exit_code == 0);
    CHECK(check.output.find("the machine runs the deck through") != std::string::npos);
    CHECK(check.output.find("0 machine stop, 0 observed, 0 double punches, 0 advice") !=
          std::string::npos);
    const auto run = run_parsons("run " + q(deck) + " -q --press-proof " + q(deck + ".job.json") +
                                 " --report " + q(dir.str("r.json")));
    INFO(run.output);
    CHECK(run.exit_code == 0);
    const auto report = nlohmann::json::parse(test::read_bytes(dir.path("r.json")));
    CHECK(report["press"]["collision"].is_null());
    CHECK(report["press"]["min_clearance_in"].get<double>() > 0);
    CHECK(report["press"]["proof_cycles"] == 2);

    const std::string conv = dir.str("conv.csv");
    REQUIRE(run_parsons("gen press-feeder --speed-only --cycles 3 -o " + q(conv)).exit_code == 0);
    auto profile = nlohmann::json::parse(test::read_bytes(conv + ".profile.json"));
    profile["press"]["change_cycle"] = 2;
    profile["press"]["change_angle_deg"] = 180;
    profile["press"]["change_factor"] = 0.75;
    test::write_bytes(dir.path("slow.json"), profile.dump());
    const auto slow = run_parsons("run " + q(conv) + " -q --profile " + q(dir.str("slow.json")) +
                                  " --press-proof " + q(conv + ".job.json"));
    CHECK(slow.exit_code == 3);
    CHECK(slow.output.find("collision in cycle ") != std::string::npos);

    // The proof follows the press from the job's start: a resumed run is not proved.
    test::write_bytes(dir.path("s.json"), "{}");
    const auto resumed = run_parsons("run " + q(deck) + " -q --resume " + q(dir.str("s.json")) +
                                     " --press-proof " + q(deck + ".job.json"));
    CHECK(resumed.exit_code == 2);
    CHECK(resumed.output.find("--press-proof with --resume") != std::string::npos);
}

TEST_CASE("Press feeder: impossible geometry is refused with exit 2", "[press_feeder][cli]") {
    TempDir dir;
    const std::string deck = dir.str("bad.csv");
    for (const char* args :
         {"--zone-edge-x 0.3", "--insert-x 0.5 --zone-edge-x 0.6", "--insert-deg 5",
          "--safe-height 5", "--cycles 0", "--takeout-angle 150"}) {
        INFO(args);
        const auto r = run_parsons(std::string("gen press-feeder ") + args + " -o " + q(deck));
        CHECK(r.exit_code == 2);
        CHECK(r.output.find("gen press-feeder") != std::string::npos);
    }
}

TEST_CASE("Press feeder: the proof's least time margin is the smallest of the cycle's margins, "
          "not the largest",
          "[press_feeder][mutation]") {
    // The press at one revolution a second (360 deg/s) from top dead centre; the die is below
    // the safe height 0.25 in from angle a1 to a2 of each turn. The feeder is driven by hand
    // across the zone edge 0.700 in, with margins 0.20, 0.05, 0.30 and 0.15 s to the die.
    axes::PressProfile press;
    press.strokes_per_min = 60.0;
    press.start_angle_deg = 0.0;
    const auto low = axes::Press(press).angles_at_height(0.25);
    REQUIRE(low);
    const double down = low->first / 360.0; // the die goes below safe height, in each second
    const double up = low->second / 360.0;  // and comes back above it
    REQUIRE(down > 0.2);
    REQUIRE(up < 0.7);
    cli::PressProof proof(press, 0.700, 0.25, 2);
    auto feeder = [&](double t, double x) { proof.on_motion(t, {x, 0, 0, 0, 0}); };
    feeder(0.0, 0.400);
    feeder(up + 0.20, 0.750);       // in 0.20 s after the die rose
    feeder(1 + down - 0.05, 0.400); // out 0.05 s before it goes down again
    feeder(1 + up + 0.30, 0.750);   // in 0.30 s after it rose
    feeder(2 + down - 0.15, 0.400); // out 0.15 s before it goes down
    proof.on_finish(3.0);
    CHECK_FALSE(proof.collision());
    REQUIRE(proof.min_margin_s());
    CHECK(*proof.min_margin_s() == Approx(0.05).margin(1e-6));
    CHECK(proof.entries_s().size() == 2);
}

TEST_CASE("Press feeder: every move of both variants, the home and the Y moves too, is "
          "speed-synchronised, none slower than the drive's 0.5 in/min, and at the nominal speed "
          "the speed-only job keeps clear for all its cycles",
          "[press_feeder]") {
    const ProvedFeeder nominal = prove(true, 4, [](axes::PressProfile&) {});
    REQUIRE_FALSE(nominal.result.stop);
    CHECK(nominal.cycles == 4);
    CHECK_FALSE(nominal.collision);
    CHECK(nominal.min_clearance > 0.05);
    // And every synchronised move of the job follows no slower than the drive's 0.5 in/min.
    for (bool speed_only : {false, true}) {
        decks::PressFeederOptions o;
        o.speed_only = speed_only;
        const cli::GeneratedPressJob g =
            cli::generate_press_job(o, axes::extended_profile(), "", "");
        REQUIRE(g.deck.moves.size() == 10); // the home's X and Y, and the cycle's eight moves
        for (const auto& m : g.deck.moves) {
            INFO(m.name);
            CHECK(m.speed_in_per_min >= 0.5);
        }
        // Every motion card of the deck has its sync card before it.
        for (std::size_t i = 0; i < g.deck.cards.size(); ++i) {
            if (g.deck.cards[i].kind == cardreader::CardKind::motion) {
                REQUIRE(i > 0);
                CHECK(g.deck.cards[i - 1].kind == cardreader::CardKind::sync);
                CHECK(g.deck.cards[i - 1].sync.speed_sync());
            }
        }
    }
}

TEST_CASE("Press feeder: a job whose timing would make a move crawl under the drive's 0.5 "
          "in/min is refused, naming the move",
          "[press_feeder][cli]") {
    TempDir dir;
    const auto r = run_parsons("gen press-feeder --strokes-per-min 1 --retract-deg 350 -o " +
                               q(dir.str("slow.csv")));
    CHECK(r.exit_code == 2);
    CHECK(r.output.find("the retract") != std::string::npos);
    CHECK(r.output.find("no slower than 0.5 in/min") != std::string::npos);
}
