// The 1952 spindle motor (rule 11): column 1 sets spindle control 165 at once, but the motor
// runs down and up again in the profile's times, and nothing in the control waits for it.
#include "tests/machine_support.hpp"

#include <catch2/catch.hpp>

using namespace parsons;
using namespace parsons::cardreader;
using namespace parsons::relaylogic;
using namespace parsons::test;

namespace {

struct SpindleRun {
    RunResult result;
    Recorder rec;
};

// Card 1: spindle forward while the table moves 0.100 in at speed 3 (long enough for the motor
// to come to speed). Card 2: spindle reverse; the tilt cuts 0.010 in at position 5.
SpindleRun run_reversal(const axes::MachineProfile& profile) {
    CardOrders one = idle_card(1, {0, 0, 0, 0, 0});
    one.spindle = Spindle::forward;
    one.axis(Axis::table) = order(0, 100, 3, {}, {}, 1);
    CardOrders two = idle_card(2, {100, 0, 0, 0, 0});
    two.spindle = Spindle::reverse;
    two.axis(Axis::tilt) = order(0, 10, 3, {}, {}, 16);
    std::vector<Card> punched;
    for (const auto& o : {one, two}) {
        punched.push_back(encode(o, fig8_layout()).card);
    }
    VectorDeck deck(punched);
    ControlCabinet cabinet(profile, fig8_layout());
    cabinet.record_card_times(true);
    SpindleRun run;
    cabinet.attach(&run.rec);
    run.result = cabinet.run(deck);
    return run;
}

std::vector<Change> to(const Recorder& rec, const std::string& signal, std::uint32_t value) {
    std::vector<Change> out;
    for (const Change& c : rec.of(signal)) {
        if (c.new_value == value) {
            out.push_back(c);
        }
    }
    return out;
}

} // namespace

TEST_CASE("Spindle motor: column 1 reverses spindle control 165 at once, the motor runs down in "
          "spindle_run_down_s and up in spindle_run_up_s, and a cut that begins before it is at "
          "speed is reported, not waited for",
          "[machine][spindle][rule11]") {
    const axes::MachineProfile profile = axes::default_profile();
    REQUIRE(profile.actions.spindle_run_down_s != profile.actions.spindle_run_up_s);
    SpindleRun run = run_reversal(profile);
    REQUIRE(run.result.completed);
    const std::string motor = "cabinet.spindle_motor";

    // From rest it only runs up: changing at card 1's relays, forward at speed run_up later.
    const auto changing = to(run.rec, motor, 3);
    const auto forward = to(run.rec, motor, 1);
    REQUIRE(changing.size() == 2);
    REQUIRE(forward.size() == 1);
    const double t1 = changing.at(0).t;
    CHECK(to(run.rec, "cabinet.spindle_control_165", 1).at(0).t == t1);
    CHECK(forward.at(0).t == Approx(t1 + profile.actions.spindle_run_up_s).margin(1e-9));

    // Card 2 reverses control 165 at once; the motor runs down, then up the other way.
    const double t2 = changing.at(1).t;
    CHECK(to(run.rec, "cabinet.spindle_control_165", 2).at(0).t == t2);
    CHECK(forward.at(0).t < t2);
    const double ready = t2 + profile.actions.spindle_run_down_s + profile.actions.spindle_run_up_s;

    // The tilt starts cutting at once (no interlock is shown), long before that.
    double cut = -1;
    for (const Change& c : to(run.rec, "cabinet.spindle_control_165.cutting", 1)) {
        if (c.t > t2 && cut < 0) {
            cut = c.t;
        }
    }
    CHECK(cut > t2);
    CHECK(cut < ready);
    REQUIRE(run.result.cards.size() == 2);
    CHECK(run.result.cards.at(0).cut_unready_s < 0);
    CHECK(run.result.cards.at(1).cut_unready_s == cut);
    CHECK(run.result.cards.at(1).spindle_ready_s == Approx(ready).margin(1e-9));
    // The deck ends before the motor is at speed: its instant does not keep the run going.
    CHECK(run.result.machine_seconds < ready);
    CHECK(to(run.rec, motor, 2).empty());

    SECTION("a motor that changes at once cuts at speed, and the machine's time is the same") {
        axes::MachineProfile instant = profile;
        instant.actions.spindle_run_down_s = 0;
        instant.actions.spindle_run_up_s = 0;
        SpindleRun quick = run_reversal(instant);
        REQUIRE(quick.result.completed);
        CHECK(quick.result.cards.at(1).cut_unready_s < 0);
        CHECK(to(quick.rec, motor, 3).empty());
        CHECK(quick.result.machine_seconds == run.result.machine_seconds);
    }
}
