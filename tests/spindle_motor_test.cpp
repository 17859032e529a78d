// The 1952 spindle motor (rule 11): column 1 sets spindle control 165 at once, but the motor
// runs down and up again in the profile's times, and nothing in the control waits for it.
#include "tests/machine_support.hpp"

#include "axes/profile_json.hpp"

#include <catch2/catch.hpp>

#include <algorithm>

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

namespace {

// Machine time as the observer is told it: how often it stepped back, and when the 1952 spindle
// motor came to speed.
class TimeOrder : public MachineObserver {
public:
    void on_signal_defined(const SignalInfo& info, std::uint32_t) override {
        if (info.scope == "cabinet" && info.name == "spindle_motor") {
            motor_ = info.id;
        }
    }
    void on_signal(double t, SignalId id, std::uint32_t, std::uint32_t value) override {
        see(t);
        if (id == motor_ && value == 1) {
            at_speed_s = t;
        }
    }
    void on_motion(double t, const std::array<double, 5>&) override { see(t); }
    int backwards = 0;
    double at_speed_s = -1;

private:
    void see(double t) {
        backwards += t < last_ ? 1 : 0;
        last_ = std::max(last_, t);
    }
    SignalId motor_ = ~SignalId{0};
    double last_ = 0;
};

} // namespace

TEST_CASE("Spindle motor: the 1952 motor coming to speed during a tap (spindle synchronisation, "
          "an addition) is reported after motor 27's encoder edges before it, never before them",
          "[machine][spindle][rule11][tapping]") {
    // Found by the machine fuzz target (tests/fuzz/regressions/machine/tapping-edge-before-stop):
    // the motor's instant was reported before the attachment's plants were caught up to it.
    axes::MachineProfile profile =
        axes::profile_from_json(R"({"press_sync": false})", axes::extended_profile());
    CardOrders one = idle_card(1, {0, 0, 0, 0, 0});
    one.spindle = Spindle::forward;
    CardOrders two;
    two.kind = CardKind::tap;
    two.number = 2;
    two.tap.tool = profile.spindle.first_tool;
    two.tap.axis = Axis::vertical;
    two.tap.motion = Motion::forward;
    two.tap.depth = 200;
    two.tap.pitch = 5000; // 0.05 in
    two.tap.rpm = 120;
    std::vector<Card> punched;
    for (const auto& o : {one, two}) {
        auto e = encode(o, fig8_layout());
        REQUIRE(e);
        punched.push_back(e.card);
    }
    int backwards = 0;
    // Motor 27's edges and the tap's samples fall each side of the instant at several run-ups.
    for (const double run_up_s : {2.5, 2.5013, 2.5029, 2.5047, 2.5061, 2.5083}) {
        profile.actions.spindle_run_up_s = run_up_s;
        for (const Pace pace : {Pace::impulse_level, Pace::fast_forward}) {
            VectorDeck deck(punched);
            ControlCabinet cabinet(profile, fig8_layout());
            cabinet.set_pace(pace);
            TimeOrder order;
            cabinet.attach(&order);
            const RunResult r = cabinet.run(deck);
            INFO((pace == Pace::impulse_level ? "impulse level" : "fast-forward")
                 << ", run-up " << run_up_s
                 << " s: " << (r.stop ? r.stop->message : std::string("completed")));
            REQUIRE(r.completed);
            REQUIRE(r.tapping);
            REQUIRE(r.tapping->holes.size() == 1);
            // The motor came to speed while motor 27 turned, and the tap went on.
            CHECK(r.tapping->holes.at(0).start_s < order.at_speed_s);
            CHECK(order.at_speed_s < r.tapping->holes.at(0).end_s);
            CHECK(r.tapping->holes.at(0).completed);
            backwards += order.backwards;
        }
    }
    CHECK(backwards == 0);
}
