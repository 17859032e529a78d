// Fast-forward against impulse level: the same machine, event for event.
//
// Each random deck runs four times: at impulse level and fast-forward with no observer (the
// results must be identical to the last bit: machine time, every counter, real positions,
// impulses, lost steps, the stop and its message), and again with an observer that records
// every signal change except those the impulses themselves drive (counter switches, comparers,
// stepping relay 256 and delay 258, which fast-forward reports a stretch at a time to an
// observer that does not follow impulses), plus every signal's value at each zeroizing. Those
// must be identical too: every relay event at the same instant, in the same order.
//
// The decks are plausible rather than valid: moves of every length, slow-downs well placed or
// too close, a wrong check or card number now and then, patterns that stall. The profiles vary
// speeds (some faster than the switches can step), stepping rate, acceleration, delay 258,
// screw error, travel limits, soft limits, separate registers, hundredths-only counting, the
// ribbon feed of Fig. 9, the readings of the patent and the additions, the measuring chain
// (backlash, lead error, instrument error and cam 160, screw-turn counting) and every kind of
// injected fault, so every kind of stretch end is met; each deck is fed on cards, on five
// cards a step or on perforated tape (col. 6).
#include "tests/machine_support.hpp"
#include "tests/random_decks.hpp"
#include "tests/test_support.hpp"

#include "cardreader/deck_io.hpp"
#include "cardreader/deck_review.hpp"
#include "relaylogic/fast_forward.hpp"

#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <array>
#include <random>
#include <sstream>

using namespace parsons;
using namespace parsons::cardreader;
using namespace parsons::relaylogic;
using parsons::test::Case;
using parsons::test::random_case;
using parsons::test::require_same;
using parsons::test::run_orders;

namespace {

// The press's signals that its detector edges drive (fast-forward takes quiet edges a stretch
// at a time, like quiet impulses).
bool press_driven(const SignalInfo& info) {
    if (info.scope != "press") {
        return false;
    }
    for (const char* prefix :
         {"detector_10", "direction_judging_13", "position_register_14", "setter_15",
          "speed_register_11.counter", "crank_21", "die_20", "motor_22"}) {
        if (info.name.rfind(prefix, 0) == 0) {
            return true;
        }
    }
    return false;
}

// Encoder 32's edges drive interface 33's relays likewise (spindle synchronisation).
bool encoder_driven(const SignalInfo& info) {
    return info.scope == "spindle" &&
           (info.name.rfind("encoder_32", 0) == 0 || info.name.rfind("interface_33", 0) == 0);
}

class Events : public MachineObserver {
public:
    explicit Events(bool follows) : follows_(follows) {}
    bool follows_impulses() const override { return follows_; }
    void on_signal_defined(const SignalInfo& info, std::uint32_t initial) override {
        const std::string& n = info.name;
        const bool driven = n.find("counter_") != std::string::npos ||
                            n.find("comparer") != std::string::npos || n == "stepping_relay_256" ||
                            n == "delay_device_258" || n.find("commutator_") == 0 ||
                            n.find("lamp_27") == 0 || press_driven(info) || encoder_driven(info);
        driven_.push_back(driven);
        values_.push_back(initial);
        if (n == "zeroizing_circuit_292") {
            zeroize_ = info.id;
        }
    }
    void on_signal(double t, SignalId id, std::uint32_t, std::uint32_t v) override {
        values_.at(id) = v;
        if (!driven_.at(id)) {
            events.emplace_back(t, id, v);
        }
        if (id == zeroize_ && v == 1) {
            at_zeroize.push_back(values_);
        }
    }
    void on_card(double t, long index, const CardOrders&) override { cards.emplace_back(t, index); }
    void on_stop(double t, const StopInfo& s) override { stops.emplace_back(t, s.message); }
    void on_condition(double t, const ConditionEvent& e) override {
        conditions.emplace_back(t, e.event, static_cast<int>(e.kind));
    }

    std::vector<std::tuple<double, int, int>> conditions; // condition cards (an addition)
    std::vector<std::tuple<double, SignalId, std::uint32_t>> events;
    std::vector<std::vector<std::uint32_t>> at_zeroize;
    std::vector<std::pair<double, long>> cards;
    std::vector<std::pair<double, std::string>> stops;

private:
    bool follows_;
    std::vector<bool> driven_;
    std::vector<std::uint32_t> values_;
    SignalId zeroize_ = 0;
};

RunResult run_at(const Case& c, Pace pace, MachineObserver* observer) {
    // The cards as punched, double punches made (a sync or tap card its layout cannot hold
    // throws: the generator's own mistake).
    const std::vector<Card> punched = test::punched_cards(c);
    std::ostringstream medium;
    DeckOptions options;
    options.format = c.medium;
    auto sink = open_card_sink(medium, options);
    for (const Card& card : punched) {
        sink->write(card);
    }
    std::istringstream fed(medium.str());
    auto source = open_card_source(fed, options);
    std::vector<Card> sensed;
    while (auto card = source->next()) {
        sensed.push_back(*card);
    }
    REQUIRE(sensed == punched);
    test::VectorDeck deck(sensed);
    ControlCabinet cabinet(c.profile, fig8_layout());
    for (const auto& f : c.faults) {
        cabinet.add_fault(f);
    }
    cabinet.set_pace(pace);
    cabinet.record_card_times(true);
    if (observer != nullptr) {
        cabinet.attach(observer);
    }
    return cabinet.run(deck);
}

} // namespace

TEST_CASE("Fast-forward: 240 random decks end exactly as at impulse level, result and relay "
          "events alike",
          "[fastforward][cabinet][heavy]") {
    std::mt19937 rng(1952);
    std::mt19937 crng(640901);
    std::mt19937 srng(436887);
    std::mt19937 trng(360190);
    long holes = 0;      // spindle synchronisation: tap cards that tapped
    int tap_stops = 0;   // ... runs that stopped on transfer_timeout or tap_refused
    long loop_backs = 0; // press synchronisation: loop cards that sent the reader back
    long resets = 0;     // ... and switch 16A operated by reset orders
    int synced = 0;      // runs with a press
    int timeouts = 0;    // ... that stopped on sync_timeout
    long impulses = 0;
    int stopped = 0;
    int lost = 0;
    int sensed_two_relays = 0; // parsons-1952 reading a double punch into two relays
    int interpretations = 0;
    long trips = 0;     // condition cards' actions acknowledged
    int not_met = 0;    // runs that stopped on condition_not_met
    int refused = 0;    // ... on condition_refused
    int interlocks = 0; // ... on tool_change_interlock
    // A quarter of them under the sanitizers (test_support.hpp).
    const int decks = parsons::test::share_of_cases(240);
    for (int n = 0; n < decks; ++n) {
        const Case c = random_case(rng, crng, srng, trng);
        INFO("deck " << n);
        const RunResult reference = run_at(c, Pace::impulse_level, nullptr);
        const RunResult jumped = run_at(c, Pace::fast_forward, nullptr);
        require_same(reference, jumped);

        Events followed(true);
        Events sparse(false);
        const RunResult traced = run_at(c, Pace::impulse_level, &followed);
        const RunResult skipped = run_at(c, Pace::fast_forward, &sparse);
        require_same(reference, traced);
        require_same(reference, skipped);
        REQUIRE(followed.events == sparse.events);
        REQUIRE(followed.at_zeroize == sparse.at_zeroize);
        REQUIRE(followed.cards == sparse.cards);
        REQUIRE(followed.stops == sparse.stops);
        REQUIRE(followed.conditions == sparse.conditions);
        trips += static_cast<long>(reference.actions.size());
        not_met += reference.stop && reference.stop->reason == StopReason::condition_not_met;
        refused += reference.stop && reference.stop->reason == StopReason::condition_refused;
        interlocks += reference.stop && reference.stop->reason == StopReason::tool_change_interlock;
        if (reference.tapping) {
            for (const HoleRecord& h : reference.tapping->holes) {
                holes += h.completed ? 1 : 0;
            }
            tap_stops +=
                reference.stop && (reference.stop->reason == StopReason::transfer_timeout ||
                                   reference.stop->reason == StopReason::tap_refused);
        }
        if (reference.press) {
            ++synced;
            loop_backs += reference.press->loop_backs;
            resets += reference.press->register_resets;
            timeouts += reference.stop && reference.stop->reason == StopReason::sync_timeout;
        }

        for (const auto& a : reference.axes) {
            impulses += a.impulses;
            lost += a.lost_steps > 0 ? 1 : 0;
        }
        stopped += reference.stop ? 1 : 0;
        const bool reader_refused =
            reference.stop && reference.stop->reason == StopReason::bad_punch;
        sensed_two_relays += !c.extra_punches.empty() && !reader_refused ? 1 : 0;
        interpretations += c.profile.incremental_equality_stops_at_any_speed ||
                                   c.profile.delay_258_waits_for_equality_to_leave
                               ? 1
                               : 0;
    }
    // The decks did what they are for: long runs, stops of several kinds, lost steps (all 240 of
    // them: a share is too few to say).
    if (!parsons::test::whole_share()) {
        return;
    }
    CHECK(impulses > 1'000'000);
    CHECK(stopped > 40);
    // At most seven in eight stop (a synchronised axis now follows a stopping press on every
    // speed, so more press decks end in sync_timeout than when its tails ran on the 1952 motor;
    // the sanitizer build's libm gives one more stop than the plain build's 200).
    CHECK(stopped < 210);
    CHECK(lost >= 2); // fewer since presses stop some of the long runs early (sync_timeout)
    CHECK(sensed_two_relays >= 3);
    CHECK(interpretations >= 40);
    CHECK(trips >= 40);
    CHECK(not_met >= 5);
    CHECK(refused >= 3);
    CHECK(interlocks >= 2);
    CHECK(synced >= 40);
    CHECK(loop_backs >= 5);
    CHECK(resets >= 5); // sync cards' reset orders (claim 5) taken at both paces
    CHECK(timeouts >= 2);
    CHECK(holes >= 20);
    CHECK(tap_stops >= 3);
}

TEST_CASE("Fast-forward: a jump leaves every stepping switch, its last-step time and the screw "
          "where taking the impulses one by one does",
          "[fastforward][counters]") {
    std::mt19937 rng(1953);
    auto pick = [&rng](long lo, long hi) {
        return std::uniform_int_distribution<long>(lo, hi)(rng);
    };
    const double min_interval = 1.0 / 100;
    for (int trial = 0; trial < 300; ++trial) {
        INFO("trial " << trial);
        Tracer tracer_a;
        Tracer tracer_b;
        axes::MachineProfile profile = axes::default_profile();
        profile.axes.at(0).travel_min_in = -1e6;
        profile.axes.at(0).travel_max_in = 1e6;
        AxisCircuit a(tracer_a, profile, Axis::table);
        AxisCircuit b(tracer_b, profile, Axis::table);
        const int motion = pick(0, 1) != 0 ? +1 : -1;
        const int counting = pick(0, 3) != 0 ? motion : -motion; // coast counted the wrong way
        const Digits start_abs = value_digits(static_cast<int>(pick(0, 9999)));
        const Digits start_inc = value_digits(static_cast<int>(pick(0, 9999)));
        for (AxisCircuit* c : {&a, &b}) {
            c->direction = counting;
            c->absolute_counter.jump(start_abs, {-1, -1, -1, -1});
            c->increment_counter.jump(start_inc, {-1, -1, -1, -1});
            c->plant.command(motion, 1);
        }
        // Both run through the same speed-up, impulse by impulse; then b jumps.
        auto step = [&](AxisCircuit& c) {
            const double t = c.plant.next_event_time();
            if (auto i = c.plant.advance_to(t)) {
                c.absolute_counter.impulse(c.direction, i->hundredths, i->tenths, i->inches, t,
                                           min_interval);
                c.increment_counter.impulse(t, min_interval);
                ++c.contact_set_a;
                ++c.contact_set_b;
            }
        };
        const long lead = pick(30, 3000);
        for (long i = 0; i < lead; ++i) {
            step(a);
            step(b);
        }
        const long n = pick(1, 30000);
        for (long i = 0; i < n; ++i) {
            step(a);
        }
        jump_quiet_impulses(b, n);
        REQUIRE(a.plant.commutator_index() == b.plant.commutator_index());
        REQUIRE(a.plant.impulses() == b.plant.impulses());
        REQUIRE(a.plant.next_event_time() == b.plant.next_event_time());
        REQUIRE(a.plant.real_in() == b.plant.real_in());
        REQUIRE(a.contact_set_a == b.contact_set_a);
        for (std::size_t i = 0; i < 4; ++i) {
            INFO("switch " << i);
            const auto& sa = a.absolute_counter.stepping_switch(i);
            const auto& sb = b.absolute_counter.stepping_switch(i);
            REQUIRE(sa.position() == sb.position());
            REQUIRE(sa.last_step_s() == sb.last_step_s());
            REQUIRE(sa.lost() == 0);
            const auto& ia = a.increment_counter.stepping_switch(i);
            const auto& ib = b.increment_counter.stepping_switch(i);
            REQUIRE(ia.position() == ib.position());
            REQUIRE(ia.last_step_s() == ib.last_step_s());
        }
    }
}

TEST_CASE("Fast-forward: decks that run into the lower limit switch stop on the same impulse, "
          "at the same place, as at impulse level",
          "[fastforward][limits]") {
    std::mt19937 rng(1954);
    auto pick = [&rng](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    auto real = [&rng](double lo, double hi) {
        return std::uniform_real_distribution<double>(lo, hi)(rng);
    };
    int at_limit = 0;
    for (int n = 0; n < 80; ++n) {
        INFO("deck " << n);
        Case c;
        const auto axis = kAxes.at(static_cast<std::size_t>(pick(0, 4)));
        auto& a = c.profile.axes.at(axis_index(axis));
        // Back to 0.000 at speed 1 with no slow-down: the part coasts some 0.020 in below zero,
        // onto a limit switch a little below it.
        a.travel_min_in = -real(0.0001, 0.025);
        a.backlash_in = pick(0, 1) != 0 ? real(0, 0.003) : 0.0;
        c.profile.measuring_chain = pick(0, 2) == 0 ? axes::MeasuringChain::screw_turns
                                                    : axes::MeasuringChain::instrument_shaft_74;
        const int to = pick(400, 3000);
        std::array<int, 5> at{};
        CardOrders out = test::idle_card(1, at);
        out.axis(axis) = axis == Axis::table ? test::order(0, to, 1, to - 200, to - 100)
                                             : test::order(0, to, 2, to - 100);
        out.axis(axis).sequence = test::idle_card(1, at).axis(axis).sequence;
        at.at(axis_index(axis)) = to;
        CardOrders back = test::idle_card(2, at);
        back.axis(axis) = test::order(to, 0, 1);
        back.axis(axis).sequence = out.axis(axis).sequence;
        c.cards = {out, back};
        const RunResult reference = run_at(c, Pace::impulse_level, nullptr);
        const RunResult jumped = run_at(c, Pace::fast_forward, nullptr);
        require_same(reference, jumped);
        if (reference.stop && reference.stop->reason == StopReason::limit_switch) {
            ++at_limit;
            CHECK_THAT(reference.stop->message, Catch::Contains("travel limit"));
        }
    }
    CHECK(at_limit > 40); // the decks did reach the switch
}
