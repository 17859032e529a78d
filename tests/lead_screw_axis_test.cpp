// The plant of one axis (axes/lead_screw_axis.hpp): motor dynamics and coast, tested on the
// plant alone.
#include "axes/lead_screw_axis.hpp"
#include "axes/state_json.hpp"

#include <catch2/catch.hpp>

using namespace parsons::axes;

namespace {

void run_to_rest(LeadScrewAxis& a) {
    while (a.next_event_time() != kNever) {
        a.advance_to(a.next_event_time());
    }
}

} // namespace

TEST_CASE("Coast: switched off, the motor brakes at braking_in_per_s2, not at its acceleration: "
          "coast = v^2 / 2 a_brake",
          "[axes][coast]") {
    for (double braking : {0.05, 0.2, 0.8}) {
        AxisProfile p = default_profile().axes.at(0);
        p.acceleration_in_per_s2 = 0.2;
        p.braking_in_per_s2 = braking;
        LeadScrewAxis a(p);
        a.command(+1, 1); // speed 1: 5.4 in/min
        while (a.impulses() < 300) {
            a.advance_to(a.next_event_time());
        }
        const double v = a.speed_in_per_s();
        REQUIRE(v == Approx(5.4 / 60));
        const double off_at = a.screw_in();
        a.command(+1, 0);
        run_to_rest(a);
        INFO("braking " << braking);
        CHECK(a.screw_in() == Approx(off_at + v * v / (2 * braking)).margin(1e-12));
        CHECK(a.speed_in_per_s() == 0);
        // Each thousandth of the coast gave its impulse.
        CHECK(a.commutator_index() == std::lround(a.screw_in() / kInchesPerImpulse));
    }
}

TEST_CASE("A speed change that ends at the very instant of an impulse leaves the screw on that "
          "impulse's crossing",
          "[axes][fastforward]") {
    // The third part of the fix for tests/fuzz/regressions/machine/tilt-real-position-differs:
    // the screw's place at one instant must not depend on whether the impulse or the end of the
    // speed change reached the plant first. A state is built (through save and load) in which
    // the acceleration ends exactly when an impulse was taken; the formula's position then
    // differs from the crossing's by rounding on some impulses, and the crossing must win.
    AxisProfile p = default_profile().axes.at(0);
    p.acceleration_in_per_s2 = 0.01; // a long run-up: many impulses while the speed changes
    p.screw_error_in = {{0.0, 0.0}, {5.0, 0.0031}};
    LeadScrewAxis a(p);
    a.command(+1, 1); // speed 1, the fastest
    int differing = 0;
    int tried = 0;
    while (tried < 400 && a.phase_acceleration() != 0) {
        if (!a.advance_to(a.next_event_time())) {
            continue;
        }
        ++tried;
        nlohmann::json state = a.save();
        const double t = exact(state.at("t"));
        const double crossing = exact(state.at("screw_in"));
        const double tau = t - exact(state.at("t0"));
        const double formula = exact(state.at("s0")) +
                               state.at("d").get<int>() * (exact(state.at("u0")) * tau +
                                                           0.5 * exact(state.at("a")) * tau * tau);
        differing += formula != crossing ? 1 : 0;
        state["phase_end"] = exact(t);
        state["next_time"] = exact(t);
        state["next_is_impulse"] = false;
        LeadScrewAxis b(p);
        b.load(state);
        const double real = b.real_in();
        b.advance_to(t); // the end of the speed change, at the impulse's instant
        INFO("impulse " << a.impulses());
        REQUIRE(b.screw_in() == crossing);
        REQUIRE(b.real_in() == real);
    }
    CHECK(tried == 400);
    CHECK(differing > 0); // the test can tell the two places apart
}

TEST_CASE("Travel limits: a crossing exactly on the lower limit is inside, the next one beyond",
          "[axes][limits][mutation]") {
    AxisProfile p = default_profile().axes.at(0);
    p.travel_min_in = -0.0005; // the crossing of the first impulse counting down from 0
    LeadScrewAxis a(p);
    a.command(-1, 1);
    CHECK(a.real_at_impulse(1) == p.travel_min_in);
    CHECK(a.impulses_to_limit() == 2);
    while (a.impulses() < 1) {
        a.advance_to(a.next_event_time());
    }
    CHECK_FALSE(a.beyond_limits()); // on the limit: inside
    while (a.impulses() < 2) {
        a.advance_to(a.next_event_time());
    }
    CHECK(a.beyond_limits());
}

TEST_CASE("Travel limits: a crossing exactly on the upper limit is inside, the next one beyond",
          "[axes][limits][mutation]") {
    AxisProfile p = default_profile().axes.at(0);
    p.travel_max_in = 0.0015; // the crossing of the second impulse counting up from 0
    LeadScrewAxis a(p);
    a.command(+1, 1);
    CHECK(a.real_at_impulse(2) == p.travel_max_in);
    CHECK(a.impulses_to_limit() == 3);
    while (a.impulses() < 2) {
        a.advance_to(a.next_event_time());
        CHECK_FALSE(a.beyond_limits());
    }
    while (a.impulses() < 3) {
        a.advance_to(a.next_event_time());
    }
    CHECK(a.beyond_limits());
}
