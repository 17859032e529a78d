// The tapered wing of Fig. 5 on the emulator: each station a straight cut along the span with
// the fixture turned by its screws; the root and tip sections come out as designed.
#include "tests/machine_support.hpp"
#include "tests/test_support.hpp"

#include "outputs/proofs/cutter_paths.hpp"

#include "decks/wing_job.hpp"

#include <catch2/catch.hpp>

#include <limits>
#include <tuple>

using namespace parsons;
using namespace parsons::decks;

namespace {

// Quantising the screws to 0.001 in (the line and, through the sine-plate arms, its angles)
// and the coast of a quarter-thousandth.
constexpr double kTolerance = 0.0015;

// The sanitize preset (PARSONS_SANITIZE) runs the test suite tens of times slower: there the
// first test runs one wing, from the coordinate file, instead of all three.
#ifdef PARSONS_SANITIZE
constexpr bool kOneWing = true;
#else
constexpr bool kOneWing = false;
#endif

} // namespace

TEST_CASE("Wing: a tapered, swept NACA wing runs to completion and its root and tip sections "
          "are cut within tolerance (Fig. 5)",
          "[wing][decks][fig5][heavy]") {
    auto [source, radius, taper, sweep] = GENERATE(
        filter([](const auto& wing) { return !kOneWing || std::get<0>(wing) == "clarky.dat"; },
               table<std::string, double, double, double>({
                   {"2412", 0.25, 0.8, 5.0},
                   {"0012", 0.1875, 0.6, 10.0},
                   {"clarky.dat", 0.125, 0.7, 8.0},
               })));
    WingOptions o;
    o.root_chord_in = 4.0;
    o.span_in = 5.0;
    o.taper = taper;
    o.sweep_deg = sweep;
    o.cutter_radius_in = radius;
    o.scallop_in = 0.002;
    const auto airfoil =
        source.size() == 4
            ? naca4(source)
            : read_dat(std::string(PARSONS_SOURCE_DIR) + "/decks/airfoils/" + source);
    const auto profile = axes::default_profile();
    const WingDeck deck = make_wing_deck(*airfoil, o, profile);
    INFO(source << ": " << deck.stations.size() << " stations, planned leftover "
                << deck.planned_leftover_in << " gouge " << deck.planned_gouge_in);
    CHECK(deck.planned_leftover_in <= 0.002);
    cli::WingPath observer(deck.zero, profile);
    const auto run = parsons::test::run_orders(deck.cards, profile, &observer);
    REQUIRE(run.completed);
    for (const auto& axis : run.axes) {
        CHECK(axis.lost_steps == 0);
        CHECK(std::abs(axis.error_in) < 0.0005);
    }
    // The fixture really turned, and the angles read back from the screws are the last
    // station's.
    double most_tilt = 0;
    for (const auto& st : deck.stations) {
        most_tilt = std::max(most_tilt, std::abs(st.tilt_rad) * 180 / 3.14159265358979);
    }
    CHECK(most_tilt > 0.5);
    CHECK(*run.axes.at(4).fixture_angle_deg ==
          Approx(deck.stations.back().tilt_rad * 180 / 3.14159265358979).margin(0.01));
    CHECK(*run.axes.at(3).fixture_angle_deg ==
          Approx(deck.stations.back().swivel_rad * 180 / 3.14159265358979).margin(0.01));
    const WingProof proof = prove_wing(observer.path, *airfoil, o);
    INFO("root gouge " << proof.root.max_gouge_in << " leftover " << proof.root.max_leftover_in
                       << "; tip gouge " << proof.tip.max_gouge_in << " leftover "
                       << proof.tip.max_leftover_in);
    for (const SectionProof* s : {&proof.root, &proof.tip}) {
        CHECK(s->max_gouge_in <= deck.planned_gouge_in + kTolerance);
        CHECK(s->max_leftover_in <= deck.planned_leftover_in + kTolerance);
    }
}

TEST_CASE("Wing: the fixture angles follow the sine-plate geometry", "[wing][decks][fig5]") {
    WingOptions o;
    o.scallop_in = 0;
    o.stations = 5;
    const auto profile = axes::default_profile();
    const WingDeck deck = make_wing_deck(*naca4("2412"), o, profile);
    for (std::size_t i = 0; i < deck.stations.size(); ++i) {
        const WingStation& st = deck.stations[i];
        const auto& card = deck.cards.at(2 * i);
        const double tilt_screw = card.axis(cardreader::Axis::tilt).stop / 1000.0;
        const double swivel_screw = card.axis(cardreader::Axis::swivel).stop / 1000.0;
        CHECK(tilt_screw == Approx(5.0 + 10.0 * std::sin(st.tilt_rad)).margin(0.0005));
        CHECK(swivel_screw == Approx(5.0 + 20.0 * std::tan(st.swivel_rad)).margin(0.0005));
        // The cut is the table's traverse, last in the sequence of the second card.
        CHECK(deck.cards.at(2 * i + 1).axis(cardreader::Axis::table).sequence == 0b10000);
    }
}

TEST_CASE("Wing: two cards a station, so 4,999 stations make 9,998 cards and 5,000 are refused "
          "before a station is computed",
          "[wing][decks][limits][heavy]") {
    using Catch::Matchers::Contains;
    const auto airfoil = naca4("2412");
    const auto profile = axes::default_profile();
    WingOptions o;
    o.scallop_in = 0;
    o.stations = 5000;
    REQUIRE_THROWS_WITH(make_wing_deck(*airfoil, o, profile),
                        Contains("--stations 5000: the deck would need 10,000 cards (2 a "
                                 "station), more than the 9,999 a deck can number (card numbers "
                                 "are four digits, columns 77-80)"));
    o.stations = 100000;
    CHECK_THROWS_WITH(make_wing_deck(*airfoil, o, profile),
                      Contains("--stations 100000: the deck would need 200,000 cards"));
#ifndef PARSONS_SANITIZE // some seconds of move planning; tens of times that under the sanitizers
    o.stations = 4999;
    CHECK(make_wing_deck(*airfoil, o, profile).cards.size() == 9998);
#endif
}

TEST_CASE("Wing: a root or tip chord or a span under 0.1 in, a cutter radius under 0.001 in, or a "
          "size that is not a number is refused, and the least of each is cut",
          "[wing][decks][limits]") {
    using Catch::Matchers::Contains;
    const auto airfoil = naca4("2412");
    const auto profile = axes::default_profile();
    // A straight, untapered wing, so the fixture stays level whatever the span.
    WingOptions straight;
    straight.root_chord_in = 4;
    straight.taper = 1;
    straight.sweep_deg = 0;
    straight.stations = 10;
    auto make = [&](auto&& change) {
        WingOptions o = straight;
        change(o);
        return make_wing_deck(*airfoil, o, profile);
    };
    CHECK(make([](WingOptions& o) { o.span_in = 0.1; }).cards.size() == 20);
    CHECK_THROWS_WITH(make([](WingOptions& o) { o.span_in = 0.0999; }),
                      Contains("--span 0.0999: a span under 0.100 in is no shape to the machine, "
                               "which moves in impulses of 0.001 in: give at least 0.100 in"));
    CHECK_THROWS_WITH(make([](WingOptions& o) { o.span_in = 1e-300; }),
                      Contains("--span 1e-300: a span under 0.100 in"));
    CHECK(make([](WingOptions& o) { o.root_chord_in = 0.1; }).cards.size() == 20);
    CHECK_THROWS_WITH(make([](WingOptions& o) { o.root_chord_in = 1e-300; }),
                      Contains("--chord 1e-300: a chord under 0.100 in"));
    // The tip chord is the root chord times the taper: 0.2 x 0.5 is the least.
    CHECK(make([](WingOptions& o) {
              o.root_chord_in = 0.2;
              o.taper = 0.5;
          }).cards.size() == 20);
    CHECK_THROWS_WITH(make([](WingOptions& o) {
                          o.root_chord_in = 0.2;
                          o.taper = 0.499;
                      }),
                      Contains("--taper 0.499: the tip chord would be 0.0998 in (0.200 in x "
                               "0.499); a chord under 0.100 in is no shape to the machine") &&
                          Contains("give a taper of at least 0.5000"));
    CHECK_THROWS_WITH(make([](WingOptions& o) { o.taper = 1e-300; }),
                      Contains("--taper 1e-300: the tip chord would be 4e-300 in"));
    CHECK(make([](WingOptions& o) { o.cutter_radius_in = 0.001; }).cards.size() == 20);
    CHECK_THROWS_WITH(make([](WingOptions& o) { o.cutter_radius_in = 1e-300; }),
                      Contains("--cutter-radius 1e-300: a cutter radius under 0.001 in"));
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    CHECK_THROWS_WITH(make([&](WingOptions& o) { o.sweep_deg = nan; }),
                      Contains("--sweep nan: give a finite number"));
    CHECK_THROWS_WITH(make([&](WingOptions& o) { o.span_in = inf; }),
                      Contains("--span inf: give a finite number"));
    CHECK_THROWS_WITH(make([&](WingOptions& o) { o.taper = inf; }),
                      Contains("--taper inf: give a finite number"));
    CHECK_THROWS_WITH(make([&](WingOptions& o) { o.root_chord_in = nan; }),
                      Contains("--chord nan: give a finite number"));
    // Too big for the counters stays the counters' refusal.
    CHECK_THROWS_WITH(make([](WingOptions& o) { o.span_in = 20; }),
                      Contains("wing: the job spans") && Contains("use a smaller wing"));
}

TEST_CASE("Wing: the job must fit the counters with its margin at both ends, 9.999 in less twice "
          "the margin",
          "[wing][decks][mutation]") {
    const auto airfoil = naca4("2412");
    const auto profile = axes::default_profile();
    WingOptions o;
    o.stations = 12;
    o.margin_in = 4.9; // nothing fits: the refusal names the job's extent
    std::string said;
    try {
        make_wing_deck(*airfoil, o, profile);
    } catch (const JobError& e) {
        said = e.what();
    }
    const double extent = parsons::test::widest_span_in(said);
    REQUIRE(extent > 0);
    const double spare = 9.999 - extent;
    REQUIRE(spare > 1.0);
    o.margin_in = 0.6 * spare; // room for the margin once, not twice
    CHECK_THROWS_AS(make_wing_deck(*airfoil, o, profile), JobError);
    o.margin_in = 0.45 * spare;
    const WingDeck deck = make_wing_deck(*airfoil, o, profile);
    CHECK_FALSE(deck.cards.empty());
    for (double z : {deck.zero.x(), deck.zero.y(), deck.zero.z()}) {
        CHECK(z >= o.margin_in - 1e-9); // the job's lowest point sits the margin above 0
    }
}
