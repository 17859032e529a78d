// The plant of one axis (axes/lead_screw_axis.hpp): motor dynamics and coast, tested on the
// plant alone.
#include "axes/lead_screw_axis.hpp"

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
