// The tapered wing of Fig. 5 on the emulator: each station a straight cut along the span with
// the fixture turned by its screws; the root and tip sections come out as designed.
#include "tests/machine_support.hpp"

#include "cli/cutter_paths.hpp"

#include "decks/wing_job.hpp"

#include <catch2/catch.hpp>

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
          "[wing][decks][fig5]") {
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
