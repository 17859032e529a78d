// The contouring attachment (an addition after EP 0636958, Black & Decker; docs/contouring.md):
// the motor's lost steps, the control cycle's decision (claims 1, 2, 4, 7, 8), the interpolator's
// plan, and small programs run on the cabinet, every figure worked by hand.
#include "tests/machine_support.hpp"

#include "axes/stepper_motor.hpp"
#include "cardreader/segment_card.hpp"
#include "cardreader/segment_listing.hpp"
#include "relaylogic/contouring/interpolator.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace parsons;
using namespace parsons::cardreader;
using namespace parsons::relaylogic;
using parsons::test::VectorDeck;

namespace contouring_test {

SegmentOrder to(int x, int y, int z, int feed) {
    SegmentOrder g;
    g.to = {static_cast<Thousandths>(x), static_cast<Thousandths>(y), static_cast<Thousandths>(z)};
    g.feed = feed;
    return g;
}

RunResult run_segments(const std::vector<SegmentOrder>& orders, const axes::MachineProfile& p) {
    std::vector<Card> cards;
    int number = 1;
    for (const SegmentOrder& g : orders) {
        auto e = segment_card(g, number++);
        REQUIRE(e);
        cards.push_back(e.card);
    }
    VectorDeck deck(cards);
    ControlCabinet cabinet(p, fig8_layout());
    return cabinet.run(deck);
}

axes::MachineProfile with(axes::JunctionPolicy policy) {
    axes::MachineProfile p = axes::extended_profile();
    p.contour.junctions = policy;
    return p;
}

} // namespace contouring_test
using namespace contouring_test;

TEST_CASE("Contouring motor: a jump of the pulse rate beyond pull-in loses (|jump| - J)^2 / 2A "
          "steps",
          "[contouring]") {
    // J 100 steps/s, A 2000 steps/s2. 20 in/min at 1000 steps/in is 333.33 steps/s: stopping
    // it at once loses (233.33)^2 / 4000 = 13.61, 14 steps; the rotor runs past the pulses.
    CHECK(axes::steps_lost(1000.0 / 3, 100, 2000) == 14);
    CHECK(axes::steps_lost(-1000.0 / 3, 100, 2000) == 14);
    CHECK(axes::steps_lost(100, 100, 2000) == 0); // exactly the pull-in rate: followed
    CHECK(axes::steps_lost(200, 100, 2000) == 3); // 100^2 / 4000 = 2.5, rounded to 3
    axes::StepperMotor m(100, 2000);
    m.ramp_to(1000.0 / 3);
    CHECK(m.jump_to(0) == 14);
    CHECK(m.offset() == 14); // slowed at once: the rotor ran 14 steps past its pulses
    CHECK(m.jump_to(-1000.0 / 3) == 14);
    CHECK(m.offset() == 28); // sped up towards minus: 14 more behind it, towards plus
    CHECK(m.lost() == 28);
}

TEST_CASE("Contouring control cycle (claims 1, 2): pass within the maximum difference of the "
          "motors' pulse rates, slow beyond it",
          "[contouring]") {
    const axes::ContourProfile p;
    const PathSegment x = make_segment({0, 0, 0}, to(2000, 0, 0, 200), 1, 1);
    // A 90-degree corner at 20 in/min: X from 333.33 to 0, Y from 0 to 333.33 steps/s.
    const PathSegment y = make_segment(x.to, to(2000, 1000, 0, 200), 2, 2);
    JunctionDecision j = control_cycle(x, y, p);
    CHECK(j.difference == Approx(1000.0 / 3));
    CHECK(j.kind == JunctionKind::slowed_rate);
    CHECK(j.exit == 0); // claim 4: the minimum is zero
    CHECK(j.entry == 0);
    // A turn of 15 degrees: Y from 0 to 333.33 sin 15 = 86.27, X by 11.36: passed at speed.
    const PathSegment turn = make_segment(x.to, to(2966, 259, 0, 200), 2, 2);
    j = control_cycle(x, turn, p);
    CHECK(j.difference == Approx(86.3).margin(0.1));
    CHECK(j.kind == JunctionKind::passed);
    CHECK(j.exit == Approx(1.0 / 3));
    CHECK(j.entry == Approx(1.0 / 3));
    // At the maximum exactly it passes; a hair above, it slows.
    axes::ContourProfile at = p;
    at.max_rate_change_steps_per_s = control_cycle(x, y, p).difference;
    CHECK(control_cycle(x, y, at).kind == JunctionKind::passed);
    at.max_rate_change_steps_per_s = std::nextafter(at.max_rate_change_steps_per_s, 0.0);
    CHECK(control_cycle(x, y, at).kind == JunctionKind::slowed_rate);
    // The policies: the rule off passes the corner; "minimum" slows even a straight junction.
    axes::ContourProfile pass = p;
    pass.junctions = axes::JunctionPolicy::pass;
    CHECK(control_cycle(x, y, pass).kind == JunctionKind::passed);
    axes::ContourProfile minimum = p;
    minimum.junctions = axes::JunctionPolicy::minimum;
    const PathSegment on = make_segment(x.to, to(4000, 0, 0, 200), 2, 2);
    CHECK(control_cycle(x, on, p).kind == JunctionKind::passed);
    CHECK(control_cycle(x, on, minimum).kind == JunctionKind::slowed_always);
    // A minimum speed of 6 in/min: the corner is met at 0.1 in/s.
    axes::ContourProfile six = p;
    six.minimum_in_per_min = 6;
    CHECK(control_cycle(x, y, six).exit == Approx(0.1));
}

TEST_CASE("Contouring control cycle (claims 7, 8): a next segment shorter than the ramp from its "
          "nominal speed to the minimum is met slowly",
          "[contouring]") {
    const axes::ContourProfile p; // ramps 1000 steps/s2 at 1000 steps/in: 1 in/s2
    const PathSegment x = make_segment({0, 0, 0}, to(2000, 0, 0, 200), 1, 1);
    // The ramp from 1/3 in/s to 0 at 1 in/s2 is (1/3)^2 / 2 = 0.0556 in.
    const PathSegment shorter = make_segment(x.to, to(2055, 0, 0, 200), 2, 2);
    const PathSegment longer = make_segment(x.to, to(2056, 0, 0, 200), 2, 2);
    JunctionDecision j = control_cycle(x, shorter, p);
    CHECK(j.ramp == Approx(1.0 / 18));
    CHECK(j.kind == JunctionKind::slowed_short);
    CHECK(control_cycle(x, longer, p).kind == JunctionKind::passed);
    axes::ContourProfile off = p;
    off.short_segment_rule = false;
    CHECK(control_cycle(x, shorter, off).kind == JunctionKind::passed);
}

TEST_CASE("Contouring interpolator: a segment's plan ramps at the path acceleration, cruises and "
          "ramps down, and too short a segment leaves faster than asked",
          "[contouring]") {
    // 2 in at 1/3 in/s from rest to rest, a = 1 in/s2: ramps of 1/3 s and 1/18 in each, the
    // cruise (2 - 1/9) / (1/3) = 5.6667 s: 6.3333 s in all.
    SegmentPlan plan = plan_segment(0, 0, 0, 2, 1.0 / 3, 0, 1);
    REQUIRE(plan.phases.size() == 3);
    CHECK(plan.phases[0].duration == Approx(1.0 / 3));
    CHECK(plan.phases[1].duration == Approx(17.0 / 3));
    CHECK(plan.phases.back().end() == Approx(19.0 / 3));
    CHECK(plan.phases.back().s_at(plan.phases.back().end()) == Approx(2));
    CHECK(plan.reaches_exit);
    // 0.03 in entered at 1/3 in/s and to be left at rest: it can only shed to
    // sqrt(1/9 - 0.06) = 0.2261 in/s.
    plan = plan_segment(0, 0, 1.0 / 3, 0.03, 1.0 / 3, 0, 1);
    CHECK_FALSE(plan.reaches_exit);
    CHECK(plan.exit_speed == Approx(std::sqrt(1.0 / 9 - 0.06)));
}

TEST_CASE("Contouring (EP 0636958): the corner rule loses no step where passing at speed loses "
          "28, and takes less time than slowing at every junction",
          "[contouring]") {
    // Out 2 in along X, a 90-degree corner, 1 in along Y, a turn of 15 degrees, 1 in on.
    const std::vector<SegmentOrder> program = {to(2000, 0, 0, 200), to(2000, 1000, 0, 200),
                                               to(2259, 1966, 0, 200)};
    const RunResult rule = run_segments(program, with(axes::JunctionPolicy::rule));
    const RunResult pass = run_segments(program, with(axes::JunctionPolicy::pass));
    const RunResult minimum = run_segments(program, with(axes::JunctionPolicy::minimum));
    REQUIRE(rule.completed);
    REQUIRE(rule.contouring);
    const ContouringResult& r = *rule.contouring;
    REQUIRE(r.junctions.size() == 2);
    CHECK(r.junctions[0].kind == JunctionKind::slowed_rate);
    CHECK(r.junctions[0].speed_in_per_min == Approx(0).margin(1e-9));
    CHECK(r.junctions[1].kind == JunctionKind::passed);
    CHECK(r.junctions[1].speed_in_per_min == Approx(20));
    // Claim 6: the second segment's parameters are computed while the first is travelled.
    CHECK(r.junctions[0].decided_s < r.junctions[0].at_s);
    CHECK(r.junctions[0].decided_at_in > 0);
    CHECK(r.junctions[0].decided_at_in < 2);
    CHECK(r.lost == std::array<std::int64_t, 3>{0, 0, 0});
    // Passed at speed, the corner jumps X by -333.33 and Y by +333.33 steps/s: 14 steps each
    // (the first test), X run past its pulses, Y behind them; the turn of 15 degrees loses none
    // (86.3 and 11.4 steps/s, within J). The path as cut ends sqrt(2) x 0.014 = 0.0198 in off.
    REQUIRE(pass.contouring);
    CHECK(pass.contouring->lost == std::array<std::int64_t, 3>{14, 14, 0});
    CHECK(pass.contouring->offset_in[0] == Approx(0.014));
    CHECK(pass.contouring->offset_in[1] == Approx(-0.014));
    CHECK(pass.contouring->largest_offset_in == Approx(0.014 * std::sqrt(2.0)));
    // Times: passing skips the two ramps of the corner (1/3 s each, at 1 in/s2 from 1/3 in/s:
    // the ramps cover 1/9 in that cruise would take 1/3 s over): 1/3 s faster than the rule;
    // slowing the straight-on turn too costs the rule's run another 1/3 s.
    CHECK(rule.contouring->motion_s - pass.contouring->motion_s == Approx(1.0 / 3).margin(1e-6));
    CHECK(minimum.contouring->motion_s - rule.contouring->motion_s == Approx(1.0 / 3).margin(1e-6));
    CHECK(minimum.contouring->lost == std::array<std::int64_t, 3>{0, 0, 0});
}

TEST_CASE("Contouring: a segment card is refused by a profile without contouring, and read back "
          "from its listing row",
          "[contouring]") {
    const RunResult r = run_segments({to(1000, 0, 0, 200)}, axes::default_profile());
    REQUIRE(r.stop);
    CHECK(r.stop->reason == StopReason::segment_refused);
    CHECK_THAT(r.stop->message, Catch::Contains("EP 0636958"));
    const auto [number, g] = read_segment_row("7,segment,2.000,0.500,0.125,20.5", "deck.csv", 3);
    CHECK(number == 7);
    CHECK(g == to(2000, 500, 125, 205));
    CardOrders o;
    o.kind = CardKind::segment;
    o.number = 7;
    o.segment = g;
    CHECK(segment_row(o) == "7,segment,2.000,0.500,0.125,20.5");
    auto e = segment_card(g, 7);
    REQUIRE(e);
    const DecodeResult back = decode(e.card, fig8_layout());
    REQUIRE(back);
    CHECK(back.orders == o);
    CHECK_THROWS_WITH(read_segment_row("7,segment,2.000,0.500,0.125,0.0", "deck.csv", 3),
                      Catch::Contains("deck.csv:3") && Catch::Contains("no speed"));
    CHECK_THROWS_WITH(read_segment_row("7,segment,2.000,0.500,0.125,100.0", "deck.csv", 3),
                      Catch::Contains("over 99.9"));
}

TEST_CASE("Contouring trace (claims 3, 6): the stepper motors' pulse periods, and the decision "
          "made while the first segment is travelled",
          "[contouring]") {
    std::vector<CardOrders> cards;
    int number = 1;
    for (const SegmentOrder& g : {to(2000, 0, 0, 200), to(2000, 1000, 0, 200)}) {
        CardOrders o;
        o.kind = CardKind::segment;
        o.number = number++;
        o.segment = g;
        cards.push_back(o);
    }
    parsons::test::Recorder rec;
    const RunResult r = parsons::test::run_orders(cards, axes::extended_profile(), &rec);
    REQUIRE(r.completed);
    REQUIRE(r.contouring);
    // 20 in/min along X alone: 333.33 steps/s, a pulse every 3000 microseconds while it cruises.
    const auto x = rec.of("contouring.X.pulse_period_us");
    CHECK(std::any_of(x.begin(), x.end(), [](const auto& c) { return c.new_value == 3000; }));
    CHECK(x.back().new_value == 0); // at rest at the corner
    const auto y = rec.of("contouring.Y.pulse_period_us");
    REQUIRE_FALSE(y.empty());
    CHECK(y.front().t >= r.contouring->junctions.at(0).at_s); // Y starts only at the corner
    // The decision (2: slowed, X changes by 333 steps/s) comes as card 2 is read, 1.2 s into
    // the run, while the tool is 1/18 + (0.6 - 1/3) / 3 = 0.144 in along the first segment.
    const auto j = rec.of("contouring.junction");
    REQUIRE_FALSE(j.empty());
    CHECK(j.front().new_value == 2);
    CHECK(j.front().t == Approx(1.2));
    CHECK(j.front().t < r.contouring->junctions.at(0).at_s);
    CHECK(rec.of("contouring.rate_difference").front().new_value == 333);
    CHECK(r.contouring->junctions.at(0).decided_at_in == Approx(1.0 / 18 + (0.6 - 1.0 / 3) / 3));
}
