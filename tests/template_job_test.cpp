// Generated decks prove themselves on the emulator: they run to completion with no check stop
// and no silent position error, and the cut they leave stays within the planned scallop plus
// quantisation of the design.
#include "tests/machine_support.hpp"
#include "tests/test_support.hpp"

#include "outputs/proofs/cutter_paths.hpp"

#include "cardreader/deck_review.hpp"
#include "decks/cut_proof.hpp"
#include "decks/deck_limits.hpp"
#include "decks/move_planner.hpp"
#include "decks/number_text.hpp"
#include "decks/template_job.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <limits>

using namespace parsons;
using namespace parsons::decks;
using parsons::test::run_orders;

namespace {

std::string data_file(const std::string& name) {
    return std::string(PARSONS_SOURCE_DIR) + "/decks/airfoils/" + name;
}

// Quantising each centre to 0.001 in on both axes moves it up to 0.0007 in; the coast leaves
// each axis a quarter of a thousandth from its number.
constexpr double kQuantisation = 0.0007 + 0.00025;

struct Proved {
    TemplateDeck deck;
    relaylogic::RunResult run;
    CutProof cut;
};

Proved generate_and_run(const Airfoil& airfoil, const TemplateOptions& options) {
    Proved p;
    const auto profile = axes::default_profile();
    p.deck = make_template_deck(airfoil, options, profile);
    cli::CutterPath cutter;
    p.run = run_orders(p.deck.cards, profile, &cutter);
    const auto samples = design_samples(airfoil, options, p.deck.work_zero_in, 800);
    const DesignContour design{samples.points, samples.toward_cutter};
    p.cut = prove_cut(simplify_path(cutter.path, 1e-7), options.cutter_radius_in, design,
                      1.5 * options.cutter_radius_in);
    return p;
}

void check_proved(const Proved& p) {
    INFO("planned leftover " << p.deck.planned_leftover_in << " gouge " << p.deck.planned_gouge_in);
    INFO("cut gouge " << p.cut.max_gouge_in << " leftover " << p.cut.max_leftover_in);
    REQUIRE(p.run.completed);
    CHECK_FALSE(p.run.stop);
    for (const auto& axis : p.run.axes) {
        CHECK(axis.lost_steps == 0);
        CHECK(std::abs(axis.error_in) < 0.0005);
    }
    CHECK(p.cut.machined_points > 100);
    CHECK(p.cut.max_gouge_in <= p.deck.planned_gouge_in + kQuantisation);
    CHECK(p.cut.max_leftover_in <= p.deck.planned_leftover_in + kQuantisation);
}

} // namespace

TEST_CASE("Template: NACA 2412 and 0012 decks run to completion and cut within tolerance",
          "[template][decks]") {
    auto [digits, radius, surface] = GENERATE(table<std::string, double, Surface>({
        {"2412", 0.25, Surface::upper},
        {"2412", 0.125, Surface::lower},
        {"0012", 0.375, Surface::both},
        {"2412", 0.5, Surface::both},
        // Strong camber tilts the nose's normal along the camber line: the approach must come
        // in along it, not drop past the nose.
        {"4412", 0.25, Surface::upper},
        {"6409", 0.5, Surface::upper},
    }));
    TemplateOptions o;
    o.chord_in = 6.0;
    o.cutter_radius_in = radius;
    o.surface = surface;
    o.scallop_in = 0.002;
    INFO("NACA " << digits << " radius " << radius);
    const auto airfoil = naca4(digits);
    check_proved(generate_and_run(*airfoil, o));
}

TEST_CASE("Template: Clark Y and E387 from coordinate files, by count and by scallop",
          "[template][decks]") {
    auto [file, radius, stations] = GENERATE(table<std::string, double, int>({
        {"clarky.dat", 0.25, 0},
        {"e387.dat", 0.1875, 80},
        {"e387.dat", 0.25, 40}, // coarse: big scallops, and the sharp trailing edge's seam
    }));
    TemplateOptions o;
    o.chord_in = 5.0;
    o.cutter_radius_in = radius;
    o.surface = Surface::both;
    o.stations = stations > 0 ? stations : 60;
    o.spacing = stations == 40 ? Spacing::uniform : Spacing::cosine;
    o.scallop_in = stations > 0 ? 0.0 : 0.002;
    INFO(file);
    const auto airfoil = read_dat(data_file(file));
    check_proved(generate_and_run(*airfoil, o));
}

TEST_CASE("Template: the patent's female template (Fig. 4) cuts from the other side",
          "[template][decks][fig4]") {
    TemplateOptions o;
    o.chord_in = 6.0;
    o.cutter_radius_in = 0.0625; // inside the leading-edge radius, 0.0953 in on a 6 in chord
    o.female = true;
    o.scallop_in = 0.002;
    const auto airfoil = naca4("2412");
    const Proved p = generate_and_run(*airfoil, o);
    check_proved(p);
    // Centre = work + (R sin theta, -R cos theta): below the upper surface, by R.
    const Station& mid = p.deck.stations.at(p.deck.stations.size() / 2);
    CHECK(mid.centre.y() < mid.work.y());
    const SurfaceSample s = airfoil->sample(Side::upper, mid.u);
    const double theta = std::atan2(s.tangent.y(), s.tangent.x());
    CHECK(mid.centre.x() == Approx(mid.work.x() + 0.0625 * std::sin(theta)));
    CHECK(mid.centre.y() == Approx(mid.work.y() - 0.0625 * std::cos(theta)));
}

TEST_CASE("Template: a cutter larger than a hollow of the surface is refused, not gouged",
          "[template][decks][fig4]") {
    TemplateOptions o;
    o.chord_in = 6.0;
    o.cutter_radius_in = 0.25; // the female leading edge is a hollow of radius 0.095 in
    o.female = true;
    try {
        make_template_deck(*naca4("2412"), o, axes::default_profile());
        FAIL("a 0.25 in cutter was accepted for a 0.095 in hollow");
    } catch (const JobError& e) {
        CHECK(std::string(e.what()).find("the cutter (radius 0.2500 in) cannot reach into the "
                                         "surface where it curves round toward the cutter with "
                                         "a radius of 0.09") != std::string::npos);
    }
}

TEST_CASE("Template: no generated card has the shared-bank hazard", "[template][decks]") {
    TemplateOptions o;
    o.scallop_in = 0.002;
    o.surface = Surface::both;
    const auto deck = make_template_deck(*naca4("2412"), o, axes::default_profile());
    std::array<int, 5> at{};
    for (const auto& card : deck.cards) {
        for (cardreader::Axis a : cardreader::kAxes) {
            const auto& order = card.axis(a);
            INFO("card " << card.number);
            CHECK(cardreader::spurious_matches_on_path(
                      order, static_cast<cardreader::Thousandths>(at.at(cardreader::axis_index(a))))
                      .empty());
            at.at(cardreader::axis_index(a)) = order.stop;
        }
    }
}

TEST_CASE("Template: the same deck with its slow-downs stripped stops with check_mismatch: the "
          "physics is doing the work",
          "[template][decks][coast]") {
    TemplateOptions o;
    o.scallop_in = 0.002;
    auto deck = make_template_deck(*naca4("2412"), o, axes::default_profile());
    int stripped = 0;
    for (auto& card : deck.cards) {
        for (auto& axis : card.axes) {
            stripped += axis.slow_down[0] ? 1 : 0;
            axis.slow_down = {};
        }
    }
    REQUIRE(stripped > 0);
    // As the patent words it, the stop number then only slows the axis (one impulse, one step)
    // and it runs on past its stop: the machine stops, somewhere it should not have gone.
    const auto run = run_orders(deck.cards);
    REQUIRE(run.stop);
    // The tutorial's words (docs/tutorial.md, step 4): card 2's table goes round its counters
    // twice and reaches its limit switch.
    CHECK(run.stop->reason == relaylogic::StopReason::limit_switch);
    CHECK(run.stop->card == 2);
    CHECK(run.stop->axis == cardreader::Axis::table);
    // The earlier reading (an incremental equality stops at any speed) stops it at speed 1:
    // it coasts past the stop and a later card's check fails.
    auto earlier = axes::default_profile();
    earlier.incremental_equality_stops_at_any_speed = true;
    const auto old = run_orders(deck.cards, earlier);
    REQUIRE(old.stop);
    CHECK(old.stop->reason == relaylogic::StopReason::check_mismatch);
}

TEST_CASE("Template: where the path turns sharply the card is made at the lowest speed "
          "(corner slow-down, EP 0636958)",
          "[template][decks]") {
    TemplateOptions o;
    o.surface = Surface::both;
    o.stations = 8; // coarse: the path turns sharply round the leading edge
    const auto airfoil = naca4("2412");
    const auto with = make_template_deck(*airfoil, o, axes::default_profile());
    o.corner_slowdown = false;
    const auto without = make_template_deck(*airfoil, o, axes::default_profile());
    REQUIRE(with.corner_cards > 0);
    CHECK(without.corner_cards == 0);
    REQUIRE(with.cards.size() == without.cards.size());
    int slowed = 0;
    for (std::size_t i = 0; i < with.cards.size(); ++i) {
        for (cardreader::Axis a : {cardreader::Axis::table, cardreader::Axis::cross}) {
            const int w = with.cards[i].axis(a).start_speed;
            const int wo = without.cards[i].axis(a).start_speed;
            CHECK(w >= wo); // never faster with the corner rule
            slowed += w > wo ? 1 : 0;
        }
    }
    CHECK(slowed > 0);
    // Both decks still run to completion: the rule is a margin, the physics still holds.
    CHECK(run_orders(with.cards).completed);
}

TEST_CASE("Move planner: speeds and slow-downs follow the profile's physics", "[decks]") {
    const auto profile = axes::default_profile();
    const auto& table = profile.axes.at(0);
    // A long table move starts on speed 1 with two slow-downs, both before the stop with room.
    auto o = plan_move({0, 4985, 2, false, 1}, table, profile);
    CHECK(o.start_speed == 1);
    REQUIRE(o.slow_down[0]);
    REQUIRE(o.slow_down[1]);
    CHECK(4985 - *o.slow_down[1] >= slow_down_room(table, 2, 3));
    CHECK(*o.slow_down[1] - *o.slow_down[0] >= slow_down_room(table, 1, 2));
    // A corner is approached at the lowest speed; a short move too.
    CHECK(plan_move({0, 4985, 2, true, 1}, table, profile).start_speed == 3);
    // Stop 5.000 from 0: every slow-down on the way (4.9xx) would also match 4.000 in the
    // shared banks, so the move starts on speed 3 rather than punch a hazard.
    CHECK(plan_move({0, 5000, 2, false, 1}, table, profile).start_speed == 3);
    CHECK(plan_move({0, 4, 2, false, 1}, table, profile).start_speed == 3);
    // An axis with one slow-down field starts at most on speed 2.
    CHECK(plan_move({0, 4985, 1, false, 1}, profile.axes.at(1), profile).start_speed == 2);
    // A speed the stepping switches cannot follow is never used.
    auto slow_switches = profile;
    slow_switches.max_stepping_rate_per_s = 50; // speed 1 is 90 impulses/s
    CHECK(plan_move({0, 4985, 2, false, 1}, table, slow_switches).start_speed == 2);
    // A profile whose speed 3 coasts past half a thousandth cannot make an exact deck.
    auto coasting = profile;
    coasting.axes.at(0).speed_in_per_min = {5.4, 1.8, 1.2};
    CHECK_THROWS_AS(plan_move({0, 4985, 2, false, 1}, coasting.axes.at(0), coasting), PlanError);
}

TEST_CASE("Template: both surfaces run round the fitted leading edge of a coordinate file, not "
          "past it",
          "[template][decks]") {
    const auto airfoil = read_dat(data_file("clarky.dat"));
    const double le_x = airfoil->sample(Side::upper, -1.0).point.x();
    REQUIRE(le_x < 0); // Clark Y's fitted nose lies just ahead of x = 0
    TemplateOptions o;
    o.chord_in = 5.0;
    o.surface = Surface::both;
    const auto samples = design_samples(*airfoil, o, Eigen::Vector2d::Zero(), 200);
    double least_x = 1e9;
    for (const auto& p : samples.points) {
        least_x = std::min(least_x, p.x());
    }
    CHECK(least_x == Approx(le_x * o.chord_in).margin(1e-12));
}

TEST_CASE("Messages: the machine's figures in fixed decimals, huge ones in engineering form",
          "[gen][messages]") {
    using parsons::decks::fixed;
    CHECK(fixed(2.5) == "2.500");
    CHECK(fixed(-0.0004, 4) == "-0.0004");
    CHECK(fixed(999999.0) == "999999.000");
    CHECK(fixed(1e6) == "1.000e6");
    CHECK(fixed(-7.92e305) == "-792.000e303");
    CHECK(fixed(1.0e300) == "1.000e300");
    CHECK(fixed(999.9996e6) == "1.000e9"); // not "1000.000e6"
    CHECK(fixed(12345678.0, 1) == "12.3e6");
}

TEST_CASE("Template: a deck holds at most 9,999 cards: the most --stations makes exactly 9,999, "
          "one station more is refused before any is computed",
          "[template][decks][limits]") {
    using Catch::Matchers::Contains;
    const auto airfoil = naca4("2412");
    const auto profile = axes::default_profile();
    TemplateOptions o; // the upper surface: 3 cards to approach, then one a station after the first
    o.stations = 9997;
    const TemplateDeck deck = make_template_deck(*airfoil, o, profile);
    CHECK(deck.cards.size() == 9999);
    CHECK(deck.cards.back().number == 9999);
    o.stations = 9998;
    REQUIRE_THROWS_WITH(make_template_deck(*airfoil, o, profile),
                        Contains("--stations 9998: the deck would need at least 10,000 cards (3 "
                                 "to approach the first of 9,998 stations") &&
                            Contains("more than the 9,999 a deck can number (card numbers are "
                                     "four digits, columns 77-80)"));
    // Refused from the options alone: ten million stations are never computed.
    o.stations = 10000000;
    CHECK_THROWS_WITH(make_template_deck(*airfoil, o, profile),
                      Contains("--stations 10000000: the deck would need at least 10,000,002 "
                               "cards"));
    o.stations = std::numeric_limits<int>::max();
    CHECK_THROWS_WITH(make_template_deck(*airfoil, o, profile),
                      Contains("the deck would need at least 2,147,483,649 cards"));
}

TEST_CASE("Template: both surfaces approach over the top, four cards: 4,998 stations a surface "
          "make 9,998 cards, 4,999 would make 10,000 and are refused before a card is made",
          "[template][decks][limits]") {
    using Catch::Matchers::Contains;
    const auto airfoil = naca4("2412");
    const auto profile = axes::default_profile();
    TemplateOptions o;
    o.surface = Surface::both;
    o.stations = 4998; // 9,995 stations round both surfaces (the leading edge once)
    const TemplateDeck deck = make_template_deck(*airfoil, o, profile);
    CHECK(deck.stations.size() == 9995);
    CHECK(deck.cards.size() == 9998);
    o.stations = 4999;
    CHECK_THROWS_WITH(make_template_deck(*airfoil, o, profile),
                      Contains("--stations 4999: the deck would need 10,000 cards (4 to approach, "
                               "9,996 from station to station), more than the 9,999 a deck can "
                               "number"));
}

TEST_CASE("Template: a scallop that would need more cards than a deck holds is refused while the "
          "stations are being chosen",
          "[template][decks][limits][heavy]") {
    TemplateOptions o;
    o.surface = Surface::both;
    o.scallop_in = 1e-7; // every step the finest, 0.0001 of the path: 20,001 stations
    CHECK_THROWS_WITH(make_template_deck(*naca4("2412"), o, axes::default_profile()),
                      Catch::Matchers::Contains("--scallop 1e-07: the deck would need at least "
                                                "10,000 cards (9,997 stations so far to hold "
                                                "it, and 50 % of the path still to go)"));
}

TEST_CASE("Template: a chord under 0.1 in or a cutter radius under 0.001 in is no shape to the "
          "machine and is refused, as is a size that is not a number, and the least of each is cut",
          "[template][decks][limits]") {
    using Catch::Matchers::Contains;
    const auto airfoil = naca4("2412");
    const auto profile = axes::default_profile();
    auto make = [&](double chord_in, double radius_in) {
        TemplateOptions o;
        o.chord_in = chord_in;
        o.cutter_radius_in = radius_in;
        o.stations = 20;
        return make_template_deck(*airfoil, o, profile);
    };
    CHECK(make(decks::kLeastShapeIn, 0.25).cards.size() == 22);
    CHECK(make(0.1, 0.25).cards.size() == 22); // as typed
    CHECK_THROWS_WITH(make(0.0999, 0.25),
                      Contains("--chord 0.0999: a chord under 0.100 in is no shape to the "
                               "machine, which moves in impulses of 0.001 in: give at least "
                               "0.100 in"));
    CHECK_THROWS_WITH(make(1e-300, 0.25), Contains("--chord 1e-300: a chord under 0.100 in"));
    CHECK_THROWS_WITH(make(-6, 0.25), Contains("--chord -6: a chord under 0.100 in"));
    CHECK(make(6, 0.001).cards.size() == 22);
    CHECK_THROWS_WITH(make(6, 0.0009),
                      Contains("--cutter-radius 0.0009: a cutter radius under 0.001 in is less "
                               "than one impulse"));
    CHECK_THROWS_WITH(make(6, 1e-300), Contains("--cutter-radius 1e-300: a cutter radius under"));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    CHECK_THROWS_WITH(make(nan, 0.25), Contains("--chord nan: give a finite number"));
    CHECK_THROWS_WITH(make(inf, 0.25), Contains("--chord inf: give a finite number"));
    CHECK_THROWS_WITH(make(6, inf), Contains("--cutter-radius inf: give a finite number"));
    CHECK_THROWS_WITH(make(6, nan), Contains("--cutter-radius nan: give a finite number"));
    // Too big for the counters stays the counters' refusal.
    CHECK_THROWS_WITH(make(1e300, 0.25), Contains("the cutter path spans 1.000e300 x"));
}

TEST_CASE("Deck limits: counts are written as a person reads them", "[decks][limits]") {
    CHECK(decks::count_text(0) == "0");
    CHECK(decks::count_text(999) == "999");
    CHECK(decks::count_text(9999) == "9,999");
    CHECK(decks::count_text(10000003) == "10,000,003");
    CHECK(decks::count_text(-1234) == "-1,234");
    CHECK(decks::kMaxDeckCards == 9999);
}

TEST_CASE("Template: the job must fit the counters with its margin at both ends, 9.999 in less "
          "twice the margin",
          "[template][decks][mutation]") {
    const auto airfoil = naca4("2412");
    const auto profile = axes::default_profile();
    TemplateOptions o;
    o.chord_in = 6.0;
    // The refusal names the path's extent: ask with a margin nothing fits in.
    o.margin_in = 4.9;
    std::string said;
    try {
        make_template_deck(*airfoil, o, profile);
    } catch (const JobError& e) {
        said = e.what();
    }
    const double extent = parsons::test::widest_span_in(said);
    REQUIRE(extent > 0);
    const double spare = 9.999 - extent; // what the two margins share
    REQUIRE(spare > 1.0);
    // A margin 0.6 of the spare: room for it once, not twice.
    o.margin_in = 0.6 * spare;
    CHECK_THROWS_AS(make_template_deck(*airfoil, o, profile), JobError);
    // 0.45 of it fits twice over, and every station's centre lies the margin inside 0 .. 9.999.
    o.margin_in = 0.45 * spare;
    const TemplateDeck deck = make_template_deck(*airfoil, o, profile);
    for (const Station& s : deck.stations) {
        const Eigen::Vector2d at = s.centre + deck.work_zero_in;
        for (double v : {at.x(), at.y()}) {
            CHECK(v >= o.margin_in - 1e-9);
            CHECK(v <= 9.999 - o.margin_in + 1e-9);
        }
    }
}

TEST_CASE(
    "Template: the cut of the tutorial's deck (NACA 2412, chord 6, cutter 0.25, scallop "
    "0.002): every design point machined, its scallops as planned and its gouge within the "
    "planned dip, each within quantising, and run --cut reports the proof of the emulated path",
    "[template][cut][mutation]") {
    using parsons::test::q;
    using parsons::test::run_parsons;
    const parsons::test::TempDir dir;
    const std::string deck = dir.str("n.cbn");
    const auto gen = run_parsons("gen airfoil --naca 2412 --chord 6 --cutter-radius 0.25 "
                                 "--scallop 0.002 --json -o " +
                                 q(deck) + " 2>/dev/null");
    REQUIRE(gen.exit_code == 0);
    const auto planned = nlohmann::json::parse(gen.output);
    const double planned_scallop = planned.at("largest_scallop_in").get<double>();
    const double planned_dip = planned.at("largest_dip_in").get<double>();
    CHECK(planned_scallop == Approx(0.002).margin(1e-9)); // what --scallop asked
    const auto run = run_parsons("run " + q(deck) + " -q --cut " + q(dir.str("cut.svg")) +
                                 " --report " + q(dir.str("r.json")));
    REQUIRE(run.exit_code == 0);
    const auto cut = nlohmann::json::parse(parsons::test::read_bytes(dir.path("r.json"))).at("cut");
    const double gouge = cut.at("max_gouge_in").get<double>();
    const double leftover = cut.at("max_leftover_in").get<double>();
    const double scallop = cut.at("max_scallop_in").get<double>();
    // 1,500 design intervals on the one surface cut, and the cutter reached every point.
    CHECK(cut.at("design_points") == 1501);
    CHECK(cut.at("machined_points") == 1501);
    // The scallops stand as high as planned, give or take quantising to 0.001 in and the coast.
    CHECK(leftover <= planned_scallop + kQuantisation);
    CHECK(leftover >= planned_scallop - kQuantisation);
    CHECK(scallop <= leftover);
    CHECK(scallop >= planned_scallop - kQuantisation);
    CHECK(gouge > 0);
    CHECK(gouge <= planned_dip + kQuantisation);

    // The same proof, from the same deck run here: the report's figures are this path's.
    TemplateOptions o;
    o.chord_in = 6.0;
    o.cutter_radius_in = 0.25;
    o.scallop_in = 0.002;
    const auto airfoil = naca4("2412");
    const auto profile = axes::default_profile();
    const TemplateDeck made = make_template_deck(*airfoil, o, profile);
    cli::CutterPath cutter;
    REQUIRE(run_orders(made.cards, profile, &cutter).completed);
    const auto samples = design_samples(*airfoil, o, made.work_zero_in);
    const CutProof proof =
        prove_cut(simplify_path(cutter.path, 1e-7), o.cutter_radius_in,
                  DesignContour{samples.points, samples.toward_cutter}, 1.5 * o.cutter_radius_in);
    CHECK(samples.points.size() == 1501);
    CHECK(gouge == Approx(proof.max_gouge_in).margin(5e-6));
    CHECK(leftover == Approx(proof.max_leftover_in).margin(5e-6));
    CHECK(scallop == Approx(proof.max_scallop_in).margin(5e-6));
}
