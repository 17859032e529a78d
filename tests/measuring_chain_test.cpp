// The measuring chain of Fig. 3 (docs/design-rules.md rule 3; claims 8-10, 23): lead screw 22 and
// nut 78 (lead error, backlash, slip), instrument shaft 74 and cam 160, and what the counters
// measure with the patent's chain and with screw-turn counting (a departure).
#include "tests/machine_support.hpp"

#include "axes/instrument_shaft.hpp"
#include "axes/lead_screw_axis.hpp"
#include "axes/lead_screw_nut.hpp"
#include "axes/profile_json.hpp"
#include "axes/screw_error_table.hpp"
#include "outputs/report/run_report.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <optional>
#include <random>

using namespace parsons;
using namespace parsons::cardreader;
using namespace parsons::relaylogic;
using namespace parsons::test;
using axes::MeasuringChain;

namespace {

axes::MachineProfile chain_profile(MeasuringChain chain) {
    auto p = axes::default_profile();
    p.measuring_chain = chain;
    return p;
}

// The table out to 1.000 and back to 0.500 at speed 3, every other axis idle.
std::vector<CardOrders> out_and_back() {
    CardOrders out = idle_card(1, {0, 0, 0, 0, 0});
    out.axis(Axis::table) = order(0, 1000, 3);
    CardOrders back = idle_card(2, {1000, 0, 0, 0, 0});
    back.axis(Axis::table) = order(1000, 500, 3);
    return {out, back};
}

} // namespace

TEST_CASE("Screw error table: interpolates, holds its ends, inverts, and sums exactly at its "
          "positions",
          "[axes][chain]") {
    const axes::ScrewErrorTable t({{0.0, 0.001}, {5.0, -0.002}, {10.0, 0.004}});
    CHECK(t.apply(0.0) == 0.001);
    CHECK(t.apply(-3.0) == -3.0 + 0.001);
    CHECK(t.apply(12.0) == 12.0 + 0.004);
    CHECK(t.apply(2.5) == Approx(2.5 - 0.0005).margin(1e-15));
    CHECK(t.error_at(7.5) == Approx(0.001).margin(1e-15));
    std::mt19937 rng(74);
    for (int i = 0; i < 200; ++i) {
        const double x = std::uniform_real_distribution<double>(-2, 12)(rng);
        CHECK(t.invert(t.apply(x)) == Approx(x).margin(1e-12));
    }
    const axes::ErrorPoints a = {{0.0, 0.002}, {10.0, 0.004}};
    const axes::ErrorPoints b = {{5.0, 0.001}};
    const auto sum = axes::ScrewErrorTable::sum({{&a, 1}, {&b, -1}});
    REQUIRE(sum.points().size() == 3);
    CHECK(sum.points().at(1).first == 5.0);
    CHECK(sum.points().at(1).second == Approx(0.003 - 0.001).margin(1e-15));
    CHECK(sum.points().at(0).second == Approx(0.002 - 0.001).margin(1e-15));
    // One table alone comes back to the last bit.
    const axes::ErrorPoints empty;
    CHECK(axes::ScrewErrorTable::sum({{&a, 1}, {&empty, -1}}).points() == a);
    CHECK(axes::ScrewErrorTable({{0.0, 0.0}, {1.0, -1.0}}).falls_after() == 0.0);
}

TEST_CASE("Nut 78: backlash is screw travel with the part standing, a slip is used up once, "
          "and a stretch begun twice at one place is the same stretch",
          "[axes][chain]") {
    axes::LeadScrewNut nut(0.002, axes::ScrewErrorTable());
    nut.reset_at(0);
    nut.rebase(0, +1);
    CHECK(nut.sigma_at(0.5) == 0.5);
    nut.rebase(0.5, -1); // reverse: the screw must turn back 0.002 first
    CHECK(nut.sigma_at(0.499) == 0.5);
    CHECK(nut.sigma_at(0.498) == 0.5);
    CHECK(nut.sigma_at(0.497) == Approx(0.499).margin(1e-15));
    CHECK(nut.screw_at(0.499) == Approx(0.497).margin(1e-15));
    const double o_end = nut.o_end();
    nut.rebase(0.4985, -1);
    nut.rebase(0.4985, -1);
    CHECK(nut.o_end() == o_end);
    CHECK(nut.sigma_at(0.4975) == Approx(0.4995).margin(1e-15));
    nut.rebase(0.3, +1); // forward again: the gap again, then the part follows
    CHECK(nut.sigma_at(0.302) == Approx(0.302).margin(1e-15));
    CHECK(nut.sigma_at(0.301) == Approx(0.302).margin(1e-15));

    axes::LeadScrewNut slipping(0, axes::ScrewErrorTable());
    slipping.reset_at(1.0);
    slipping.rebase(1.0, +1, 0.010); // the drive slips for 0.010 in of screw travel
    CHECK(slipping.sigma_at(1.006) == 1.0);
    CHECK(slipping.sigma_at(1.012) == Approx(1.002).margin(1e-15));
    slipping.rebase(1.004, -1); // reversed after 0.004: 0.006 still to slip, going back
    CHECK(slipping.slip_in() == Approx(-0.004).margin(1e-15));
    CHECK(slipping.slip_left_in() == Approx(0.006).margin(1e-15));
    CHECK(slipping.sigma_at(0.999) == 1.0);
    CHECK(slipping.sigma_at(0.997) == Approx(0.999).margin(1e-15));
    slipping.rebase(0.99, +1);
    CHECK(slipping.slip_left_in() == 0);
    CHECK(slipping.slip_in() == Approx(-0.004 + 0.006).margin(1e-15));
}

TEST_CASE("Measuring chain: backlash in nut 78 is counted by instrument shaft 74 and the part "
          "stops on its number, counting screw turns it ends a backlash off, unseen",
          "[cabinet][chain]") {
    for (MeasuringChain chain :
         {MeasuringChain::instrument_shaft_74, MeasuringChain::screw_turns}) {
        auto profile = chain_profile(chain);
        profile.axes.at(0).backlash_in = 0.003;
        const RunResult r = run_orders(out_and_back(), profile);
        const RunResult perfect = run_orders(out_and_back(), chain_profile(chain));
        REQUIRE(r.completed); // every 1952 check passes either way
        CHECK(r.axes.at(0).counter_in == Approx(0.500));
        if (chain == MeasuringChain::instrument_shaft_74) {
            // Stop impulse at 0.5005 going down, coast 0.00025: the part at 0.50025.
            CHECK(r.axes.at(0).real_in == Approx(0.50025).margin(1e-12));
            CHECK(r.axes.at(0).screw_in == Approx(0.50025 - 0.003).margin(1e-12));
            // The screw turned 0.003 in more, at speed 3 (0.01 in/s): 0.3 s longer.
            CHECK(r.machine_seconds - perfect.machine_seconds == Approx(0.3).margin(1e-9));
        } else {
            CHECK(r.axes.at(0).screw_in == Approx(0.50025).margin(1e-12));
            CHECK(r.axes.at(0).real_in == Approx(0.50325).margin(1e-12));
            CHECK(r.axes.at(0).error_in == Approx(0.00325).margin(1e-12));
            CHECK(r.machine_seconds == Approx(perfect.machine_seconds).margin(1e-12));
        }
    }
}

TEST_CASE("Measuring chain: lead screw 22's lead error is measured, counting its turns it is "
          "not",
          "[cabinet][chain]") {
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::table) = order(0, 2000, 3);
    for (MeasuringChain chain :
         {MeasuringChain::instrument_shaft_74, MeasuringChain::screw_turns}) {
        auto profile = chain_profile(chain);
        profile.axes.at(0).lead_error_in = {{0.0, 0.0}, {10.0, 0.010}}; // 1 thousandth an inch
        const RunResult r = run_orders({c}, profile);
        REQUIRE(r.completed);
        CHECK(r.axes.at(0).counter_in == Approx(2.000));
        if (chain == MeasuringChain::instrument_shaft_74) {
            CHECK(r.axes.at(0).real_in == Approx(1.9995 + 1.001 * 0.00025).margin(1e-12));
            CHECK(r.axes.at(0).screw_in == Approx(1.9995 / 1.001 + 0.00025).margin(1e-12));
        } else {
            CHECK(r.axes.at(0).screw_in == Approx(1.99975).margin(1e-12));
            CHECK(r.axes.at(0).real_in == Approx(1.001 * 1.99975).margin(1e-12));
        }
    }
}

namespace {

// The probe of issue 29 (item 3): the table out to 4.985 at speed 1, slowing at 4.785 and
// 4.885; a lead screw 22 a thousandth an inch long.
CardOrders table_to_4985() {
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::table) = order(0, 4985, 1, 4785, 4885);
    return c;
}
const axes::ErrorPoints kLongLead = {{0.0, 0.0}, {10.0, 0.010}};

} // namespace

TEST_CASE("Measuring chain: cam 160 corrects lead screw 22 (\"illustrated herein at 160 for the "
          "table lead screw 22\"): a cam cut to its lead error leaves the part where the "
          "counters say and the screw turning as a perfect one",
          "[cabinet][chain][cam-160]") {
    const RunResult perfect = run_orders({table_to_4985()}, axes::default_profile());
    REQUIRE(perfect.completed);
    // The stop impulse as the counters pass 4.9845, the coast 0.00025 on.
    CHECK(perfect.axes.at(0).real_in == Approx(4.98475).margin(1e-12));
    CHECK(perfect.axes.at(0).screw_in - perfect.axes.at(0).counter_in ==
          Approx(-0.00025).margin(1e-12));

    auto profile = axes::default_profile();
    profile.axes.at(0).lead_error_in = kLongLead;
    const RunResult worn = run_orders({table_to_4985()}, profile);
    REQUIRE(worn.completed);
    // Instrument shaft 74 measures the lead error: the part stops where the counters say,
    // the screw short of it by the error.
    CHECK(worn.axes.at(0).real_in == Approx(4.9845 + 1.001 * 0.00025).margin(1e-12));
    CHECK(worn.axes.at(0).screw_in == Approx(4.9845 / 1.001 + 0.00025).margin(1e-12));

    profile.axes.at(0).cam_160_in = kLongLead; // the cam cut to that error
    const RunResult cam = run_orders({table_to_4985()}, profile);
    REQUIRE(cam.completed);
    CHECK(cam.axes.at(0).real_in == Approx(perfect.axes.at(0).real_in).margin(1e-9));
    CHECK(cam.axes.at(0).error_in == Approx(-0.00025).margin(1e-9));
    CHECK(cam.axes.at(0).screw_in - cam.axes.at(0).counter_in == Approx(-0.00025).margin(1e-9));
    CHECK(cam.machine_seconds == Approx(perfect.machine_seconds).margin(1e-9));

    // With instrument shaft 74's own error the cam on screw 22 changes nothing the counters
    // read: that error stays, unseen.
    auto shaft = axes::default_profile();
    shaft.axes.at(0).instrument_error_in = {{0.0, 0.0}, {10.0, 0.004}};
    const RunResult uncorrected = run_orders({table_to_4985()}, shaft);
    shaft.axes.at(0).cam_160_in = {{0.0, 0.0}, {10.0, 0.004}};
    const RunResult on_screw_22 = run_orders({table_to_4985()}, shaft);
    CHECK(uncorrected.axes.at(0).error_in == Approx(0.004 * 4.9845 / 10 - 0.00025).margin(1e-12));
    CHECK(on_screw_22.axes.at(0).real_in == Approx(uncorrected.axes.at(0).real_in).margin(1e-12));
}

TEST_CASE("Interpretation cam_160_on_instrument_shaft: cam 160 corrects instrument shaft 74's "
          "own error, which the counters cannot see, and a cam cut to lead screw 22 puts the "
          "part off its number",
          "[cabinet][chain][cam-160]") {
    auto profile = axes::default_profile();
    CHECK_FALSE(profile.cam_160_on_instrument_shaft);
    profile.cam_160_on_instrument_shaft = true;
    profile.axes.at(0).instrument_error_in = {{0.0, 0.0}, {10.0, 0.004}};
    const RunResult uncorrected = run_orders({table_to_4985()}, profile);
    // The stop impulse as the counters pass 4.9845, the part 0.004 x 4.9845 / 10 beyond; the
    // coast 0.00025 on: the error against the counters' 4.985.
    CHECK(uncorrected.axes.at(0).error_in == Approx(0.004 * 4.9845 / 10 - 0.00025).margin(1e-12));
    profile.axes.at(0).cam_160_in = {{0.0, 0.0}, {10.0, 0.004}};
    const RunResult corrected = run_orders({table_to_4985()}, profile);
    CHECK(corrected.axes.at(0).error_in == Approx(-0.00025).margin(1e-12));
    CHECK(corrected.axes.at(0).real_in == Approx(4.98475).margin(1e-12));

    // The cam cut to lead screw 22's error, read as a correction of shaft 74: the part ends
    // 0.005 in short (the stop at 0.999 x 4.9845, the coast 1.001 x 0.00025 on) and the
    // screw twice that.
    auto cam = axes::default_profile();
    cam.cam_160_on_instrument_shaft = true;
    cam.axes.at(0).lead_error_in = kLongLead;
    cam.axes.at(0).cam_160_in = kLongLead;
    const RunResult r = run_orders({table_to_4985()}, cam);
    REQUIRE(r.completed);
    CHECK(r.axes.at(0).real_in == Approx(0.999 * 4.9845 + 1.001 * 0.00025).margin(1e-12));
    CHECK(r.axes.at(0).screw_in - r.axes.at(0).counter_in ==
          Approx(0.999 * 4.9845 / 1.001 + 0.00025 - 4.985).margin(1e-12));
    // The screw turns less than the part moves: 0.133 s sooner than the perfect machine.
    const RunResult perfect = run_orders({table_to_4985()}, axes::default_profile());
    CHECK(r.machine_seconds - perfect.machine_seconds ==
          Approx(67.236588 - 67.369444).margin(1e-6));

    // Counting screw turns, the screw the counters read is the main screw either way.
    cam.measuring_chain = MeasuringChain::screw_turns;
    const RunResult turns = run_orders({table_to_4985()}, cam);
    cam.cam_160_on_instrument_shaft = false;
    const RunResult turns_patent = run_orders({table_to_4985()}, cam);
    CHECK(turns.axes.at(0).real_in == turns_patent.axes.at(0).real_in);
    CHECK(turns.axes.at(0).real_in == Approx(4.98475).margin(1e-12));
}

TEST_CASE("Measuring chain: a slip of the drive makes the axis run on to its real stop with the "
          "patent's chain, counting screw turns the part ends short",
          "[cabinet][chain][faults]") {
    CardOrders c = idle_card(1, {0, 0, 0, 0, 0});
    c.axis(Axis::table) = order(0, 1000, 3);
    const std::vector<Fault> slip = {parse_fault("slip:table:200:40")};
    const RunResult patent =
        run_orders({c}, chain_profile(MeasuringChain::instrument_shaft_74), nullptr, slip);
    REQUIRE(patent.completed);
    CHECK(patent.axes.at(0).real_in == Approx(0.99975).margin(1e-12));
    CHECK(patent.axes.at(0).screw_in == Approx(1.03975).margin(1e-12));
    CHECK(patent.axes.at(0).slip_in == Approx(-0.040).margin(1e-12));
    const RunResult turns =
        run_orders({c}, chain_profile(MeasuringChain::screw_turns), nullptr, slip);
    REQUIRE(turns.completed);
    CHECK(turns.axes.at(0).real_in == Approx(0.95975).margin(1e-12));
    CHECK(turns.axes.at(0).error_in == Approx(-0.04025).margin(1e-12));
    // The patent's machine ran 0.040 in of screw travel longer, at speed 3.
    CHECK(patent.machine_seconds - turns.machine_seconds == Approx(4.0).margin(1e-9));
}

TEST_CASE("Profile: the measuring chain's keys round-trip and bad values are refused by name",
          "[profile][chain]") {
    auto p = axes::profile_from_json(
        R"({"measuring_chain": "screw_turns", "axes": {"tilt": {"backlash_in": 0.002,
            "lead_error_in": [[0, 0], [10, 0.01]], "instrument_error_in": [[0, 0.001]],
            "cam_160_in": [[0, 0.0005]]}}})",
        axes::default_profile());
    CHECK(p.measuring_chain == MeasuringChain::screw_turns);
    CHECK(p.axes.at(4).backlash_in == 0.002);
    const auto again = axes::profile_from_json(axes::profile_to_json(p), axes::default_profile());
    CHECK(again.measuring_chain == MeasuringChain::screw_turns);
    CHECK(again.axes.at(4).lead_error_in == p.axes.at(4).lead_error_in);
    CHECK(again.axes.at(4).cam_160_in == p.axes.at(4).cam_160_in);
    CHECK(again.axes.at(4).instrument_error_in == p.axes.at(4).instrument_error_in);
    CHECK_FALSE(again.cam_160_on_instrument_shaft);
    for (const char* name : axes::kBuiltinProfiles) {
        INFO(name);
        CHECK_FALSE(axes::builtin_profile(name)->cam_160_on_instrument_shaft);
    }
    const auto reading = axes::profile_from_json(R"({"cam_160_on_instrument_shaft": true})",
                                                 axes::default_profile());
    CHECK(reading.cam_160_on_instrument_shaft);
    CHECK(axes::profile_from_json(axes::profile_to_json(reading), axes::default_profile())
              .cam_160_on_instrument_shaft);
    CHECK(axes::profile_from_json("{}", axes::default_profile()).measuring_chain ==
          MeasuringChain::instrument_shaft_74);
    for (const char* bad :
         {R"({"measuring_chain": "screw"})", R"({"axes": {"table": {"backlash_in": -0.001}}})",
          R"({"axes": {"table": {"backlash_in": 0.2}}})",
          R"({"axes": {"table": {"cam_160_in": [[0, 0], [1, 1.5]]}}})",
          R"({"axes": {"table": {"instrument_error_in": [[0, 0], [1, -0.6]],
                                 "cam_160_in": [[0, 0], [1, 0.6]]}}})",
          R"({"axes": {"table": {"screw_error_in": [[0, 0], [1, 0.6]],
                                 "cam_160_in": [[0, 0], [1, 1.5]]}}})",
          R"({"cam_160_on_instrument_shaft": 1})"}) {
        INFO(bad);
        CHECK_THROWS_AS(axes::profile_from_json(bad, axes::default_profile()), axes::ProfileError);
    }
    CHECK(axes::profile_from_json(R"({"axes": {"table": {"backlash_in": 0.1}}})",
                                  axes::default_profile())
              .axes.at(0)
              .backlash_in == 0.1);
}

TEST_CASE("Measuring chain: error tables bring the impulses closer than 0.001 in of screw travel, "
          "and the axis says by how much",
          "[axes][chain]") {
    auto p = axes::default_profile().axes.at(0);
    CHECK(axes::ScrewErrorTable({{0.0, 1.0}, {5.0, 0.0}, {10.0, 1.0}}).slope_range() ==
          std::pair<double, double>(0.8, 1.2));
    p.screw_error_in = {{0.0, 0.5}, {5.0, -0.5}}; // the part runs 0.8 in a reading inch
    p.lead_error_in = {{0.0, 0.0}, {4.0, 1.0}};   // and 1.25 in a screw inch
    axes::LeadScrewAxis axis(p);
    CHECK(axis.least_screw_per_impulse() == Approx(0.001 * 0.8 / 1.25).epsilon(1e-12));
    axis.command(+1, 3);
    std::optional<double> last; // the screw at the last crossing (the first is half a step)
    double least = 1;
    for (int i = 0; i < 6000 && axis.next_event_time() < axes::kNever; ++i) {
        if (axis.advance_to(axis.next_event_time())) {
            if (last) {
                least = std::min(least, axis.screw_in() - *last);
            }
            last = axis.screw_in();
        }
    }
    // The bound holds, and it is reached where both tables are at their steepest.
    CHECK(least >= axis.least_screw_per_impulse() * (1 - 1e-9));
    CHECK(least == Approx(axis.least_screw_per_impulse()).epsilon(1e-6));
    axis.measure_by(MeasuringChain::screw_turns, false);
    CHECK(axis.least_screw_per_impulse() == axes::kInchesPerImpulse);
}

TEST_CASE("Measuring chain: the summary names the real cause of a silent position error from the "
          "chain's own figures (backlash, lead error, instrument error, slip, coast counted the "
          "other way)",
          "[cabinet][chain][summary]") {
    auto summary = [](const RunResult& r) { return cli::summary_text(r, "d.cbn", "p"); };
    SECTION("counting screw turns: backlash taken up at the reversal, its figure") {
        auto profile = chain_profile(MeasuringChain::screw_turns);
        profile.axes.at(0).backlash_in = 0.003;
        const RunResult r = run_orders(out_and_back(), profile);
        REQUIRE(r.completed);
        CHECK(r.axes.at(0).chain.backlash_in == Approx(0.003).margin(1e-12));
        CHECK(r.axes.at(0).wrong_way == 0);
        const std::string s = summary(r);
        CHECK_THAT(s, Catch::Contains("table ends +0.0033 in from where its counters say (backlash "
                                      "in nut 78 +0.0030 in, taken up when the motion reversed"));
        CHECK_THAT(s, !Catch::Contains("coast counted"));
    }
    SECTION("counting screw turns: lead error and a slip, both named, the larger first") {
        auto profile = chain_profile(MeasuringChain::screw_turns);
        profile.axes.at(0).lead_error_in = {{0, 0}, {1, 0.004}};
        const RunResult r =
            run_orders(out_and_back(), profile, nullptr, {parse_fault("slip:table:100:6")});
        REQUIRE(r.completed);
        const std::string s = summary(r);
        INFO(s);
        const auto slip = s.find("the lead screw's drive slipped -0.0060 in (fault slip)");
        const auto lead = s.find("lead error of lead screw 22 +0.0020 in at 0.494 in");
        REQUIRE(slip != std::string::npos);
        REQUIRE(lead != std::string::npos);
        CHECK(slip < lead);
    }
    SECTION("through instrument shaft 74: its own error, and nothing of what it measures") {
        auto profile = chain_profile(MeasuringChain::instrument_shaft_74);
        profile.axes.at(0).instrument_error_in = {{0, 0}, {1, 0.004}};
        profile.axes.at(0).backlash_in = 0.003; // measured: not a cause
        const RunResult r = run_orders(out_and_back(), profile);
        REQUIRE(r.completed);
        const std::string s = summary(r);
        INFO(s);
        CHECK_THAT(s, Catch::Contains("(instrument shaft 74's own screw error +0.0020 in at 0.500 "
                                      "in (instrument_error_in)"));
        CHECK_THAT(s, !Catch::Contains("backlash in nut 78 +"));
        CHECK(r.axes.at(0).chain.backlash_in == 0);
    }
    SECTION("coast that runs on after the next card set the other sense, counted the wrong way") {
        // Card 1: the table at speed 1 with no slow-downs, last in the sequence, so it coasts
        // on; card 2 sets reverse while it still coasts.
        CardOrders one = idle_card(1, {0, 0, 0, 0, 0});
        one.axis(Axis::table) = order(0, 1000, 1, {}, {}, 16);
        one.axis(Axis::tilt).sequence = 1;
        CardOrders two = idle_card(2, {1000, 0, 0, 0, 0});
        two.axis(Axis::table) = order(1000, 900, 3, {}, {}, 1);
        auto profile = axes::default_profile();
        profile.incremental_equality_stops_at_any_speed = true;
        const RunResult r = run_orders({one, two}, profile);
        REQUIRE(r.axes.at(0).wrong_way > 0);
        const std::string s = summary(r);
        INFO(s);
        CHECK_THAT(s, Catch::Contains(fmt::format("({} impulses of coast counted in the other "
                                                  "direction",
                                                  r.axes.at(0).wrong_way)));
        CHECK_THAT(s, !Catch::Contains("not accounted for"));
    }
    SECTION("a perfect machine: no warning") {
        const RunResult r = run_orders(out_and_back(), axes::default_profile());
        CHECK_THAT(summary(r), !Catch::Contains("warning"));
    }
}
