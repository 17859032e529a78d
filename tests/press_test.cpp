// The rotary press of EP 0436887 Fig. 1A (axes/press.hpp): motor 22's speed in segments,
// crank 21's angle, detector 10's two phases and die 20's height, tested on the plant alone (the
// press's profile keys: press_profile_test.cpp).
#include "axes/press.hpp"
#include "axes/profile_json.hpp"
#include "axes/state_json.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <string>
#include <vector>

using namespace parsons::axes;

namespace {

// 2 strokes a minute: 12 degrees a second, 48 pulses a second at 4 a degree.
constexpr double kDegPerS = 12.0;

PressProfile steady() {
    PressProfile p;
    p.strokes_per_min = 2.0;
    p.pulses_per_degree = 4;
    return p;
}

struct Taken {
    double t = 0;
    DetectorEdge edge;
};

// Runs the press event by event until it has taken `pulses` more edges (or stands).
std::vector<Taken> take(Press& press, long pulses) {
    std::vector<Taken> out;
    while (static_cast<long>(out.size()) < pulses && press.next_event_time() != kNever) {
        const double t = press.next_event_time();
        if (auto e = press.advance_to(t)) {
            out.push_back({t, *e});
        }
    }
    return out;
}

// Runs until the pulse count reaches `count` (moving in the press's sense); returns its time.
double time_of_count(Press& press, long count) {
    while (press.count() != count) {
        REQUIRE(press.next_event_time() != kNever);
        press.advance_to(press.next_event_time());
    }
    return press.time_s();
}

bool same_edge(const DetectorEdge& a, const DetectorEdge& b) {
    return a.phase_a == b.phase_a && a.phase_b == b.phase_b && a.count == b.count;
}

} // namespace

TEST_CASE("Press: detector 10 gives pulses_per_degree edges a degree, at exactly t0 + (m / ppd - "
          "theta0) / w at constant speed (Fig. 1A)",
          "[press]") {
    const int ppd = GENERATE(1, 4, 27);
    PressProfile p = steady();
    p.pulses_per_degree = ppd;
    Press press(p);
    CHECK(press.speed_deg_per_s() == kDegPerS);
    CHECK(press.count() == 0);
    // The first segment runs from 0 to pressing_from_deg (150): every edge time is the formula's
    // double, to the last bit.
    const std::vector<Taken> first = take(press, 150L * ppd);
    REQUIRE(first.size() == static_cast<std::size_t>(150 * ppd));
    for (std::size_t i = 0; i < first.size(); ++i) {
        const long m = static_cast<long>(i) + 1;
        INFO("edge " << m);
        CHECK(first[i].edge.count == m);
        CHECK(first[i].t == (static_cast<double>(m) / ppd - 0.0) / kDegPerS);
    }
    CHECK(press.theta_deg() == 150.0);
    // Ten degrees are 10 ppd edges, and a whole revolution 360 ppd edges in 30 s.
    const double at_150 = press.time_s();
    CHECK(time_of_count(press, 160L * ppd) - at_150 == Approx(10 / kDegPerS));
    CHECK(time_of_count(press, 360L * ppd) == Approx(30.0).epsilon(1e-14));
    CHECK(press.angle_deg() == 0.0);
}

TEST_CASE("Press: an edge on a segment boundary is taken in the segment it ends, then the "
          "boundary begins the next",
          "[press]") {
    Press press(steady());
    time_of_count(press, 599); // 149.75 degrees
    // Edge 600 lies on pressing_from_deg = 150: it comes first, the boundary at the same time.
    REQUIRE(press.next_event_is_pulse());
    const double t = press.next_event_time();
    CHECK(t == 12.5);
    CHECK(press.pulse_time(2) == kNever); // edge 601 is the next segment's
    CHECK(press.pulses_by(t) == 1);       // at or before: an edge at t itself counts
    CHECK(press.pulses_by(std::nextafter(t, 0.0)) == 0);
    CHECK(press.pulses_by(1e9) == 1);
    auto edge = press.advance_to(t);
    REQUIRE(edge);
    CHECK(edge->count == 600);
    CHECK_FALSE(press.next_event_is_pulse());
    CHECK(press.next_event_time() == t);
    CHECK_FALSE(press.advance_to(t)); // the boundary: no edge
    REQUIRE(press.next_event_is_pulse());
    CHECK(press.next_event_time() > t);
    CHECK(press.advance_to(press.next_event_time())->count == 601);
}

TEST_CASE("Press: the phases A, B follow the Gray code, one phase per edge, and backwards the "
          "sequence runs back (direction judging device 13)",
          "[press]") {
    CHECK(same_edge(phases_at(0), DetectorEdge{0, 0, 0}));
    CHECK(same_edge(phases_at(1), DetectorEdge{1, 0, 1}));
    CHECK(same_edge(phases_at(2), DetectorEdge{1, 1, 2}));
    CHECK(same_edge(phases_at(3), DetectorEdge{0, 1, 3}));
    CHECK(same_edge(phases_at(-1), DetectorEdge{0, 1, -1}));
    CHECK(same_edge(phases_at(-6), DetectorEdge{1, 1, -6}));

    const bool reverse = GENERATE(false, true);
    PressProfile p = steady();
    p.reverse = reverse;
    p.start_angle_deg = 90.25; // on an edge: count 361
    Press press(p);
    REQUIRE(press.count() == 361);
    DetectorEdge before = phases_at(press.count());
    const std::vector<Taken> edges = take(press, 2000); // past 0 degrees when reversing
    REQUIRE(edges.size() == 2000);
    for (const Taken& e : edges) {
        INFO("count " << e.edge.count);
        CHECK(e.edge.count == before.count + (reverse ? -1 : +1));
        CHECK(std::abs(e.edge.phase_a - before.phase_a) +
                  std::abs(e.edge.phase_b - before.phase_b) ==
              1);
        // The Gray sequence forward: B follows A's previous level; backward A follows B's.
        if (reverse) {
            CHECK(e.edge.phase_a == before.phase_b);
        } else {
            CHECK(e.edge.phase_b == before.phase_a);
        }
        CHECK(same_edge(e.edge, phases_at(e.edge.count)));
        before = e.edge;
    }
    if (reverse) {
        // The crank starts on edge 361 (90.25 degrees), so backwards that edge is taken at once.
        CHECK(edges.front().t == 0.0);
        CHECK(edges.front().edge.count == 360);
        CHECK(edges.at(1).t == 0.25 / kDegPerS);
        CHECK(press.speed_deg_per_s() < 0);
        CHECK(press.count() == 361 - 2000);
        CHECK(press.theta_deg() == -1639.0 / 4 + 0.25);
        CHECK(press.revolution() == -1); // -409.5 degrees: two top dead centres back
        CHECK(press.angle_deg() == 310.5);
    } else {
        CHECK(edges.front().t == 0.25 / kDegPerS);
        CHECK(press.speed_deg_per_s() > 0);
    }
}

TEST_CASE("Press: the run starts with crank 21 at start_angle_deg in revolution 1, count "
          "floor(theta x ppd)",
          "[press]") {
    PressProfile p = steady();
    p.start_angle_deg = 100.1;
    Press press(p);
    CHECK(press.count() == 400);
    CHECK(press.theta_deg() == 100.1);
    CHECK(press.angle_deg() == 100.1);
    CHECK(press.revolution() == 1);
    CHECK(press.time_s() == 0);
    CHECK(press.die_height_in() == press.die_height_in_at_angle(100.1));
    CHECK(press.next_event_time() == (100.25 - 100.1) / kDegPerS);
    CHECK(press.advance_to(press.next_event_time())->count == 401);
    // Reaching the first top dead centre takes the rest of the revolution only.
    CHECK(time_of_count(press, 1440) == Approx((360 - 100.1) / kDegPerS));
    CHECK(press.revolution() == 2);
}

TEST_CASE("Press: the start count agrees with the edge angles m / ppd where theta x ppd rounds "
          "across an edge",
          "[press]") {
    struct Start {
        int ppd;
        double theta;
        long count;
    };
    // 1.6666666666666665 x 3 rounds up to 5, but edge 5 (5 / 3 = 1.6666666666666667) lies
    // ahead; 8.714285714285714 x 7 rounds down below 61, but it is edge 61's own angle.
    const Start s = GENERATE(values<Start>({{3, 1.6666666666666665, 4},
                                            {7, 8.714285714285714, 61},
                                            {4, 100.25, 401},
                                            {27, 359.99999999999994, 9719}}));
    PressProfile p = steady();
    p.pulses_per_degree = s.ppd;
    p.start_angle_deg = s.theta;
    Press press(p);
    CHECK(press.count() == s.count);
    CHECK(static_cast<double>(press.count()) / s.ppd <= s.theta);
    CHECK(static_cast<double>(press.count() + 1) / s.ppd > s.theta);
    CHECK(press.next_event_time() > 0);
    CHECK(press.advance_to(press.next_event_time())->count == s.count + 1);
}

TEST_CASE("Press: the revolution counts top dead centres: at 360 degrees the second begins",
          "[press]") {
    Press press(steady());
    CHECK(press.revolution() == 1);
    time_of_count(press, 1439);
    CHECK(press.revolution() == 1);
    time_of_count(press, 1440);
    CHECK(press.theta_deg() == 360.0);
    CHECK(press.revolution() == 2);
    CHECK(press.angle_deg() == 0.0);
    CHECK(time_of_count(press, 3 * 1440 + 4 * 45) == Approx(3 * 30.0 + 45 / kDegPerS));
    CHECK(press.revolution() == 4);
    CHECK(press.angle_deg() == Approx(45.0));
    // Between events the crank moves without an edge.
    const double t = press.time_s();
    const double next = press.next_event_time();
    CHECK(press.angle_deg_at((t + next) / 2) == Approx(45.125)); // before it gets there
    CHECK(press.angle_deg() == Approx(45.0));
    CHECK_FALSE(press.advance_to((t + next) / 2));
    CHECK(press.theta_deg() == Approx(1080 + 45 + 0.125));
    CHECK(press.angle_deg_at((t + next) / 2) == Approx(45.125));
    CHECK(press.count() == 3 * 1440 + 180);
}

TEST_CASE("Press: the pressing slow-down lengthens exactly the pressing part of a revolution",
          "[press]") {
    PressProfile p = steady();
    p.pressing_from_deg = 150;
    p.pressing_to_deg = 210;
    p.pressing_slowdown = 0.25;
    Press press(p);
    CHECK(press.speed_at(149.999) == kDegPerS);
    CHECK(press.speed_at(150) == 9.0);
    CHECK(press.speed_at(209.999) == 9.0);
    CHECK(press.speed_at(210) == kDegPerS);
    CHECK(press.speed_at(360 + 180) == 9.0);
    const double at_150 = time_of_count(press, 600);
    CHECK(at_150 == 150 / kDegPerS);
    press.advance_to(press.next_event_time()); // the boundary at 150
    CHECK(press.speed_deg_per_s() == 9.0);
    const double at_210 = time_of_count(press, 840);
    CHECK(at_210 - at_150 == Approx(60 / 9.0));
    const double at_360 = time_of_count(press, 1440);
    CHECK(at_360 - at_210 == Approx(150 / kDegPerS));
    // 60 degrees at 3/4 speed: a third of 5 s longer than the steady press's 30 s.
    CHECK(at_360 == Approx(30 + 5.0 / 3));
    CHECK(time_of_count(press, 2 * 1440) - at_360 == Approx(30 + 5.0 / 3));
}

TEST_CASE("Press: turning backwards, the crank crosses the pressing angles at the pressing "
          "speed (the speed of the angles it passes)",
          "[press]") {
    PressProfile p = steady();
    p.reverse = true;
    p.start_angle_deg = 220;
    p.pressing_slowdown = 0.25;
    Press press(p);
    // 220 is on an edge (880): that edge is taken at once, going down.
    const double at_210 = time_of_count(press, 4 * 210 - 1);
    CHECK(at_210 == Approx(10 / kDegPerS));
    CHECK(press.theta_deg() == 210);
    press.advance_to(press.next_event_time()); // the boundary at 210
    CHECK(press.speed_deg_per_s() == -9.0);
    const double at_150 = time_of_count(press, 4 * 150 - 1);
    CHECK(at_150 - at_210 == Approx(60 / 9.0));
    press.advance_to(press.next_event_time()); // the boundary at 150
    CHECK(press.speed_deg_per_s() == -kDegPerS);
    // On through top dead centre into revolution 0.
    const double at_0 = time_of_count(press, -1);
    CHECK(at_0 - at_150 == Approx(150 / kDegPerS));
    CHECK(press.revolution() == 1); // standing on 0 degrees: still revolution 1
    press.advance_to(press.next_event_time());
    CHECK(press.advance_to(press.next_event_time())->count == -2);
    CHECK(press.revolution() == 0);
    CHECK(press.angle_deg() == 359.75);
}

TEST_CASE("Press: a change_factor 0.75 from a mid-cycle angle slows the press for good "
          "(the seed's speed fluctuation)",
          "[press]") {
    PressProfile p = steady();
    p.change_cycle = 2;
    p.change_angle_deg = 90;
    p.change_factor = 0.75;
    Press press(p);
    CHECK(press.speed_at(449.999) == kDegPerS);
    CHECK(press.speed_at(450) == 9.0);
    CHECK(press.speed_at(5000) == 9.0);
    CHECK(press.speed_at(89) == kDegPerS); // in revolution 1 the angle 90 changes nothing
    CHECK(press.speed_at(91) == kDegPerS);
    const double at_change = time_of_count(press, 1800);
    CHECK(at_change == Approx(450 / kDegPerS));
    press.advance_to(press.next_event_time());
    CHECK(press.speed_deg_per_s() == 9.0);
    CHECK(time_of_count(press, 2880) - at_change == Approx(270 / 9.0));
    const double at_720 = time_of_count(press, 2880);
    CHECK(time_of_count(press, 4320) - at_720 == Approx(40.0));
}

TEST_CASE("Press: motor 22 stops at stop_cycle, stop_angle_deg, and the press then stands",
          "[press]") {
    PressProfile p = steady();
    p.stop_cycle = 2;
    p.stop_angle_deg = 45;
    Press press(p);
    CHECK(press.speed_at(404.999) == kDegPerS);
    CHECK(press.speed_at(405) == 0);
    CHECK(press.speed_at(1e6) == 0);
    while (!press.stopped()) {
        REQUIRE(press.next_event_time() != kNever);
        press.advance_to(press.next_event_time());
    }
    CHECK(press.time_s() == Approx(405 / kDegPerS));
    CHECK(press.count() == 1620); // the edge on the stop point was taken before the stop
    CHECK(press.next_event_time() == kNever);
    CHECK_FALSE(press.next_event_is_pulse());
    CHECK(press.speed_deg_per_s() == 0);
    CHECK(press.pulse_time(1) == kNever);
    CHECK(press.pulses_by(1e9) == 0);
    CHECK_FALSE(press.advance_to(1000));
    CHECK(press.theta_deg() == 405);
    CHECK(press.count() == 1620);
    CHECK(press.angle_deg() == 45);
    CHECK(press.revolution() == 2);
}

TEST_CASE("Press: seeded variation is a pure function of seed and revolution", "[press]") {
    PressProfile p = steady();
    p.variation = 0.3;
    p.seed = 7;
    const Press a(p);
    const Press b(p);
    PressProfile q = p;
    q.seed = 8;
    const Press c(q);
    std::vector<double> speeds;
    int differs = 0;
    for (int rev = 1; rev <= 20; ++rev) {
        const double theta = 360.0 * (rev - 1) + 10;
        const double w = a.speed_at(theta);
        INFO("revolution " << rev);
        CHECK(w == b.speed_at(theta));
        CHECK(w >= kDegPerS * 0.7);
        CHECK(w <= kDegPerS * 1.3);
        CHECK(a.speed_at(theta + 300) == w); // one speed all revolution (no pressing slow-down)
        differs += c.speed_at(theta) != w ? 1 : 0;
        speeds.push_back(w);
    }
    CHECK(differs >= 19);
    // u runs over -1..1: some revolutions slower than nominal, some faster.
    CHECK(std::count_if(speeds.begin(), speeds.end(), [](double w) { return w < kDegPerS; }) >= 4);
    CHECK(std::count_if(speeds.begin(), speeds.end(), [](double w) { return w > kDegPerS; }) >= 4);
    std::sort(speeds.begin(), speeds.end());
    CHECK(speeds.back() - speeds.front() > kDegPerS * 0.2); // it does vary
    // Running the press does not change what speed_at says: no hidden state.
    Press run(p);
    const double end_of_first = time_of_count(run, 1440);
    CHECK(end_of_first == Approx(360 / a.speed_at(10)));
    CHECK(time_of_count(run, 2880) - end_of_first == Approx(360 / a.speed_at(370)));
    CHECK(run.speed_at(10) == a.speed_at(10));
}

TEST_CASE("Press: drift_per_cycle multiplies each revolution's speed by (1 + drift)", "[press]") {
    PressProfile p = steady();
    p.drift_per_cycle = 0.05;
    Press press(p);
    CHECK(press.speed_at(10) == kDegPerS);
    CHECK(press.speed_at(370) == Approx(kDegPerS * 1.05));
    CHECK(press.speed_at(1090) == Approx(kDegPerS * 1.05 * 1.05 * 1.05));
    const double first = time_of_count(press, 1440);
    CHECK(first == Approx(30.0));
    CHECK(time_of_count(press, 2880) - first == Approx(30.0 / 1.05));
    p.drift_per_cycle = -0.1;
    CHECK(Press(p).speed_at(730) == Approx(kDegPerS * 0.81));
}

TEST_CASE("Press: die 20's height follows the slider crank, and angles_at_height inverts it",
          "[press]") {
    PressProfile p = steady();
    p.stroke_in = 4;
    p.rod_in = 8;
    const Press press(p);
    // r = 2, L = 8: h = 2 cos a + sqrt(64 - 4 sin^2 a) - 6.
    CHECK(press.die_height_in_at_angle(0) == Approx(4.0).margin(1e-12));
    CHECK(press.die_height_in_at_angle(180) == Approx(0.0).margin(1e-12));
    CHECK(press.die_height_in_at_angle(90) == Approx(1.7459666924148338).margin(1e-12)); // sqrt 60
    CHECK(press.die_height_in_at_angle(270) == Approx(1.7459666924148338).margin(1e-12));
    CHECK(press.die_height_in_at_angle(60) == Approx(2.810249675906654).margin(1e-12)); // sqrt 61
    CHECK(press.die_height_in_at_angle(120) == Approx(0.8102496759066544).margin(1e-12));
    CHECK(press.die_height_in() == Approx(4.0).margin(1e-12));

    auto at_90 = press.angles_at_height(1.7459666924148338);
    REQUIRE(at_90);
    CHECK(at_90->first == Approx(90).margin(1e-9));
    CHECK(at_90->second == Approx(270).margin(1e-9));
    const double h = GENERATE(0.0, 1e-9, 0.25, 1.0, 2.0, 2.810249675906654, 3.999999, 4.0);
    auto angles = press.angles_at_height(h);
    REQUIRE(angles);
    INFO("h " << h);
    CHECK(angles->first >= 0);
    CHECK(angles->first <= 180);
    CHECK(angles->second >= 180);
    CHECK(angles->second <= 360);
    CHECK(angles->first + angles->second == Approx(360));
    CHECK(press.die_height_in_at_angle(angles->first) == Approx(h).margin(1e-12));
    CHECK(press.die_height_in_at_angle(angles->second) == Approx(h).margin(1e-12));
    CHECK_FALSE(press.angles_at_height(-0.001));
    CHECK_FALSE(press.angles_at_height(4.001));
    CHECK(press.angles_at_height(4.0)->first == 0);
    CHECK(press.angles_at_height(0.0)->first == Approx(180).margin(1e-12));
    CHECK(press.angles_at_height(2.810249675906654)->first == Approx(60).margin(1e-9));
}

namespace {

PressProfile random_profile(std::mt19937& rng) {
    auto real = [&rng](double a, double b) { return std::uniform_real_distribution<>(a, b)(rng); };
    auto whole = [&rng](int a, int b) { return std::uniform_int_distribution<>(a, b)(rng); };
    // Half the angles whole degrees, so edges fall on the boundaries.
    auto angle = [&](double a, double b) {
        return whole(0, 1) == 0 ? std::floor(real(a, b)) : real(a, b);
    };
    PressProfile p;
    p.strokes_per_min = real(0.5, 60);
    p.pulses_per_degree = whole(1, 27);
    p.start_angle_deg = angle(0, 360);
    p.reverse = whole(0, 2) == 0;
    p.pressing_from_deg = angle(0, 300);
    p.pressing_to_deg = whole(0, 3) == 0 ? 360
                                         : std::floor(p.pressing_from_deg) + 1 +
                                               angle(0, 358 - p.pressing_from_deg);
    p.pressing_slowdown = real(0, 0.9);
    p.drift_per_cycle = real(-0.1, 0.1);
    p.variation = real(0, 0.5);
    p.seed = static_cast<unsigned>(rng());
    p.change_cycle = whole(0, 3);
    p.change_angle_deg = angle(0, 360);
    p.change_factor = real(0.25, 4);
    p.stop_cycle = whole(0, 1) == 0 ? 0 : whole(1, 6);
    p.stop_angle_deg = angle(0, 360);
    return p;
}

} // namespace

TEST_CASE("Press: edges taken one by one and skipped in jumps agree to the last bit over many "
          "segments (random profiles)",
          "[press][fastforward]") {
    std::mt19937 rng(436887);
    long compared = 0;
    for (int trial = 0; trial < 60; ++trial) {
        const PressProfile p = random_profile(rng);
        INFO("trial " << trial << " ppd " << p.pulses_per_degree << " reverse " << p.reverse
                      << " start " << p.start_angle_deg);
        Press one(p);  // every edge through advance_to(), with moves between them
        Press jump(p); // skip_pulses() in jumps
        int segments = 0;
        while (!one.stopped() && segments < 25) {
            REQUIRE(one.save() == jump.save());
            if (!jump.next_event_is_pulse()) {
                const double t = jump.next_event_time();
                CHECK_FALSE(one.advance_to(t));
                CHECK_FALSE(jump.advance_to(t));
                ++segments;
                continue;
            }
            const long left = jump.pulses_by(kNever);
            REQUIRE(left >= 1);
            CHECK(jump.pulse_time(left) != kNever);
            CHECK(jump.pulse_time(left + 1) == kNever);
            long n = 0;
            if (std::uniform_int_distribution<>(0, 1)(rng) == 0) {
                n = std::uniform_int_distribution<long>(1, left)(rng);
            } else { // by time: as many as come at or before a time within the segment
                double t = std::uniform_real_distribution<>(jump.next_event_time(),
                                                            jump.pulse_time(left))(rng);
                if (std::uniform_int_distribution<>(0, 2)(rng) == 0) { // an edge's own time
                    t = jump.pulse_time(std::uniform_int_distribution<long>(1, left)(rng));
                }
                n = jump.pulses_by(t);
                CHECK((n == 0 || jump.pulse_time(n) <= t));
                CHECK((n == left || jump.pulse_time(n + 1) > t));
                if (n == 0) {
                    continue;
                }
            }
            const double expected_t = jump.pulse_time(n);
            const DetectorEdge skipped = jump.skip_pulses(n);
            std::optional<DetectorEdge> last;
            for (long i = 0; i < n; ++i) {
                const double next = one.next_event_time();
                REQUIRE(one.next_event_is_pulse());
                const int move = std::uniform_int_distribution<>(0, 7)(rng);
                const double between = move == 0 ? one.time_s() + (next - one.time_s()) / 3
                                                 : std::nextafter(next, 0.0);
                if (move < 2 && between < next && between > one.time_s()) {
                    CHECK_FALSE(one.advance_to(between));
                    // Between edges the crank stays between them, on its count.
                    const double lo = static_cast<double>(one.count()) / p.pulses_per_degree;
                    const double hi = static_cast<double>(one.count() + 1) / p.pulses_per_degree;
                    CHECK(lo <= one.theta_deg());
                    CHECK(one.theta_deg() <= hi);
                }
                last = one.advance_to(next);
                REQUIRE(last);
            }
            CHECK(one.time_s() == expected_t);
            CHECK(jump.time_s() == expected_t);
            CHECK(same_edge(*last, skipped));
            ++compared;
        }
        CHECK(one.save() == jump.save());
        CHECK(one.stopped() == jump.stopped());
    }
    CHECK(compared > 1000);
}

TEST_CASE("Press: a saved press, loaded, continues to the last bit, and a state that does not fit "
          "the profile is refused",
          "[press]") {
    std::mt19937 rng(2026);
    for (int trial = 0; trial < 20; ++trial) {
        PressProfile p = random_profile(rng);
        p.stop_cycle = 0;
        Press a(p);
        take(a, std::uniform_int_distribution<long>(0, 5000)(rng));
        // Stop between two events, mid-segment.
        a.advance_to(a.time_s() + (a.next_event_time() - a.time_s()) / 2);
        const std::string saved = a.save().dump();
        Press b(p);
        b.load(nlohmann::json::parse(saved));
        REQUIRE(b.save() == a.save());
        for (int i = 0; i < 3000; ++i) {
            const double t = a.next_event_time();
            REQUIRE(t == b.next_event_time());
            auto ea = a.advance_to(t);
            auto eb = b.advance_to(t);
            REQUIRE(ea.has_value() == eb.has_value());
            if (ea) {
                CHECK(same_edge(*ea, *eb));
            }
        }
        CHECK(a.save() == b.save());
    }

    Press press(steady());
    take(press, 100);
    const nlohmann::json good = press.save();
    const nlohmann::json before = Press(steady()).save();
    auto refused = [&](const char* key, const nlohmann::json& value) {
        nlohmann::json bad = good;
        bad[key] = value;
        Press other(steady());
        INFO(key << " = " << value.dump());
        CHECK_THROWS_AS(other.load(bad), StateError);
        CHECK(other.save() == before); // unchanged
    };
    refused("count", good["count"].get<long>() + 5);
    refused("theta_deg", 400.0);
    refused("theta_deg", "x");
    refused("t", -1.0);
    refused("w_deg_per_s", 13.0);
    refused("segment_end_deg", 200.0);
    refused("next_time", 0.0);
    refused("next_is_pulse", false);
    refused("stopped", true);
    refused("theta0_deg", "inf");
    // States consistent in all but one thing: a speed the profile does not give (its times
    // worked out with it), an angle past the segment's end (with a count and plan to match).
    nlohmann::json fast = good;
    fast["w_deg_per_s"] = 13.0;
    fast["segment_end_t"] = (150.0 - 0.0) / 13.0;
    fast["next_time"] = (101.0 / 4 - 0.0) / 13.0;
    CHECK_THROWS_AS(Press(steady()).load(fast), StateError);
    nlohmann::json past = good;
    past["theta_deg"] = 200.0;
    past["count"] = 800;
    past["next_is_pulse"] = false;
    past["next_time"] = good["segment_end_t"];
    CHECK_THROWS_AS(Press(steady()).load(past), StateError);
    // A press that has stopped stays stopped through save and load.
    PressProfile stopping = steady();
    stopping.stop_cycle = 1;
    stopping.stop_angle_deg = 10;
    Press stands(stopping);
    take(stands, 100);
    REQUIRE(stands.stopped());
    stands.advance_to(50);
    Press loaded(stopping);
    loaded.load(nlohmann::json::parse(stands.save().dump()));
    CHECK(loaded.stopped());
    CHECK(loaded.next_event_time() == kNever);
    CHECK(loaded.theta_deg() == 10);
    CHECK(loaded.save() == stands.save());
    nlohmann::json missing = good;
    missing.erase("t0");
    CHECK_THROWS_AS(Press(steady()).load(missing), StateError);
    // Another profile's press: the segment's speed does not follow from this one.
    PressProfile faster = steady();
    faster.strokes_per_min = 3;
    CHECK_THROWS_AS(Press(faster).load(good), StateError);
    Press again(steady());
    again.load(good);
    CHECK(again.save() == good);
}

TEST_CASE("Press: drift compounds per revolution turned, either sense, and motor 22's governor "
          "holds it within half the nominal speed",
          "[press]") {
    PressProfile p = steady(); // 12 deg/s
    p.drift_per_cycle = -0.05;
    const Press slowing(p);
    CHECK(slowing.speed_at(10.0) == Approx(12.0));                         // revolution 1
    CHECK(slowing.speed_at(360.0 * 2 + 10) == Approx(12.0 * 0.95 * 0.95)); // revolution 3
    // Backwards from revolution 1 the crank turns revolutions 0, -1, ...: the same slowing.
    CHECK(slowing.speed_at(-360.0 * 2 + 10) == Approx(12.0 * 0.95 * 0.95));
    CHECK(slowing.speed_at(-360.0 * 200) == Approx(6.0)); // held at half, not racing
    CHECK(slowing.speed_at(360.0 * 200) == Approx(6.0));
    p.drift_per_cycle = 0.05;
    const Press rising(p);
    CHECK(rising.speed_at(360.0 * 5 + 10) == Approx(12.0 * std::pow(1.05, 5)));
    CHECK(rising.speed_at(360.0 * 500) == Approx(18.0)); // held at one and a half
}
