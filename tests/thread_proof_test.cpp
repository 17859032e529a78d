// The thread proof's arithmetic (outputs/proofs/thread_proof.hpp) on synthetic taps, with no
// cabinet: a perfect helix, a helix of the wrong pitch, the chamfer left out, a revolution's
// advance read between samples, taps too shallow to judge, and the findings besides the pitch. The
// tapping job run end to end: tapping_job_test.cpp.
#include "outputs/proofs/thread_proof.hpp"

#include "tests/tap_support.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <functional>

using namespace parsons;

using parsons::test::kPitch1;
using parsons::test::kPitch2;

namespace {

// ---- Synthetic taps for the proof's arithmetic ----

// A tap going in from `start` (sense -1: counting down) to `depth`, advanced advance_at_revs(r)
// at r tool revolutions, sampled every `step` revolutions, then back out the same way.
std::vector<relaylogic::TapSample> helix(double start, double depth, double step,
                                         const std::function<double(double)>& advance_at_revs) {
    std::vector<relaylogic::TapSample> s;
    double r = 0;
    double t = 0;
    for (; advance_at_revs(r) < depth; r += step, t += 0.05) {
        s.push_back({t, r, start - advance_at_revs(r)});
    }
    s.push_back({t, r, start - advance_at_revs(r)});
    // back out: the revolutions go down again as the spindle reverses
    for (double back = r - step; back >= 0; back -= step) {
        t += 0.05;
        s.push_back({t, back, start - advance_at_revs(back)});
    }
    return s;
}

cli::ThreadGauge gauge(double pitch, double tolerance = 5.0) {
    cli::ThreadGauge g;
    g.surface_in = 1.000;
    g.sense = -1;
    g.tap_pitch_in = pitch;
    g.thread_depth_in = 0.500;
    g.chamfer_revs = 3.0;
    g.tolerance_percent = tolerance;
    return g;
}

} // namespace

TEST_CASE("Thread proof: a perfect helix has no pitch error", "[tapping_job]") {
    // start 0.100 above the surface, 0.600 down, every 0.1 revolution
    const auto s = helix(1.100, 0.600, 0.1, [](double r) { return kPitch1 * r; });
    const cli::ThreadMeasure m = cli::measure_thread(s, gauge(kPitch1));
    REQUIRE(m.measured);
    // the zone: 0.500 - 3 x 0.05 = 0.350 in, 7 revolutions from the surface (reached at r = 2)
    CHECK(m.zone_in == Approx(0.350));
    CHECK(m.entry_revs == Approx(2.0));
    CHECK(m.revolutions == Approx(7.0));
    CHECK(m.per_revolution_in.size() == 7);
    CHECK(m.mean_pitch_in == Approx(kPitch1));
    CHECK(m.worst_error_percent == Approx(0.0).margin(1e-9));
    CHECK_FALSE(m.flagged);
}

TEST_CASE("Thread proof: a helix of 1.25 times the tap's pitch is flagged at +25 %",
          "[tapping_job]") {
    const auto s = helix(1.100, 0.600, 0.25, [](double r) { return 1.25 * kPitch2 * r; });
    const cli::ThreadMeasure m = cli::measure_thread(s, gauge(kPitch2));
    REQUIRE(m.measured);
    CHECK(m.mean_pitch_in == Approx(0.078125));
    CHECK(m.worst_pitch_in == Approx(0.078125));
    CHECK(m.mean_error_percent == Approx(25.0));
    CHECK(m.worst_error_percent == Approx(25.0));
    CHECK(m.flagged);
    // 0.3125 in of full thread at 0.078125 a revolution: 4 revolutions
    CHECK(m.revolutions == Approx(4.0));
    // Within a tolerance of 30 % it passes.
    CHECK_FALSE(cli::measure_thread(s, gauge(kPitch2, 30.0)).flagged);
}

TEST_CASE("Thread proof: the tolerance's edge, both ways: 4.9 % passes, 5.1 % is flagged, short "
          "as long",
          "[tapping_job]") {
    for (const double factor : {1.049, 0.951}) {
        INFO("pitch x " << factor);
        const auto s = helix(1.100, 0.600, 0.1, [&](double r) { return factor * kPitch1 * r; });
        const cli::ThreadMeasure m = cli::measure_thread(s, gauge(kPitch1));
        REQUIRE(m.measured);
        CHECK(std::abs(m.worst_error_percent) == Approx(4.9).margin(1e-6));
        CHECK_FALSE(m.flagged);
    }
    for (const double factor : {1.051, 0.949}) {
        INFO("pitch x " << factor);
        const auto s = helix(1.100, 0.600, 0.1, [&](double r) { return factor * kPitch1 * r; });
        const cli::ThreadMeasure m = cli::measure_thread(s, gauge(kPitch1));
        REQUIRE(m.measured);
        CHECK(std::abs(m.worst_error_percent) == Approx(5.1).margin(1e-6));
        CHECK(m.flagged);
    }
}

TEST_CASE("Thread proof: the chamfer's last revolutions are not judged", "[tapping_job]") {
    // Right pitch down to 0.40 in below the surface, then twice the pitch: the tap's chamfer
    // (3 x 0.05 = 0.15 in above the 0.500 depth, from 0.35 in) covers the bad stretch.
    auto bent = [](double r) {
        const double a = kPitch1 * r; // from the start
        const double knee = 0.100 + 0.400;
        return a <= knee ? a : knee + 2 * (a - knee);
    };
    const auto s = helix(1.100, 0.600, 0.05, bent);
    const cli::ThreadMeasure m = cli::measure_thread(s, gauge(kPitch1));
    REQUIRE(m.measured);
    CHECK(m.zone_in == Approx(0.350));
    CHECK(std::abs(m.worst_error_percent) < 1e-6);
    CHECK_FALSE(m.flagged);
    // With no chamfer the zone reaches the bad stretch: flagged at +100 %.
    cli::ThreadGauge g = gauge(kPitch1);
    g.chamfer_revs = 0;
    const cli::ThreadMeasure whole = cli::measure_thread(s, g);
    CHECK(whole.flagged);
    CHECK(whole.worst_error_percent == Approx(100.0));
}

TEST_CASE("Thread proof: a revolution's advance is read between samples by linear "
          "interpolation",
          "[tapping_job]") {
    // Samples every half revolution, the tap meeting the surface at 2.25 revolutions (clearance
    // 0.1125 at 0.05 a revolution); the sample at r = 3.5 lies 0.010 in deeper than the helix,
    // the one at r = 4.5 0.004 in deeper.
    std::vector<relaylogic::TapSample> s;
    for (int i = 0; i <= 26; ++i) {
        const double r = 0.5 * i;
        const double bump = i == 7 ? 0.010 : i == 9 ? 0.004 : 0.0;
        s.push_back({0.1 * i, r, 1.1125 - kPitch1 * r - bump});
    }
    const cli::ThreadMeasure m = cli::measure_thread(s, gauge(kPitch1));
    REQUIRE(m.measured);
    CHECK(m.entry_revs == Approx(2.25));
    // Revolution 1, 2.25 .. 3.25: d(3.25) lies halfway between r = 3.0 (on the helix) and 3.5
    // (+0.010): +0.005, so 0.055 (+10 %). Revolution 2, 3.25 .. 4.25: from +0.005 to +0.002
    // (halfway to r = 4.5's +0.004): 0.047 (-6 %). Revolution 3: from +0.002 to 0: 0.048 (-4 %).
    REQUIRE(m.per_revolution_in.size() >= 4);
    CHECK(m.per_revolution_in[0] == Approx(0.055));
    CHECK(m.per_revolution_in[1] == Approx(0.047));
    CHECK(m.per_revolution_in[2] == Approx(0.048));
    CHECK(m.per_revolution_in[3] == Approx(kPitch1));
    CHECK(m.worst_revolution == 1);
    CHECK(m.worst_pitch_in == Approx(0.055));
    CHECK(m.worst_error_percent == Approx(10.0));
    CHECK(m.flagged);
    CHECK(m.mean_pitch_in == Approx(kPitch1)); // the ends of the zone are on the helix
}

TEST_CASE("Thread proof: a tap that never reached its full thread is not measured",
          "[tapping_job]") {
    // The tap stopped 0.100 in into the work: all of it within the chamfer of 0.150.
    const auto s = helix(1.100, 0.200, 0.1, [](double r) { return kPitch1 * r; });
    const cli::ThreadMeasure m = cli::measure_thread(s, gauge(kPitch1));
    CHECK_FALSE(m.measured);
    CHECK_THAT(m.not_measured, Catch::Contains("no full thread"));
    // 0.175 in: a full thread of 0.025 in, half a revolution.
    const auto half = helix(1.100, 0.275, 0.05, [](double r) { return kPitch1 * r; });
    const cli::ThreadMeasure h = cli::measure_thread(half, gauge(kPitch1));
    CHECK_FALSE(h.measured);
    CHECK_THAT(h.not_measured, Catch::Contains("less than one tool revolution"));
    CHECK_FALSE(cli::measure_thread({}, gauge(kPitch1)).measured);
}

// ---- Besides the pitch ----

namespace {

relaylogic::HoleRecord hole(int number, int tool, std::optional<double> pitch) {
    relaylogic::HoleRecord h;
    h.card = number;
    h.number = number;
    h.tool = tool;
    h.tap_pitch_in = pitch;
    h.head_ratio = 0.25;
    h.ratio_used = 0.25;
    h.sense = -1;
    h.start_in = 1.100;
    h.depth_in = 0.600;
    h.completed = true;
    h.samples = helix(1.100, 0.600, 0.1, [](double r) { return kPitch1 * r; });
    return h;
}

} // namespace

TEST_CASE("Thread proof: a hole cut by a cutter, by another tool than the job's, or on a card "
          "the job does not know is flagged with its finding, and one the machine never began "
          "is not",
          "[tapping_job]") {
    decks::TappingJob job;
    job.clearance_in = 0.100;
    job.tolerance_percent = 5.0;
    for (int card : {2, 4, 6, 8}) {
        decks::TappingHole h;
        h.hole = card / 2;
        h.card = card;
        h.tool = 1;
        h.tap_pitch_in = kPitch1;
        h.surface_in = 1.000;
        h.thread_depth_in = 0.500;
        h.tolerance_percent = 5.0;
        job.holes.push_back(h);
    }
    relaylogic::TappingResult run;
    run.holes.push_back(hole(2, 1, kPitch1));      // right
    run.holes.push_back(hole(4, 3, std::nullopt)); // a cutter's head
    run.holes.push_back(hole(6, 2, kPitch1));      // the right pitch, but tool 2
    run.holes.push_back(hole(9, 1, kPitch1));      // no hole of the job
    relaylogic::HoleRecord unstarted;              // the machine stopped before tool ready
    unstarted.card = 8;
    unstarted.number = 8;
    run.holes.push_back(unstarted);
    const cli::ThreadProof proof = cli::prove_threads(run, job, axes::SpindleSyncProfile{}, {});
    REQUIRE(proof.holes.size() == 5);
    CHECK_FALSE(proof.holes[0].flagged);
    CHECK(proof.holes[0].measure.measured);
    CHECK(proof.holes[1].flagged);
    CHECK_THAT(proof.holes[1].faults.at(0), Catch::Contains("holds a cutter"));
    CHECK(proof.holes[2].flagged);
    CHECK_THAT(proof.holes[2].faults.at(0), Catch::Contains("the job calls for tool 1"));
    CHECK(proof.holes[3].flagged);
    CHECK_THAT(proof.holes[3].faults.at(0), Catch::Contains("card 0009 is no hole of the job"));
    CHECK(proof.holes[3].measure.measured); // judged from its start less the job's clearance
    CHECK(std::abs(proof.holes[3].measure.worst_error_percent) < 1e-6);
    CHECK_FALSE(proof.holes[4].flagged);
    CHECK_FALSE(proof.holes[4].measure.measured);
    CHECK(proof.flagged() == 3);
    const auto lines = cli::wrong_pitch_lines(proof);
    REQUIRE(lines.size() == 3);
    CHECK_THAT(lines[0], Catch::StartsWith("hole 2 (card 0004, tool 3): head 3 holds a cutter"));
    // --thread-tolerance replaces each hole's tolerance from the job.
    const cli::ThreadProof strict = cli::prove_threads(run, job, axes::SpindleSyncProfile{}, 1e-4);
    CHECK_FALSE(strict.holes[0].flagged);
    CHECK(strict.holes[0].gauge.tolerance_percent == Approx(1e-4));
}
