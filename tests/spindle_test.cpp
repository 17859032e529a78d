// The spindle of EP 0360190 Figs. 1 and 3 (axes/spindle.hpp): motor 27's speed in segments of
// constant acceleration, encoder 32's edges at exact times, the lasting change, gear unit 30
// and the heads 31, saved state; and the profile keys of spindle synchronisation. Tested on the
// plant alone.
#include "axes/machine_profile.hpp"
#include "axes/profile_json.hpp"
#include "axes/spindle.hpp"
#include "axes/state_json.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <string>
#include <vector>

using namespace parsons::axes;

namespace {

// 240 rev/min (4 rev/s) reached in 1 s from rest (4 rev/s2) and left in 0.75 s (5.33 rev/s2);
// 24 edges a revolution, 96 a second at full speed.
SpindleSyncProfile plain() {
    SpindleSyncProfile p;
    p.max_rpm = 240;
    p.run_up_rpm_per_s = 240;
    p.run_down_rpm_per_s = 320;
    p.encoder_pulses_per_rev = 24;
    return p;
}

struct Taken {
    double t = 0;
    DetectorEdge edge;
};

// Takes every event at or before t one by one, then moves to t.
std::vector<Taken> run_to(Spindle& s, double t) {
    std::vector<Taken> out;
    while (s.next_event_time() <= t) {
        const double at = s.next_event_time();
        if (auto e = s.advance_to(at)) {
            out.push_back({at, *e});
        }
    }
    s.advance_to(t);
    return out;
}

// Takes edges one by one until the next event is the segment's end (not taken).
std::vector<Taken> edges_to_boundary(Spindle& s) {
    std::vector<Taken> out;
    while (s.next_event_is_pulse()) {
        const double at = s.next_event_time();
        auto e = s.advance_to(at);
        if (!e || out.size() > 100000) {
            FAIL("an edge was announced and none came, or the segment never ends");
        }
        out.push_back({at, *e});
    }
    return out;
}

// Takes the segment's end, which must come next.
void take_boundary(Spindle& s) {
    REQUIRE_FALSE(s.next_event_is_pulse());
    REQUIRE(s.next_event_time() != kNever);
    CHECK_FALSE(s.advance_to(s.next_event_time()));
}

bool same_edge(const DetectorEdge& a, const DetectorEdge& b) {
    return a.phase_a == b.phase_a && a.phase_b == b.phase_b && a.count == b.count;
}

// A spindle of any temper, and a run of commands for it: speeds either way, rest, the same
// command again, reversals, at random instants.
struct Command {
    double t = 0;
    double rpm = 0;
};

SpindleSyncProfile random_profile(std::mt19937_64& rng) {
    auto real = [&rng](double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(rng);
    };
    SpindleSyncProfile p;
    p.max_rpm = 240;
    p.encoder_pulses_per_rev = std::uniform_int_distribution<int>(4, 40)(rng);
    p.run_up_rpm_per_s = real(20, 2000);
    p.run_down_rpm_per_s = real(20, 2000);
    if (real(0, 1) < 0.5) {
        p.change_at_s = real(0, 20);
        p.change_factor = real(0.3, 1.5);
    }
    return p;
}

std::vector<Command> random_commands(std::mt19937_64& rng, int count) {
    auto real = [&rng](double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(rng);
    };
    std::vector<Command> out;
    double t = 0;
    double rpm = 0;
    for (int i = 0; i < count; ++i) {
        t += real(0.01, 3);
        const double u = real(0, 1);
        rpm = u < 0.15 ? 0.0 : u < 0.25 ? rpm : (real(0, 1) < 0.5 ? -1 : 1) * real(1, 240);
        out.push_back({t, rpm});
    }
    return out;
}

} // namespace

TEST_CASE("Spindle: a run-up from rest takes rpm / run_up_rpm_per_s seconds and v^2 / 2a "
          "revolutions, edge m at sqrt(2 m / (ppr a))",
          "[spindle]") {
    SpindleSyncProfile p = plain();
    p.run_up_rpm_per_s = 150; // 2.5 rev/s2: 240 rev/min in 1.6 s, 4^2 / 5 = 3.2 revolutions
    Spindle s(p);
    CHECK(s.at_rest());
    CHECK(s.next_event_time() == kNever);
    s.command_rpm(240);
    CHECK_FALSE(s.at_rest());
    CHECK(s.rpm_at(0.8) == Approx(120).epsilon(1e-14));
    {
        // Asking again for what is commanded, mid-ramp, changes nothing (not even the segment).
        Spindle again(p);
        again.command_rpm(240);
        run_to(again, 0.377);
        const nlohmann::json mid_ramp = again.save();
        again.command_rpm(240);
        CHECK(again.save() == mid_ramp);
    }
    CHECK(s.motor_revs_at(0.8) == Approx(0.5 * 2.5 * 0.8 * 0.8).epsilon(1e-14));
    const std::vector<Taken> edges = edges_to_boundary(s);
    REQUIRE(edges.size() == 76); // 3.2 x 24 = 76.8
    for (std::size_t i = 0; i < edges.size(); ++i) {
        const long m = static_cast<long>(i) + 1;
        INFO("edge " << m);
        CHECK(same_edge(edges[i].edge, phases_at(m)));
        CHECK(edges[i].t == Approx(std::sqrt(2.0 * m / 24 / 2.5)).epsilon(1e-13));
    }
    CHECK(s.next_event_time() == 240.0 / 150.0);
    take_boundary(s);
    CHECK(s.rpm() == 240);
    CHECK(s.motor_revs() == Approx(3.2).epsilon(1e-14));
    // Steady at 4 rev/s from there: edge 77 at 1.6 + (77 / 24 - 3.2) / 4.
    CHECK(s.next_event_is_pulse());
    CHECK(s.next_event_time() == Approx(1.6 + (77.0 / 24 - 3.2) / 4).epsilon(1e-14));

    SECTION("from a speed already turning: (v1^2 - v0^2) / 2a revolutions") {
        Spindle h(p);
        h.command_rpm(120);
        run_to(h, 3); // 0.8 s up, then 2 rev/s
        const double revs = h.motor_revs();
        h.command_rpm(240);
        edges_to_boundary(h);
        CHECK(h.next_event_time() == Approx(3 + 120.0 / 150).epsilon(1e-14));
        take_boundary(h);
        CHECK(h.motor_revs() - revs == Approx((16.0 - 4.0) / (2 * 2.5)).epsilon(1e-13));
        CHECK(h.rpm() == 240);
    }
}

TEST_CASE("Spindle: an edge on the run-up's end is taken in the segment it ends, then the "
          "boundary begins the next",
          "[spindle]") {
    Spindle s(plain()); // from rest to 240 in 1 s: 2 revolutions, edge 48 exactly at the end
    s.command_rpm(240);
    CHECK(s.pulses_by(kNever) == 48);
    CHECK(s.pulse_time(48) == 1.0);
    CHECK(s.pulse_time(49) == kNever);
    CHECK(s.pulses_by(1.0) == 48);
    CHECK(s.pulses_by(std::nextafter(1.0, 0.0)) == 47);
    s.skip_pulses(47);
    auto edge = s.advance_to(s.next_event_time());
    REQUIRE(edge);
    CHECK(edge->count == 48);
    CHECK(s.time_s() == 1.0);
    CHECK_FALSE(s.next_event_is_pulse());
    CHECK(s.next_event_time() == 1.0);
    take_boundary(s);
    REQUIRE(s.next_event_is_pulse());
    CHECK(s.next_event_time() == Approx(1.0 + 1.0 / 96).epsilon(1e-15));
    CHECK(s.advance_to(s.next_event_time())->count == 49);
}

TEST_CASE("Spindle: a run-down takes the speed lost / run_down_rpm_per_s and (v0^2 - v1^2) / 2a "
          "revolutions, to a lower speed or to rest",
          "[spindle]") {
    Spindle s(plain());
    s.command_rpm(240);
    run_to(s, 5); // 2 revolutions up, 16 at 4 rev/s
    CHECK(s.motor_revs() == Approx(18).epsilon(1e-14));
    // To 120: 0.375 s at 16/3 rev/s2, (16 - 4) / (32/3) = 1.125 revolutions.
    s.command_rpm(120);
    CHECK(s.rpm_at(5.1875) == Approx(180).epsilon(1e-14));
    edges_to_boundary(s);
    CHECK(s.next_event_time() == Approx(5.375).epsilon(1e-15));
    take_boundary(s);
    CHECK(s.rpm() == 120);
    CHECK(s.motor_revs() == Approx(19.125).epsilon(1e-14));
    // To rest: 0.375 s, 4 / (32/3) = 0.375 revolutions; only then at rest, and nothing comes.
    s.command_rpm(0);
    CHECK_FALSE(s.at_rest());
    run_to(s, 5.7);
    CHECK_FALSE(s.at_rest()); // commanded to stand, still turning
    CHECK(s.rpm() == Approx(16).epsilon(1e-13));
    edges_to_boundary(s);
    CHECK(s.next_event_time() == Approx(5.75).epsilon(1e-15));
    take_boundary(s);
    CHECK(s.at_rest());
    CHECK(s.rpm() == 0);
    CHECK(s.next_event_time() == kNever);
    CHECK(s.motor_revs() == Approx(19.5).epsilon(1e-14));
    CHECK(s.count() == 468); // 19.5 x 24
    s.advance_to(100);
    CHECK(s.time_s() == 100);
    CHECK(s.motor_revs() == Approx(19.5).epsilon(1e-14));
}

TEST_CASE("Spindle: a reversal runs down to rest (a boundary at zero speed), then up the other "
          "way, and the encoder counts back down through the Gray code",
          "[spindle]") {
    Spindle s(plain());
    s.command_rpm(240);
    run_to(s, 2); // 6 revolutions, count 144
    REQUIRE(s.count() == 144);
    s.command_rpm(-240);
    CHECK(s.rpm_at(2.375) == Approx(120).epsilon(1e-14)); // still forward, slowing
    // Down at 320 rev/min/s: 0.75 s, 1.5 revolutions on to 7.5 (edges 145-180).
    const std::vector<Taken> forward = edges_to_boundary(s);
    REQUIRE(forward.size() == 36);
    CHECK(forward.back().edge.count == 180);
    CHECK(s.next_event_time() == 2.75);
    take_boundary(s);
    CHECK(s.rpm() == 0);
    CHECK_FALSE(s.at_rest()); // commanded -240
    CHECK(s.motor_revs() == 7.5);
    CHECK(s.rpm_at(3.25) == Approx(-120).epsilon(1e-14));
    // Up backwards at 240 rev/min/s: 1 s, 2 revolutions back to 5.5. The motor stood exactly on
    // edge 180, so turning back crosses it at once (count 179); edge 132 lies on the end.
    const std::vector<Taken> back = edges_to_boundary(s);
    REQUIRE(back.size() == 49);
    CHECK(back.front().t == 2.75);
    long count = 180;
    for (const Taken& e : back) {
        --count;
        INFO("count " << count);
        CHECK(same_edge(e.edge, phases_at(count)));
    }
    CHECK(back.back().edge.count == 131);
    CHECK(s.next_event_time() == Approx(3.75).epsilon(1e-15));
    take_boundary(s);
    CHECK(s.rpm() == -240);
    CHECK(s.motor_revs() == Approx(5.5).epsilon(1e-14));
    // Backwards the phases run through the sequence the other way: (0,1), (1,1), (1,0), (0,0).
    const std::vector<Taken> more = run_to(s, 3.75 + 4.5 / 96);
    REQUIRE(more.size() == 4);
    CHECK(same_edge(more[0].edge, DetectorEdge{1, 1, 130}));
    CHECK(same_edge(more[1].edge, DetectorEdge{1, 0, 129}));
    CHECK(same_edge(more[2].edge, DetectorEdge{0, 0, 128}));
    CHECK(same_edge(more[3].edge, DetectorEdge{0, 1, 127}));
}

TEST_CASE("Spindle: edges taken one by one and skipped in jumps have the same times and leave the "
          "same state, to the last bit, over random commands",
          "[spindle]") {
    std::mt19937_64 rng(20260914);
    long edges = 0;
    long time_mismatches = 0;
    long backwards = 0;
    for (int trial = 0; trial < 120; ++trial) {
        const SpindleSyncProfile p = random_profile(rng);
        const std::vector<Command> commands = random_commands(rng, 12);
        Spindle one(p);
        Spindle jump(p);
        std::vector<Taken> taken;
        std::size_t skipped = 0;
        for (const Command& c : commands) {
            INFO("trial " << trial << ", command at " << c.t);
            const std::vector<Taken> now = run_to(one, c.t);
            taken.insert(taken.end(), now.begin(), now.end());
            // The jumping spindle: each pulse_time it offers must be the one-by-one time.
            while (true) {
                const long n = jump.pulses_by(c.t);
                for (long k = 1; k <= n; ++k) {
                    const std::size_t i = skipped + static_cast<std::size_t>(k) - 1;
                    if (i >= taken.size() || jump.pulse_time(k) != taken[i].t) {
                        ++time_mismatches;
                    }
                }
                if (n > 0) {
                    const DetectorEdge last = jump.skip_pulses(n);
                    skipped += static_cast<std::size_t>(n);
                    REQUIRE(skipped <= taken.size());
                    CHECK(same_edge(last, taken[skipped - 1].edge));
                }
                if (jump.next_event_time() > c.t) {
                    break;
                }
                if (jump.advance_to(jump.next_event_time())) {
                    ++skipped;
                }
            }
            jump.advance_to(c.t);
            REQUIRE(skipped == taken.size());
            REQUIRE(jump.save() == one.save());
            one.command_rpm(c.rpm);
            jump.command_rpm(c.rpm);
        }
        for (std::size_t i = 1; i < taken.size(); ++i) {
            if (taken[i].t < taken[i - 1].t) {
                ++backwards;
            }
        }
        edges += static_cast<long>(taken.size());
    }
    CHECK(edges > 50000); // the trials did turn the motor
    CHECK(time_mismatches == 0);
    CHECK(backwards == 0); // edge times never run backwards
}

TEST_CASE("Spindle: pulses_by counts exactly the edges pulse_time puts at or before an instant, "
          "at each edge's own time and a rounding before it",
          "[spindle]") {
    struct Case {
        const char* what;
        double from_rpm;
        double to_rpm;
    };
    const Case c = GENERATE(values<Case>({{"run-up from rest", 0, 240},
                                          {"run-up", 60, 240},
                                          {"run-down to rest", 240, 0},
                                          {"run-down", 240, 37},
                                          {"reversal", 200, -240},
                                          {"backwards, up", -30, -240},
                                          {"steady", 240, 240}}));
    INFO(c.what);
    SpindleSyncProfile p = plain();
    p.encoder_pulses_per_rev = 37;
    p.run_up_rpm_per_s = 123.4;
    p.run_down_rpm_per_s = 456.7;
    Spindle s(p);
    s.command_rpm(c.from_rpm);
    run_to(s, 3.3);
    s.command_rpm(c.to_rpm);
    const long left = s.pulses_by(kNever);
    const long n_max = c.from_rpm == c.to_rpm ? 500 : left;
    if (c.from_rpm != c.to_rpm) {
        CHECK(s.pulse_time(left + 1) == kNever);
        CHECK(left > 10);
    } else {
        CHECK(left == std::numeric_limits<long>::max()); // steady for good
    }
    long wrong = 0;
    double before = s.time_s();
    for (long n = 1; n <= n_max; ++n) {
        const double t = s.pulse_time(n);
        if (!(t >= before) || s.pulses_by(t) < n || s.pulses_by(std::nextafter(t, -kNever)) >= n) {
            ++wrong;
        }
        before = t;
    }
    CHECK(wrong == 0);
    // And taken one by one, those are the edges there are.
    const std::vector<Taken> edges =
        c.from_rpm == c.to_rpm ? run_to(s, s.pulse_time(n_max)) : edges_to_boundary(s);
    CHECK(static_cast<long>(edges.size()) == n_max);
}

TEST_CASE("Spindle: the lasting change takes effect at change_at_s, the motor running to "
          "change_factor x its command at its own rates",
          "[spindle]") {
    SpindleSyncProfile p = plain();
    p.change_at_s = 5.0;
    p.change_factor = 0.5;
    Spindle s(p);
    s.command_rpm(240);
    edges_to_boundary(s);
    take_boundary(s); // the run-up's end at 1 s
    // Steady until the change: a boundary of its own at 5 s.
    edges_to_boundary(s);
    CHECK(s.next_event_time() == 5.0);
    CHECK(s.rpm_at(4.999) == 240);
    take_boundary(s);
    // Down to 120 at 320 rev/min/s, not in a step: 0.375 s.
    CHECK(s.rpm() == 240);
    CHECK(s.rpm_at(5.1875) == Approx(180).epsilon(1e-14));
    edges_to_boundary(s);
    CHECK(s.next_event_time() == Approx(5.375).epsilon(1e-15));
    take_boundary(s);
    CHECK(s.rpm() == 120);
    CHECK(s.commanded_rpm() == 240);
    // A later command is halved too: 200 -> 100, down at the run-down rate.
    run_to(s, 8);
    s.command_rpm(200);
    edges_to_boundary(s);
    CHECK(s.next_event_time() == Approx(8 + 20.0 / 320).epsilon(1e-15));
    take_boundary(s);
    CHECK(s.rpm() == 100);

    SECTION("a factor above 1 runs up at the run-up rate") {
        SpindleSyncProfile q = plain();
        q.change_at_s = 3.0;
        q.change_factor = 1.5;
        Spindle u(q);
        u.command_rpm(200);
        run_to(u, 3.0);
        CHECK(u.rpm() == 200);
        CHECK(u.rpm_at(3.25) == Approx(260).epsilon(1e-14));
        edges_to_boundary(u);
        CHECK(u.next_event_time() == Approx(3.0 + 100.0 / 240).epsilon(1e-15));
        take_boundary(u);
        CHECK(u.rpm() == 300);
    }
    SECTION("standing commanded to stand, nothing happens at the change; a later command finds "
            "it come") {
        Spindle r(p);
        CHECK(r.next_event_time() == kNever);
        r.advance_to(6);
        r.command_rpm(240);
        edges_to_boundary(r);
        CHECK(r.next_event_time() == Approx(6.5).epsilon(1e-15));
        take_boundary(r);
        CHECK(r.rpm() == 120);
    }
    SECTION("a change during a run-up ends the run-up there") {
        SpindleSyncProfile q = plain();
        q.change_at_s = 0.25;
        q.change_factor = 0.25;
        Spindle u(q);
        u.command_rpm(240); // 60 rev/min at 0.25 s, the new target itself
        edges_to_boundary(u);
        CHECK(u.next_event_time() == 0.25);
        take_boundary(u);
        CHECK(u.rpm() == 60);
        CHECK(u.next_event_is_pulse()); // steady at 60: no boundary comes
        CHECK(u.pulses_by(kNever) == std::numeric_limits<long>::max());
    }
}

TEST_CASE("Spindle: the tool turns at the head's ratio x the motor, and its revolutions carry "
          "on across a head exchange (gear unit 30, heads 31)",
          "[spindle]") {
    const SpindleSyncProfile p = plain(); // heads: tool 1 at 0.25, 2 at 1/3, 3 at 0.5
    Spindle s(p);
    CHECK(s.tool() == 1);
    CHECK(s.ratio() == 0.25);
    s.command_rpm(240);
    run_to(s, 3);
    CHECK(s.tool_revs() == Approx(s.motor_revs() * 0.25).epsilon(1e-15));
    CHECK(s.tool_revs_at(3.1) == Approx(s.motor_revs_at(3.1) * 0.25).epsilon(1e-15));
    s.command_rpm(0);
    edges_to_boundary(s);
    take_boundary(s);
    REQUIRE(s.at_rest());
    const double tool_before = s.tool_revs();
    const double motor_before = s.motor_revs();
    CHECK(tool_before == Approx(motor_before * 0.25).epsilon(1e-15));
    s.mount(3);
    CHECK(s.tool() == 3);
    CHECK(s.ratio() == 0.5);
    CHECK(s.tool_revs() == tool_before); // no jump at the exchange
    s.command_rpm(-120);
    run_to(s, 8);
    const double turned = s.motor_revs() - motor_before;
    CHECK(turned < -1);
    CHECK(s.tool_revs() == Approx(tool_before + turned * 0.5).epsilon(1e-14));
    CHECK(s.tool_revs_at(8.05) ==
          Approx(tool_before + (s.motor_revs_at(8.05) - motor_before) * 0.5).epsilon(1e-14));
    // A tool on no head: nothing mounted, the tool's revolutions stand while the motor turns.
    const double tool_at_8 = s.tool_revs();
    s.mount(77);
    CHECK(s.tool() == 0);
    CHECK(s.ratio() == 0);
    run_to(s, 9);
    CHECK(s.tool_revs() == tool_at_8);
}

TEST_CASE("Spindle: a saved spindle loads back and goes on to the last bit, and a state that "
          "does not follow from the profile is refused",
          "[spindle]") {
    std::mt19937_64 rng(777);
    for (int trial = 0; trial < 20; ++trial) {
        INFO("trial " << trial);
        const SpindleSyncProfile p = random_profile(rng);
        const std::vector<Command> commands = random_commands(rng, 10);
        Spindle a(p);
        const std::size_t half = commands.size() / 2;
        for (std::size_t i = 0; i < half; ++i) {
            run_to(a, commands[i].t);
            a.command_rpm(commands[i].rpm);
        }
        if (trial % 3 == 1) {
            a.mount(trial % 2 == 0 ? 2 : 3);
        }
        // Somewhere between events, mid-ramp as often as not.
        run_to(a, commands[half - 1].t + 0.1234);
        const nlohmann::json saved = nlohmann::json::parse(a.save().dump());
        Spindle b(p);
        b.load(saved);
        CHECK(b.save() == a.save());
        CHECK(b.tool_revs() == a.tool_revs());
        for (std::size_t i = half; i < commands.size(); ++i) {
            const std::vector<Taken> ea = run_to(a, commands[i].t);
            const std::vector<Taken> eb = run_to(b, commands[i].t);
            REQUIRE(ea.size() == eb.size());
            for (std::size_t k = 0; k < ea.size(); ++k) {
                CHECK(ea[k].t == eb[k].t);
            }
            a.command_rpm(commands[i].rpm);
            b.command_rpm(commands[i].rpm);
        }
        CHECK(b.save() == a.save());
        CHECK(b.tool_revs() == a.tool_revs());
    }

    Spindle s(plain());
    s.command_rpm(240);
    run_to(s, 0.61);
    const nlohmann::json good = s.save();
    auto refused = [](const SpindleSyncProfile& p, const nlohmann::json& j) {
        Spindle fresh(p);
        CHECK_THROWS_AS(fresh.load(j), StateError);
        CHECK(fresh.save() == Spindle(p).save()); // unchanged
    };
    nlohmann::json missing = good;
    missing.erase("rpm0");
    refused(plain(), missing);
    nlohmann::json faster = good;
    faster["rpm0"] = 10.0; // the segment's end no longer follows
    refused(plain(), faster);
    nlohmann::json off_count = good;
    off_count["count"] = good["count"].get<long>() + 1;
    refused(plain(), off_count);
    nlohmann::json no_head = good;
    no_head["tool"] = 42;
    refused(plain(), no_head);
    nlohmann::json end_speed = good; // the segment's record disagrees with itself
    end_speed["segment_end_rpm"] = 200.0;
    refused(plain(), end_speed);
    nlohmann::json late = good;
    late["next_time"] = 99.0;
    refused(plain(), late);
    SpindleSyncProfile other = plain();
    other.run_up_rpm_per_s = 200; // another motor: the ramp's end does not follow
    refused(other, good);
    Spindle again(plain());
    again.load(good);
    CHECK(again.save() == good);
}

// ---- The profile's keys ----

TEST_CASE("Spindle profile: every spindle key reads back from the profile's JSON, and a partial "
          "object changes only its keys",
          "[spindle]") {
    MachineProfile p = extended_profile();
    CHECK(p.spindle_sync);
    CHECK_FALSE(default_profile().spindle_sync);
    CHECK_FALSE(safe_profile().spindle_sync);
    SpindleSyncProfile& s = p.spindle;
    s.max_rpm = 150.5;
    s.run_up_rpm_per_s = 77.25;
    s.run_down_rpm_per_s = 99.5;
    s.encoder_pulses_per_rev = 36;
    s.sample_s = 0.025;
    s.feed_gain_per_s = 12.5;
    s.change_at_s = 42.125;
    s.change_factor = 0.625;
    s.heads = {{7, 0.75, 0.0625, std::nullopt}, {9, 1.0 / 7.0, std::nullopt, 0.375}};
    s.first_tool = 9;
    s.ratio_source = RatioSource::stored;
    s.pc_scan_s = 0.015;
    s.head_change_s = 4.5;
    s.transfer_timeout_s = 3.25;
    s.chamfer_revs = 2.5;
    const MachineProfile q = profile_from_json(profile_to_json(p), default_profile());
    CHECK(q.spindle_sync);
    const SpindleSyncProfile& r = q.spindle;
    CHECK(r.max_rpm == 150.5);
    CHECK(r.run_up_rpm_per_s == 77.25);
    CHECK(r.run_down_rpm_per_s == 99.5);
    CHECK(r.encoder_pulses_per_rev == 36);
    CHECK(r.sample_s == 0.025);
    CHECK(r.feed_gain_per_s == 12.5);
    REQUIRE(r.change_at_s);
    CHECK(*r.change_at_s == 42.125);
    CHECK(r.change_factor == 0.625);
    REQUIRE(r.heads.size() == 2);
    CHECK(r.heads[0].tool == 7);
    CHECK(r.heads[0].ratio == 0.75);
    CHECK(r.heads[0].pitch_in == 0.0625);
    CHECK_FALSE(r.heads[0].radius_in);
    CHECK(r.heads[1].tool == 9);
    CHECK(r.heads[1].ratio == 1.0 / 7.0); // to the last bit
    CHECK_FALSE(r.heads[1].pitch_in);
    CHECK(r.heads[1].radius_in == 0.375);
    CHECK(r.first_tool == 9);
    CHECK(r.ratio_source == RatioSource::stored);
    CHECK(r.pc_scan_s == 0.015);
    CHECK(r.head_change_s == 4.5);
    CHECK(r.transfer_timeout_s == 3.25);
    CHECK(r.chamfer_revs == 2.5);
    CHECK(profile_to_json(q) == profile_to_json(p));
    // change_at_s null: no change.
    const MachineProfile n = profile_from_json(R"({"spindle": {"change_at_s": null}})", q);
    CHECK_FALSE(n.spindle.change_at_s);
    // A partial spindle object changes only its keys.
    const MachineProfile t = profile_from_json(
        R"({"spindle_sync": true, "spindle": {"sample_s": 0.1, "ratio_source": "transferred"}})",
        default_profile());
    CHECK(t.spindle_sync);
    CHECK(t.spindle.sample_s == 0.1);
    CHECK(t.spindle.ratio_source == RatioSource::transferred);
    CHECK(t.spindle.max_rpm == SpindleSyncProfile{}.max_rpm);
    CHECK(t.spindle.heads.size() == SpindleSyncProfile{}.heads.size());
    // Every built-in profile prints and reads back unchanged.
    for (const char* name : kBuiltinProfiles) {
        INFO(name);
        const MachineProfile b = *builtin_profile(name);
        CHECK(profile_to_json(profile_from_json(profile_to_json(b), default_profile())) ==
              profile_to_json(b));
    }
    // The limits themselves are accepted.
    for (const char* ok : {
             R"({"spindle": {"max_rpm": 1, "encoder_pulses_per_rev": 4, "sample_s": 0.001}})",
             R"({"spindle": {"sample_s": 1, "feed_gain_per_s": 0, "change_factor": 0.1}})",
             R"({"spindle": {"feed_gain_per_s": 1000, "change_factor": 2, "change_at_s": 0}})",
             R"({"spindle": {"pc_scan_s": 0.001, "head_change_s": 0, "chamfer_revs": 0}})",
             R"({"spindle": {"pc_scan_s": 1, "head_change_s": 600, "chamfer_revs": 20}})",
             R"({"spindle": {"transfer_timeout_s": 3600, "change_at_s": 1e9}})",
             R"({"spindle": {"heads": [{"tool": 99, "ratio": 10, "radius_in": 1.99}],
                 "first_tool": 99}})",
             R"({"spindle": {"max_rpm": 9999, "encoder_pulses_per_rev": 9999}})",
         }) {
        INFO(ok);
        CHECK_NOTHROW(profile_from_json(ok, default_profile()));
    }
}

TEST_CASE("Spindle profile: a value out of range is an error naming its key", "[spindle]") {
    struct Bad {
        const char* json;
        const char* key;
    };
    const Bad bad = GENERATE(values<Bad>({
        {R"({"spindle_sync": 1})", "spindle_sync:"},
        {R"({"spindle": []})", "spindle:"},
        {R"({"spindle": {"rpm": 3}})", "spindle.rpm: unknown key"},
        {R"({"spindle": {"max_rpm": 0.5}})", "spindle.max_rpm:"},
        {R"({"spindle": {"max_rpm": 10000}})", "spindle.max_rpm:"},
        {R"({"spindle": {"max_rpm": "240"}})", "spindle.max_rpm:"},
        {R"({"spindle": {"run_up_rpm_per_s": 0}})", "spindle.run_up_rpm_per_s:"},
        {R"({"spindle": {"run_down_rpm_per_s": -5}})", "spindle.run_down_rpm_per_s:"},
        {R"({"spindle": {"encoder_pulses_per_rev": 3}})", "spindle.encoder_pulses_per_rev:"},
        {R"({"spindle": {"encoder_pulses_per_rev": 10000}})", "spindle.encoder_pulses_per_rev:"},
        {R"({"spindle": {"encoder_pulses_per_rev": 24.5}})", "spindle.encoder_pulses_per_rev:"},
        {R"({"spindle": {"sample_s": 0.0009}})", "spindle.sample_s:"},
        {R"({"spindle": {"sample_s": 1.01}})", "spindle.sample_s:"},
        {R"({"spindle": {"feed_gain_per_s": -0.1}})", "spindle.feed_gain_per_s:"},
        {R"({"spindle": {"feed_gain_per_s": 1000.5}})", "spindle.feed_gain_per_s:"},
        {R"({"spindle": {"change_factor": 0.09}})", "spindle.change_factor:"},
        {R"({"spindle": {"change_factor": 2.01}})", "spindle.change_factor:"},
        {R"({"spindle": {"change_at_s": -1}})", "spindle.change_at_s:"},
        {R"({"spindle": {"change_at_s": "soon"}})", "spindle.change_at_s:"},
        {R"({"spindle": {"pc_scan_s": 0}})", "spindle.pc_scan_s:"},
        {R"({"spindle": {"pc_scan_s": 1.5}})", "spindle.pc_scan_s:"},
        {R"({"spindle": {"head_change_s": -1}})", "spindle.head_change_s:"},
        {R"({"spindle": {"head_change_s": 601}})", "spindle.head_change_s:"},
        {R"({"spindle": {"transfer_timeout_s": 0}})", "spindle.transfer_timeout_s:"},
        {R"({"spindle": {"transfer_timeout_s": 3601}})", "spindle.transfer_timeout_s:"},
        {R"({"spindle": {"chamfer_revs": -0.5}})", "spindle.chamfer_revs:"},
        {R"({"spindle": {"chamfer_revs": 21}})", "spindle.chamfer_revs:"},
        {R"({"spindle": {"ratio_source": "bus"}})", "spindle.ratio_source:"},
        {R"({"spindle": {"first_tool": 0}})", "spindle.first_tool:"},
        {R"({"spindle": {"first_tool": 4}})", "spindle.first_tool: tool 4 is on no head"},
        {R"({"spindle": {"heads": []}})", "spindle.heads:"},
        {R"({"spindle": {"heads": {"tool": 1}}})", "spindle.heads:"},
        {R"({"spindle": {"heads": [1]}})", "spindle.heads[0]:"},
        {R"({"spindle": {"heads": [{"tool": 1, "ratio": 0.5}]}})",
         "spindle.heads[0]: needs exactly one"},
        {R"({"spindle": {"heads": [{"tool": 1, "ratio": 0.5, "pitch_in": 0.05, "radius_in": 0.2}]}})",
         "spindle.heads[0]: needs exactly one"},
        {R"({"spindle": {"heads": [{"ratio": 0.5, "pitch_in": 0.05}]}})",
         "spindle.heads[0]: needs"},
        {R"({"spindle": {"heads": [{"tool": 1, "pitch_in": 0.05}]}})", "spindle.heads[0]: needs"},
        {R"({"spindle": {"heads": [{"tool": 100, "ratio": 0.5, "pitch_in": 0.05}]}})",
         "spindle.heads[0].tool:"},
        {R"({"spindle": {"heads": [{"tool": 1, "ratio": 0, "pitch_in": 0.05}]}})",
         "spindle.heads[0].ratio:"},
        {R"({"spindle": {"heads": [{"tool": 1, "ratio": 10.5, "pitch_in": 0.05}]}})",
         "spindle.heads[0].ratio:"},
        {R"({"spindle": {"heads": [{"tool": 1, "ratio": 0.5, "pitch_in": 1}]}})",
         "spindle.heads[0].pitch_in:"},
        {R"({"spindle": {"heads": [{"tool": 1, "ratio": 0.5, "radius_in": 2}]}})",
         "spindle.heads[0].radius_in:"},
        {R"({"spindle": {"heads": [{"tool": 1, "ratio": 0.5, "radius_in": 0}]}})",
         "spindle.heads[0].radius_in:"},
        {R"({"spindle": {"heads": [{"tool": 1, "ratio": 0.5, "pitch_in": 0.05, "gear": 3}]}})",
         "spindle.heads[0].gear: unknown key"},
        {R"({"spindle": {"heads": [{"tool": 1, "ratio": 0.5, "pitch_in": 0.05},
                                   {"tool": 1, "ratio": 0.25, "pitch_in": 0.05}]}})",
         "spindle.heads[1].tool: tool 1 is on two heads"},
    }));
    INFO(bad.json);
    CHECK_THROWS_WITH(profile_from_json(bad.json, default_profile()), Catch::StartsWith(bad.key));
}

TEST_CASE("Spindle profile: more heads than gear unit 30 takes are refused", "[spindle]") {
    nlohmann::json heads = nlohmann::json::array();
    for (int tool = 1; tool <= 21; ++tool) {
        heads.push_back({{"tool", tool}, {"ratio", 0.5}, {"pitch_in", 0.05}});
    }
    const nlohmann::json twenty_one{{"spindle", {{"heads", heads}}}};
    CHECK_THROWS_WITH(profile_from_json(twenty_one.dump(), default_profile()),
                      Catch::StartsWith("spindle.heads:"));
    heads.erase(heads.end() - 1);
    const nlohmann::json twenty{{"spindle", {{"heads", heads}}}};
    CHECK(profile_from_json(twenty.dump(), default_profile()).spindle.heads.size() == 20);
}

TEST_CASE("Spindle profile: an encoder whose edges at max_rpm come faster than interface 33's "
          "stepping switches follow is refused, naming spindle.max_rpm and what they can follow",
          "[spindle]") {
    const MachineProfile extended = extended_profile(); // 100 steps a second, 24 edges a rev
    // 250 rev/min: 100 edges a second, within; 251: 100.4, beyond.
    CHECK_NOTHROW(profile_from_json(R"({"spindle": {"max_rpm": 250}})", extended));
    CHECK_THROWS_WITH(profile_from_json(R"({"spindle": {"max_rpm": 251}})", extended),
                      Catch::StartsWith("spindle.max_rpm:") &&
                          Catch::Contains("100.4 encoder pulses a second") &&
                          Catch::Contains("at most 250.00 rev/min"));
    // More edges a revolution make it sooner: 240 rev/min at 30 edges is 120 a second.
    CHECK_THROWS_WITH(profile_from_json(R"({"spindle": {"encoder_pulses_per_rev": 30}})", extended),
                      Catch::StartsWith("spindle.max_rpm:") &&
                          Catch::Contains("at most 200.00 rev/min"));
    // Slower switches too, whichever key makes it so.
    CHECK_THROWS_WITH(profile_from_json(R"({"max_stepping_rate_per_s": 90})", extended),
                      Catch::StartsWith("spindle.max_rpm:") &&
                          Catch::Contains("at most 225.00 rev/min"));
    // A lasting change above 1 turns the motor faster than max_rpm: 250 x 1.2 is 120 edges a
    // second; a change below 1 takes nothing away from max_rpm, and without change_at_s the
    // factor never acts.
    CHECK_NOTHROW(
        profile_from_json(R"({"spindle": {"max_rpm": 250, "change_factor": 1.2}})", extended));
    CHECK_THROWS_WITH(
        profile_from_json(
            R"({"spindle": {"max_rpm": 250, "change_at_s": 9, "change_factor": 1.2}})", extended),
        Catch::StartsWith("spindle.max_rpm:") && Catch::Contains("x change_factor 1.2") &&
            Catch::Contains("at most 208.33 rev/min"));
    CHECK_NOTHROW(profile_from_json(
        R"({"spindle": {"max_rpm": 208, "change_at_s": 9, "change_factor": 1.2}})", extended));
    CHECK_NOTHROW(profile_from_json(
        R"({"spindle": {"max_rpm": 250, "change_at_s": 9, "change_factor": 0.5}})", extended));
    // Half a revolution between two samples: 240 rev/min is 4 a second, so 0.125 s is exactly
    // half (refused) and 0.1249 s within; the lasting change counts here too.
    CHECK_THROWS_WITH(profile_from_json(R"({"spindle": {"sample_s": 0.125}})", extended),
                      Catch::StartsWith("spindle.sample_s:") &&
                          Catch::Contains("0.500 of a revolution") &&
                          Catch::Contains("below 0.1250 s"));
    CHECK_NOTHROW(profile_from_json(R"({"spindle": {"sample_s": 0.1249}})", extended));
    CHECK_THROWS_WITH(
        profile_from_json(
            R"({"spindle": {"max_rpm": 200, "sample_s": 0.1249, "change_at_s": 1, "change_factor": 1.25}})",
            extended),
        Catch::StartsWith("spindle.sample_s:"));
    // Faster switches follow a faster spindle; without spindle synchronisation nothing is judged.
    CHECK_NOTHROW(profile_from_json(
        R"({"spindle": {"max_rpm": 500}, "max_stepping_rate_per_s": 200})", extended));
    CHECK_NOTHROW(profile_from_json(R"({"spindle": {"max_rpm": 500}})", default_profile()));
    CHECK_THROWS_WITH(profile_from_json(R"({"spindle": {"max_rpm": 500}, "spindle_sync": true})",
                                        default_profile()),
                      Catch::StartsWith("spindle.max_rpm:"));
}
