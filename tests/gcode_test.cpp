// G-code both ways (docs/gcode.md): reading a program (decks/gcode_program.hpp), the deck made
// of it (decks/gcode_job.hpp), the machine's path written as G-code
// (outputs/traces/gcode_path.hpp), and the commands. The independent cross-check of the round trip
// is tests/js/gcode_crosscheck.js.
#include "machine_support.hpp"
#include "test_support.hpp"

#include "cardreader/deck_error.hpp"
#include "decks/gcode_job.hpp"
#include "decks/gcode_program.hpp"
#include "decks/move_planner.hpp"
#include "decks/template_job.hpp"
#include "outputs/traces/gcode_path.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <regex>
#include <sstream>

using namespace parsons;
using Catch::Matchers::Contains;
using Eigen::Vector3d;

namespace {

std::string refusal(const std::string& text) {
    try {
        decks::read_gcode(text, "p.ngc");
    } catch (const cardreader::DeckError& e) {
        return e.what();
    }
    return "no refusal";
}

decks::GcodeProgram read(const std::string& text) {
    return decks::read_gcode(text, "p.ngc");
}

// The distance from x to the polyline through the design points of a program, sampled finely.
double off_program(const Vector3d& x, const decks::GcodeProgram& p, const Vector3d& zero) {
    double best = 1e9;
    Vector3d last = zero;
    for (const auto& m : p.moves) {
        for (int i = 1; i <= 400; ++i) {
            const Vector3d b = decks::point_on(m, i / 400.0) + zero;
            const Vector3d d = b - last;
            const double t = d.squaredNorm() == 0
                                 ? 0
                                 : std::clamp((x - last).dot(d) / d.squaredNorm(), 0.0, 1.0);
            best = std::min(best, (x - (last + t * d)).norm());
            last = b;
        }
    }
    return best;
}

Vector3d stop_of(const cardreader::CardOrders& c) {
    return {c.axes[0].stop / 1000.0, c.axes[1].stop / 1000.0, c.axes[2].stop / 1000.0};
}

} // namespace

TEST_CASE("G-code: refusals name the file, the line and the word", "[gcode]") {
    struct Case {
        const char* program;
        const char* message;
    };
    const std::vector<Case> cases = {
        {"G20\nG41 X1\n", "p.ngc:2: G41: cutter radius compensation"},
        {"G20\nG42 X1\n", "p.ngc:2: G42: cutter radius compensation"},
        {"G20\nT1 M6\nG1 X1\nT2 M6\n", "p.ngc:4: T2: a second tool (the program began with T1)"},
        {"G20\nT1.5\n", "p.ngc:2: T1.5: a tool number is one whole number"},
        {"G20\nT1 T1\n", "p.ngc:2: T1: a tool number is one whole number"},
        {"G1 X1\n", "p.ngc:1: X1: a move before the units are given"},
        {"G20\n\nX1\n", "p.ngc:3: X1: a move with no motion mode"},
        {"G20\nG1 X1 X2\n", "p.ngc:2: X2: X given twice on one line"},
        {"G20\nG0 G1 X1\n", "p.ngc:2: G1: G0 and G1 on one line"},
        {"G20\nG20 G21\n", "p.ngc:2: G21: G20 and G21 on one line"},
        {"G20\nG2 X1 Y0 I0.3 J0\n", "p.ngc:2: G2: the arc's end is not on its circle"},
        {"G20\nG2 X2 Y0 R0.5\n", "p.ngc:2: R0.5: the radius 0.5000 in is less than half"},
        {"G20\nG2 X0 Y0 R0.5\n", "p.ngc:2: R0.5: a full circle cannot be given by its radius"},
        {"G20\nG2 X1 Y1\n", "p.ngc:2: G2: an arc with neither I and J nor R"},
        {"G20\nG3 X1 Y1 I1 R1\n", "p.ngc:2: R1: an arc takes its centre from I and J or"},
        {"G20\nG2 X0 Y0 I0 J0\n", "p.ngc:2: G2: an arc of no radius"},
        {"G21 G91 G1 M6 Y1\nG3 X1 Y1 I22222267410415839\n",
         "p.ngc:2: G3: an arc of radius 8.74892e+14 in, over 1,000,000 in"},
        {"G20\nG2 X1 Y0 I1000000.5 J0\n", "p.ngc:2: G2: an arc of radius 1e+06 in, over"},
        {"G20\nG18\n", "p.ngc:2: G18: the XZ plane"},
        {"G20\nG19\n", "p.ngc:2: G19: the YZ plane"},
        {"G20\nG90.1\n", "p.ngc:2: G90.1: absolute arc centres"},
        {"G20\nG1 X1 (comment\n", "p.ngc:2: (: a comment that is not closed"},
        {"G20\n#1=2\n", "p.ngc:2: #: parameters, expressions"},
        {"G20\nO100 sub\n", "p.ngc:2: O: parameters, expressions and subroutines"},
        {"G20\nO<cut> call\n", "p.ngc:2: O: parameters, expressions and subroutines"},
        {"G20\nG1 X1 O100\n", "p.ngc:2: O: parameters, expressions and subroutines"},
        {"G20\nO<cut\n", "p.ngc:2: O: parameters, expressions and subroutines"},
        {"G20\nG1 A10\n", "p.ngc:2: A10: a rotary axis"},
        {"G20\nG1 X1 K1\n", "p.ngc:2: K1: K: arcs in the XY plane take I and J only"},
        {"G20\nG1 X\n", "p.ngc:2: X: a letter with no number"},
        {"G20\nG1 X1 F0\n", "p.ngc:2: F0: a feed must be positive"},
        {"G20\nG1 X1 S-5\n", "p.ngc:2: S-5: a spindle speed cannot be negative"},
        {"G20\nG4 P1\n", "p.ngc:2: G4: dwell"},
        {"G20\nG81 X1 Y1 Z-1 R0.1\n", "p.ngc:2: G81: a drilling cycle"},
        {"G20\nG85 X1\n", "p.ngc:2: G85: a canned cycle"},
        {"G20\nG84 X1\n", "p.ngc:2: G84: a tapping cycle"},
        {"G20\nG28\nG1 X1\n", "p.ngc:2: G28: a return home with a move after it (line 3)"},
        {"G20\nG28 G91 Z0\nG90\nX1\n", "p.ngc:2: G28: a return home with a move after it"},
        {"G20\nG28 I1\n", "p.ngc:2: G28: a return home takes no I, J or R"},
        {"G20\nG92 X0\n", "p.ngc:2: G92: setting the origin"},
        {"G20\nG1 X1 H1\n", "p.ngc:2: H1: not a word parsons reads"},
        {"G20\nG1 X1 P0.01\n", "p.ngc:2: P0.01: not a word parsons reads"},
        {"G20\nG43 P1\n", "p.ngc:2: P1: not a word parsons reads"},
        {"G20\nG64 H1\n", "p.ngc:2: H1: not a word parsons reads"},
        {"G20\nG43.1 Z1\n", "p.ngc:2: G43.1: not a G-code parsons reads"},
        {"G20\nG55\n", "p.ngc:2: G55: a second work offset"},
        {"G20\nG93\n", "p.ngc:2: G93: inverse-time feed"},
        {"G20\nG1.5 X1\n", "p.ngc:2: G1.5: not a G-code parsons reads"},
        {"G20\nG7\n", "p.ngc:2: G7: not a G-code parsons reads"},
        {"G20\nM98 P100\n", "p.ngc:2: M98: not an M-code parsons reads"},
        {"G20\nM0\n", "p.ngc:2: M0: a program stop"},
        {"G20\nM3 M4\n", "p.ngc:2: M4: two spindle words on one line"},
        {"G20\nG1 I1\n", "p.ngc:2: I1: arc words with no arc"},
        {"G20\n/G1 X1\n", "p.ngc:2: /: block delete"},
        {"G20\n% G1 X1\n", "p.ngc:2: %: a '%' line"},
        {"G20\nG1 X1 @\n", "p.ngc:2: @: not a G-code word"},
        {"G20\nG1 X1 Q2\n", "p.ngc:2: Q2: not a word parsons reads"},
        {"G20\nG1 X1.2.3\n", "p.ngc:2: .: not a G-code word"},
    };
    for (const Case& c : cases) {
        INFO(c.program);
        CHECK_THAT(refusal(c.program), Contains(c.message));
    }
}

TEST_CASE("G-code: what is read: units, distances, comments, the end, the spindle", "[gcode]") {
    SECTION("G21 millimetres are inches on the deck, G20 inches as they are") {
        const auto p = read("G21 G1 X25.4 Y-12.7 F100\nG20 G1 Z0.5\n");
        REQUIRE(p.moves.size() == 2);
        CHECK(p.millimetres);
        CHECK(p.moves[0].to.x() == Approx(1.0));
        CHECK(p.moves[0].to.y() == Approx(-0.5));
        CHECK(p.moves[1].to.isApprox(Vector3d(1.0, -0.5, 0.5)));
    }
    SECTION("G91 adds to where the tool stands, G90 puts it back to absolute") {
        const auto p = read("G20 G91 G1 X1\nX1 Y0.5\nG90 X0.25\n");
        REQUIRE(p.moves.size() == 3);
        CHECK(p.moves[1].from.x() == Approx(1.0));
        CHECK(p.moves[1].to.x() == Approx(2.0));
        CHECK(p.moves[1].to.y() == Approx(0.5));
        CHECK(p.moves[2].to.x() == Approx(0.25));
        CHECK(p.moves[2].to.y() == Approx(0.5));
    }
    SECTION("comments, line numbers, % lines and blank lines are read past; M2 ends the program") {
        const auto p = read("%\n(a comment)\nN10 G20 ; inches\n\r\nN20 G1 X1 (move) Y1\nM2\nG1 "
                            "X5\nthis is not G-code\n");
        REQUIRE(p.moves.size() == 1);
        CHECK(p.moves[0].line == 5);
        CHECK(p.moves[0].to == Vector3d(1, 1, 0));
    }
    SECTION("lower case and spaces inside a word are read as RS-274 reads them") {
        const auto p = read("g20 g1 x 1.5 y-.5\n");
        REQUIRE(p.moves.size() == 1);
        CHECK(p.moves[0].to == Vector3d(1.5, -0.5, 0));
    }
    SECTION("F, S and coolant are listed as ignored, once each, with the first line") {
        const auto p = read("G20 M3 S1000\nG1 X1 F10\nG1 X2 F20\nM8\n");
        REQUIRE(p.ignored.size() == 3);
        CHECK_THAT(p.ignored[0], Contains("S (first on line 1)"));
        CHECK_THAT(p.ignored[1], Contains("F (first on line 2)"));
        CHECK_THAT(p.ignored[2], Contains("M7/M8/M9 (first on line 4)"));
        // One warning a kind, at its first line, counting the later lines that hold one.
        REQUIRE(p.warnings.size() == 3);
        CHECK(p.warnings[0] == "p.ngc:1: S1000 ignored: spindle speed: the 1952 spindle runs at "
                               "the speed set on the machine");
        CHECK(p.warnings[1] ==
              "p.ngc:2: F10 ignored: feeds: the deck's speeds are the speed switches', chosen by "
              "the slow-down rule, not the program's (the same on 1 later line, not told again)");
        CHECK(p.warnings[2] == "p.ngc:4: M8 ignored: coolant: the 1952 card has no column for it");
    }
    SECTION("the modal words that state what parsons assumes are read without a word") {
        const auto p = read("G17 G40 G49 G54 G61 G80 G90 G94 G91.1\nG20 G1 X1\n");
        CHECK(p.warnings.empty());
        CHECK(p.moves.size() == 1);
    }
    SECTION("M3, M4 and M5 set the spindle column of the moves that follow") {
        const auto p = read("G20 G1 X1\nM3\nX2\nM4 X3\nM5\nX4\n");
        REQUIRE(p.moves.size() == 4);
        CHECK(p.moves[0].spindle == 0);
        CHECK(p.moves[1].spindle == 1);
        CHECK(p.moves[2].spindle == 2);
        CHECK(p.moves[3].spindle == 0);
    }
    SECTION("a move to where the tool stands is not a move") {
        CHECK(read("G20 G1 X0 Y0\nG1 X1\nX1\n").moves.size() == 1);
    }
}

TEST_CASE("G-code: arcs by centre and by radius, both senses, full circles and helices",
          "[gcode]") {
    SECTION("I J: a clockwise quarter is -90 degrees, the counter-clockwise way round 270") {
        const auto cw = read("G20 G0 X1\nG2 X0 Y-1 I-1 J0\n").moves.at(1);
        CHECK(cw.centre.isApprox(Eigen::Vector2d(0, 0)));
        CHECK(cw.sweep_rad == Approx(-std::numbers::pi / 2));
        const auto ccw = read("G20 G0 X1\nG3 X0 Y-1 I-1 J0\n").moves.at(1);
        CHECK(ccw.sweep_rad == Approx(3 * std::numbers::pi / 2));
        CHECK(decks::point_on(ccw, 1.0 / 3).isApprox(Vector3d(0, 1, 0)));
    }
    SECTION("R positive: the short way; negative: the long way; the centre on the right side") {
        const auto g2 = read("G20 G2 X1 Y1 R1\n").moves.at(0);
        CHECK(g2.centre.isApprox(Eigen::Vector2d(1, 0)));
        CHECK(g2.sweep_rad == Approx(-std::numbers::pi / 2));
        const auto g3 = read("G20 G3 X1 Y1 R1\n").moves.at(0);
        CHECK(g3.centre.isApprox(Eigen::Vector2d(0, 1)));
        CHECK(g3.sweep_rad == Approx(std::numbers::pi / 2));
        const auto g2long = read("G20 G2 X1 Y1 R-1\n").moves.at(0);
        CHECK(g2long.centre.isApprox(Eigen::Vector2d(0, 1)));
        CHECK(g2long.sweep_rad == Approx(-3 * std::numbers::pi / 2));
    }
    SECTION("an arc ending where it starts is a full circle; a Z word makes a helix") {
        const auto full = read("G20 G0 X1\nG2 X1 Y0 Z-0.5 I-1 J0\n").moves.at(1);
        CHECK(full.sweep_rad == Approx(-2 * std::numbers::pi));
        const Vector3d half = decks::point_on(full, 0.5);
        CHECK(half.isApprox(Vector3d(-1, 0, -0.25), 1e-9));
        const auto full_ccw = read("G20 G0 X1\nG3 X1 Y0 I-1 J0\n").moves.at(1);
        CHECK(full_ccw.sweep_rad == Approx(2 * std::numbers::pi));
    }
    SECTION("an end half a thousandth off its circle is taken; more is refused") {
        CHECK_NOTHROW(read("G20 G0 X1\nG3 X0 Y1.0004 I-1 J0\n"));
        CHECK_THROWS_AS(read("G20 G0 X1\nG3 X0 Y1.0006 I-1 J0\n"), cardreader::DeckError);
    }
}

TEST_CASE("G-code deck: within the tolerance, chords and staircases, every station",
          "[gcode][heavy]") {
    const auto program = read("G20 G90\nG0 Z0.2\nG1 Z-0.1\nG1 X2 Y1\nG3 X3 Y2 I0 J1\nG2 X3.5 Y2.5 "
                              "R0.5\nG1 X0.5 Y2.5 Z0\n");
    const auto profile = axes::default_profile();
    for (double tolerance : {0.003, 0.005, 0.02}) {
        INFO("tolerance " << tolerance);
        decks::GcodeJobOptions o;
        o.tolerance_in = tolerance;
        const auto deck = decks::make_gcode_deck(program, o, profile);
        CHECK(deck.approach_cards == 1);
        CHECK(deck.arcs == 2);
        CHECK(deck.lines == 4);
        // Only Z goes below 0: it alone is moved, the program's lowest point margin inside.
        CHECK(deck.work_zero_in.x() == 0);
        CHECK(deck.work_zero_in.y() == 0);
        CHECK(deck.work_zero_in.z() == Approx(0.6));
        CHECK(deck.planned_deviation_in <= tolerance / 3 + 0.0009);
        // Every stop and every staircase corner of every card after the approach, against the
        // program's own path.
        Vector3d at = stop_of(deck.cards.front());
        double worst = 0;
        for (std::size_t i = 1; i < deck.cards.size(); ++i) {
            const auto& c = deck.cards[i];
            std::vector<std::pair<int, int>> order; // sequence position, axis
            for (int k = 0; k < 3; ++k) {
                if (c.axes[k].check != 0) {
                    order.emplace_back(static_cast<int>(c.axes[k].sequence), k);
                }
            }
            std::sort(order.begin(), order.end());
            for (const auto& [position, k] : order) {
                at[k] = c.axes[k].stop / 1000.0;
                worst = std::max(worst, off_program(at, program, deck.work_zero_in));
            }
        }
        CHECK(worst <= tolerance);
        CHECK(worst >= tolerance / 20); // the staircase is there: a finer tolerance, more cards
    }
    decks::GcodeJobOptions coarse;
    coarse.tolerance_in = 0.02;
    decks::GcodeJobOptions fine;
    fine.tolerance_in = 0.003;
    CHECK(decks::make_gcode_deck(program, fine, profile).cards.size() >
          2 * decks::make_gcode_deck(program, coarse, profile).cards.size());
}

TEST_CASE("G-code deck: the order of the axes, the approach, the spindle column", "[gcode]") {
    const auto profile = axes::default_profile();
    const auto deck =
        decks::make_gcode_deck(read("G20 M3 G1 X1 Y0.5 Z1\nG1 X2 Z0.5\nM4 G1 X2.5\n"), {}, profile);
    // The program lies within the counters: nothing is moved, and there is no approach.
    CHECK(deck.work_zero_in == Vector3d::Zero());
    CHECK(deck.approach_cards == 0);
    const auto& up = deck.cards.front();
    // Going up: the vertical slide first, then the table, then the cross slide, at the last
    // sequence positions; swivel and tilt stand at the first.
    CHECK(up.axes[2].sequence == 0b00100);
    CHECK(up.axes[0].sequence == 0b01000);
    CHECK(up.axes[1].sequence == 0b10000);
    CHECK(up.axes[3].sequence == 0b00001);
    CHECK(up.axes[4].sequence == 0b00010);
    CHECK(up.spindle == cardreader::Spindle::forward);
    // Going down: the table first and the vertical slide last.
    const auto down = std::find_if(deck.cards.begin(), deck.cards.end(), [](const auto& c) {
        return c.axes[2].motion == cardreader::Motion::reverse && c.axes[2].check != 0;
    });
    REQUIRE(down != deck.cards.end());
    CHECK(down->axes[0].sequence < down->axes[2].sequence);
    CHECK(deck.cards.back().spindle == cardreader::Spindle::reverse);
    CHECK(stop_of(deck.cards.back()).isApprox(Vector3d(2.5, 0.5, 0.5)));

    SECTION("a program below the counters' zero: the approach goes there vertical, table, cross") {
        const auto d = decks::make_gcode_deck(read("G20 G1 X-1 Y-2 Z-0.25\n"), {}, profile);
        CHECK(d.work_zero_in.isApprox(Vector3d(1.5, 2.5, 0.75)));
        REQUIRE(d.approach_cards == 1);
        const auto& a = d.cards.front();
        CHECK(stop_of(a).isApprox(d.work_zero_in));
        CHECK(a.axes[2].sequence < a.axes[0].sequence);
        CHECK(a.axes[0].sequence < a.axes[1].sequence);
    }
}

TEST_CASE("G-code deck: the corner rule slows only the approach to a sharp turn", "[gcode]") {
    const auto profile = axes::default_profile();
    const auto program = read("G20 G1 X3\nG1 Y2\n");
    const auto deck = decks::make_gcode_deck(program, {}, profile);
    // Card 1 runs the table fast to 0.05 in before the turn, card 2 the rest at speed 3.
    REQUIRE(deck.cards.size() >= 3);
    CHECK(deck.cards[0].axes[0].start_speed == 1);
    CHECK(deck.cards[0].axes[0].stop == 2950);
    CHECK(deck.cards[1].axes[0].start_speed == 3);
    CHECK(deck.cards[1].axes[0].stop == 3000);
    CHECK(deck.corner_cards == 1);
    // Without the rule, one card to the turn, as the planner chooses it.
    decks::GcodeJobOptions off;
    off.corner_slowdown = false;
    const auto plain = decks::make_gcode_deck(program, off, profile);
    CHECK(plain.corner_cards == 0);
    CHECK(plain.cards[0].axes[0].stop == 3000);
    CHECK(plain.cards.size() + 1 == deck.cards.size());
    // A gentle turn (under the 30-degree limit) is not a corner.
    CHECK(decks::make_gcode_deck(read("G20 G1 X3\nG1 X6 Y1\n"), {}, profile).corner_cards == 0);
}

TEST_CASE("G-code deck: refusals: the counters' range, the tolerance, too many cards", "[gcode]") {
    const auto profile = axes::default_profile();
    const auto program = read("G20\nG1 X5\nG1 X-6\n");
    decks::GcodeJobOptions o;
    o.work_zero_in = Vector3d(1, 0, 0);
    CHECK_THROWS_WITH(
        decks::make_gcode_deck(program, o, profile),
        Contains("p.ngc:3: X (table) reaches -6.0000 in, -5.0000 in on the counters") &&
            Contains("given by --work-zero"));
    o.work_zero_in = Vector3d(6, 0, 0);
    CHECK_THROWS_WITH(decks::make_gcode_deck(program, o, profile),
                      Contains("p.ngc:2: X (table) reaches 5.0000 in, 11.0000 in"));
    // Automatic: 11 inches of travel cannot fit 0 .. 9.999.
    CHECK_THROWS_WITH(decks::make_gcode_deck(read("G20 G1 X5\nX-6\n"), {}, profile),
                      Contains("X (table) reaches 5.0000 in, 11.5000 in"));
    decks::GcodeJobOptions tight;
    tight.tolerance_in = 0.0029;
    CHECK_THROWS_WITH(decks::make_gcode_deck(read("G20 G1 X1\n"), tight, profile),
                      Contains("tolerance 0.0029 in: at least 0.003 in"));
    tight.tolerance_in = 0.003;
    CHECK_NOTHROW(decks::make_gcode_deck(read("G20 G1 X1\n"), tight, profile));
    std::string circles = "G20 G0 X4.5 Y0.5\n";
    for (int i = 0; i < 7; ++i) {
        circles += "G3 X4.5 Y0.5 I0 J4\n"; // 8,166 cards a turn at 0.003 in
    }
    CHECK_THROWS_WITH(decks::make_gcode_deck(read(circles), tight, profile),
                      Contains("p.ngc:3: more than 9,999 cards at a tolerance of 0.003 in"));
    CHECK_THROWS_WITH(decks::make_gcode_deck(read("G20\n"), {}, profile), Contains("no moves"));
}

TEST_CASE("G-code deck: runs on the machine to the program's end", "[gcode]") {
    const auto profile = axes::default_profile();
    const auto deck = decks::make_gcode_deck(
        read("G21 G0 Z5\nG0 X-10 Y-5\nG1 Z-2\nG2 X10 Y-5 I10 J0\nG0 Z5\n"), {}, profile);
    const auto result = test::run_orders(deck.cards, profile);
    REQUIRE(result.completed);
    const Vector3d end = Vector3d(10 / 25.4, -5 / 25.4, 5 / 25.4) + deck.work_zero_in;
    for (int k = 0; k < 3; ++k) {
        CHECK(result.axes.at(static_cast<std::size_t>(k)).real_in == Approx(end[k]).margin(0.0011));
    }
}

TEST_CASE("G-code path: lines per speed, F from the speed switches, cards and the end named",
          "[gcode]") {
    // One card: the table 2.95 in at speed 1 with its two slow-downs (5.4, 1.8, 0.6 in/min).
    const auto profile = axes::default_profile();
    cardreader::CardOrders c = test::idle_card(1, {0, 0, 0, 0, 0});
    c.axis(cardreader::Axis::table) =
        decks::plan_move({0, 2950, 2, false, 0b00001}, profile.axes[0], profile);
    REQUIRE(c.axis(cardreader::Axis::table).start_speed == 1);
    std::ostringstream out;
    cli::GcodePathWriter writer(out, "one.csv");
    const auto result = test::run_orders({c}, profile, &writer);
    REQUIRE(result.completed);
    const std::string g = out.str();
    CHECK_THAT(g, Contains("(parsons: one.csv as the emulated machine moved it)"));
    CHECK_THAT(g, Contains("G20 G90 G17 G94\n(card 1, number 0001)\nG1 X"));
    CHECK_THAT(g, Contains("(completed at "));
    CHECK(g.substr(g.size() - 3) == "M2\n");
    std::vector<double> feeds;
    double last_x = 0;
    const std::regex line(R"(G1 X(-?[0-9.]+) Y(-?[0-9.]+) Z(-?[0-9.]+) F([0-9.]+))");
    for (const auto& l : test::lines_of(g)) {
        std::smatch m;
        if (std::regex_match(l, m, line)) {
            feeds.push_back(std::stod(m[4]));
            last_x = std::stod(m[1]);
        }
    }
    CHECK(last_x == Approx(result.axes[0].real_in).margin(0.00001));
    // The first line at speed 1 (5.4 in/min, less its run-up), then one line from each step of
    // speed switch 236, each slower (the slowing from one speed to the next is in its line),
    // the last no faster than speed 3 (0.6 in/min), creeping to the stop and coasting.
    REQUIRE(feeds.size() >= 3);
    CHECK(feeds.front() == Approx(5.4).epsilon(0.03));
    CHECK(std::is_sorted(feeds.rbegin(), feeds.rend()));
    CHECK(feeds.back() <= 0.6 + 1e-9);
}

TEST_CASE("G-code commands: gen gcode and convert to .ngc, exit codes", "[gcode][cli]") {
    test::TempDir dir;
    const std::string sample = test::source_path("decks/samples/bracket.ngc");
    auto r = test::run_parsons("gen gcode " + test::q(sample) + " -o " + test::q(dir.str("b.cbn")));
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.output, Contains("4 arcs"));
    r = test::run_parsons("convert " + test::q(dir.str("b.cbn")) + " -o " +
                          test::q(dir.str("b.ngc")));
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.output, Contains("-> " + dir.str("b.ngc") + " (G-code)"));
    const std::string g = test::read_bytes(dir.path("b.ngc"));
    CHECK_THAT(g, Contains("(card 1987, number 1987)"));
    CHECK_THAT(g, Contains("(completed at "));

    SECTION("bad G-code: exit 2, the file, the line and the word") {
        test::write_bytes(dir.path("bad.ngc"), "G20\nG1 X1\nG41 X2\n");
        r = test::run_parsons("gen gcode " + test::q(dir.str("bad.ngc")) + " -o " +
                              test::q(dir.str("x.cbn")));
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Contains(dir.str("bad.ngc") + ":3: G41: cutter radius compensation"));
        CHECK_FALSE(std::filesystem::exists(dir.path("x.cbn")));
    }
    SECTION("a program that does not fit the counters: exit 2 naming the line") {
        test::write_bytes(dir.path("big.ngc"), "G20\nG1 X12\n");
        r = test::run_parsons("gen gcode " + test::q(dir.str("big.ngc")) + " -o " +
                              test::q(dir.str("x.cbn")));
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Contains("big.ngc:2: X (table) reaches 12.0000 in"));
    }
    SECTION("a deck that stops the machine: the path to the stop, a comment, exit 3") {
        r = test::run_parsons("run " + test::q(dir.str("b.cbn")) + " --limit table=0:2 -q");
        REQUIRE(r.exit_code == 3);
        r = test::run_parsons("convert " + test::q(dir.str("b.cbn")) + " -o " +
                              test::q(dir.str("s.ngc")) + " --profile " +
                              test::q(test::source_path("tests/gcode/short-table.json")));
        CHECK(r.exit_code == 3);
        CHECK_THAT(r.output, Contains("to the machine stop"));
        const std::string g = test::read_bytes(dir.path("s.ngc"));
        CHECK_THAT(g, Contains("(machine stop at "));
        // Cut short, it says so last and never ends as a whole program would.
        const auto lines = test::lines_of(g);
        REQUIRE_FALSE(lines.empty());
        CHECK_THAT(lines.back(), Contains("(INCOMPLETE: the path ends at the machine stop"));
        for (const std::string& line : lines) {
            CHECK(line != "M2");
            CHECK(line != "M30");
        }
    }
    SECTION("--profile is only for G-code output") {
        r = test::run_parsons("convert " + test::q(dir.str("b.cbn")) + " -o " +
                              test::q(dir.str("b.bin")) + " --profile parsons-1952");
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Contains("--profile is for G-code output"));
    }
}

namespace {

decks::GcodeProgram read_file(const std::string& relative, decks::GcodeReading how = {}) {
    return decks::read_gcode(test::read_bytes(test::source_path(relative)), relative, how);
}

std::string strict_refusal(const std::string& relative) {
    try {
        read_file(relative, {.strict = true});
    } catch (const cardreader::DeckError& e) {
        return e.what();
    }
    return "no refusal";
}

const std::vector<std::string> kLinuxcncWarnings = {
    "tests/gcode/linuxcnc-post.ngc:2: O1001 ignored: a program number: the deck is known by its "
    "file's name",
    "tests/gcode/linuxcnc-post.ngc:9: G64 P0.001 ignored: path blending: the 1952 machine stops "
    "every axis at the end of each card, an exact stop whatever the program asks",
    "tests/gcode/linuxcnc-post.ngc:11: T1 M6 ignored: the 1952 machine has no tool changer; the "
    "deck runs the one cutter set in the spindle by hand",
    "tests/gcode/linuxcnc-post.ngc:12: G43 H1 ignored: tool length offset: the cutter is set by "
    "hand to the deck's zero, so the program's Z is the cutter's tip",
    "tests/gcode/linuxcnc-post.ngc:13: S1200 ignored: spindle speed: the 1952 spindle runs at the "
    "speed set on the machine",
    "tests/gcode/linuxcnc-post.ngc:14: M8 ignored: coolant: the 1952 card has no column for it "
    "(the same on 1 later line, not told again)",
    "tests/gcode/linuxcnc-post.ngc:15: F5. ignored: feeds: the deck's speeds are the speed "
    "switches', chosen by the slow-down rule, not the program's (the same on 3 later lines, not "
    "told again)",
};

const std::vector<std::string> kGrblWarnings = {
    "tests/gcode/grbl-post.ngc:11: T1 ignored: the 1952 machine has no tool changer; the deck "
    "runs the one cutter set in the spindle by hand",
    "tests/gcode/grbl-post.ngc:13: S12000 ignored: spindle speed: the 1952 spindle runs at the "
    "speed set on the machine",
    "tests/gcode/grbl-post.ngc:15: M8 ignored: coolant: the 1952 card has no column for it (the "
    "same on 1 later line, not told again)",
    "tests/gcode/grbl-post.ngc:16: F127 ignored: feeds: the deck's speeds are the speed "
    "switches', chosen by the slow-down rule, not the program's (the same on 3 later lines, not "
    "told again)",
    "tests/gcode/grbl-post.ngc:31: G28 ignored: a return home after the last move: the deck ends "
    "where its last card stops, and the operator brings the machine home",
};

} // namespace

TEST_CASE("G-code: programs as LinuxCNC's and grbl's posts write them are the bracket's cut, "
          "with one warning a kind of ignored word",
          "[gcode]") {
    const auto bare = read_file("decks/samples/bracket.ngc");
    const auto profile = axes::default_profile();
    const auto bare_deck = decks::make_gcode_deck(bare, {}, profile);
    struct Post {
        std::string file;
        std::vector<std::string> warnings;
    };
    for (const Post& post : {Post{"tests/gcode/linuxcnc-post.ngc", kLinuxcncWarnings},
                             Post{"tests/gcode/grbl-post.ngc", kGrblWarnings}}) {
        INFO(post.file);
        const auto p = read_file(post.file);
        CHECK(p.warnings == post.warnings);
        // The same moves: kind, ends, centres, sweeps and spindle, to a millionth of an inch
        // (the grbl program is in millimetres).
        REQUIRE(p.moves.size() == bare.moves.size());
        for (std::size_t i = 0; i < p.moves.size(); ++i) {
            INFO("move " << i + 1);
            CHECK(p.moves[i].motion == bare.moves[i].motion);
            CHECK((p.moves[i].from - bare.moves[i].from).norm() < 1e-6);
            CHECK((p.moves[i].to - bare.moves[i].to).norm() < 1e-6);
            CHECK((p.moves[i].centre - bare.moves[i].centre).norm() < 1e-6);
            CHECK(p.moves[i].sweep_rad == Approx(bare.moves[i].sweep_rad).margin(1e-9));
            CHECK(p.moves[i].spindle == bare.moves[i].spindle);
        }
        // And the same deck, card for card.
        const auto deck = decks::make_gcode_deck(p, {}, profile);
        CHECK(deck.cards == bare_deck.cards);
    }
    SECTION("--strict refuses each at its first ignored word, naming file, line and word") {
        CHECK_THAT(strict_refusal("tests/gcode/linuxcnc-post.ngc"),
                   Contains("tests/gcode/linuxcnc-post.ngc:2: O1001: a program number") &&
                       Contains("(refused under --strict, which ignores nothing)"));
        CHECK_THAT(strict_refusal("tests/gcode/grbl-post.ngc"),
                   Contains("tests/gcode/grbl-post.ngc:11: T1: the 1952 machine has no tool "
                            "changer"));
        CHECK_THAT(strict_refusal("decks/samples/bracket.ngc"),
                   Contains("decks/samples/bracket.ngc:5: S1200: spindle speed"));
        // A program with nothing to ignore reads the same under --strict.
        CHECK(
            decks::read_gcode("G20 G90 G17\nG1 X1 Y1\nG2 X2 Y0 R1\nM2\n", "p.ngc", {.strict = true})
                .moves.size() == 2);
    }
    SECTION("what the machine cannot follow is still refused without --strict") {
        std::string text = test::read_bytes(test::source_path("tests/gcode/linuxcnc-post.ngc"));
        text.replace(text.find("N50 X3. F12."), 12, "N50 G41 D1 X3.");
        CHECK_THAT(refusal(text), Contains("p.ngc:16: G41: cutter radius compensation"));
    }
}

TEST_CASE("G-code commands: gen gcode reads a post's program with its warnings on standard "
          "error, and --strict refuses it with exit 2 and no deck",
          "[gcode][cli]") {
    test::TempDir dir;
    auto r =
        test::run_parsons("gen gcode " + test::q(test::source_path("decks/samples/bracket.ngc")) +
                          " -o " + test::q(dir.str("bare.cbn")));
    REQUIRE(r.exit_code == 0);
    for (const std::string name : {"linuxcnc-post", "grbl-post"}) {
        INFO(name);
        // Run from the source tree, so that the warnings name the file as the table above does.
        const std::string cd = "cd " + test::q(test::source_path("")) + " && ";
        r = test::run_shell(cd + "PARSONS gen gcode tests/gcode/" + name + ".ngc -o " +
                            test::q(dir.str(name + ".cbn")) + " >/dev/null");
        CHECK(r.exit_code == 0);
        std::string expected;
        for (const std::string& w : name == "grbl-post" ? kGrblWarnings : kLinuxcncWarnings) {
            expected += "parsons: warning: " + w + "\n";
        }
        CHECK(r.output == expected);
        CHECK(test::read_bytes(dir.path(name + ".cbn")) == test::read_bytes(dir.path("bare.cbn")));

        r = test::run_shell(cd + "PARSONS gen gcode tests/gcode/" + name + ".ngc --strict -o " +
                            test::q(dir.str(name + "-strict.cbn")));
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Contains("parsons: error: tests/gcode/" + name + ".ngc:"));
        CHECK_THAT(r.output, Contains("(refused under --strict, which ignores nothing)"));
        CHECK_FALSE(std::filesystem::exists(dir.path(name + "-strict.cbn")));
    }
    r = test::run_parsons("gen gcode --help");
    CHECK_THAT(r.output, Contains("--strict"));
}

TEST_CASE("G-code: a second tool is refused whatever its number, higher or lower than the first's",
          "[gcode]") {
    CHECK_THAT(refusal("G20\nT3 M6\nG1 X1\nT5 M6\n"),
               Contains("p.ngc:4: T5: a second tool (the program began with T3)"));
    CHECK_THAT(refusal("G20\nT3 M6\nG1 X1\nT1 M6\n"),
               Contains("p.ngc:4: T1: a second tool (the program began with T3)"));
    // The same tool again is no second tool.
    CHECK(read("G20\nT3 M6\nG1 X1\nT3 M6\nG1 X2\n").moves.size() == 2);
}

TEST_CASE("G-code: a program number followed by a semicolon comment is a program number",
          "[gcode]") {
    const auto p = read("O1234 ; the bracket\nG20 G1 X1\n");
    REQUIRE(p.moves.size() == 1);
    REQUIRE(p.ignored.size() == 1);
    CHECK_THAT(p.ignored[0], Contains("O (first on line 1)"));
    CHECK(read("N5 O<part>;x\nG20 G1 X1\n").ignored.size() == 1);
    // Anything else after it is LinuxCNC's subroutines, refused.
    CHECK_THAT(refusal("O1234 sub\n"), Contains("p.ngc:1: O: parameters"));
}

TEST_CASE("G-code: a UTF-8 byte-order mark at the start of a program is read past", "[gcode]") {
    const auto p = read("\xEF\xBB\xBFG20 G1 X1\n");
    REQUIRE(p.moves.size() == 1);
    CHECK(p.moves[0].to == Vector3d(1, 0, 0));
    // Only at the start: elsewhere the bytes are no G-code, named visibly.
    CHECK_THAT(refusal("G20\n\xEF\xBB\xBFG1 X1\n"), Contains("p.ngc:2: \\xef: not a G-code word"));
}

TEST_CASE("G-code: Fusion's retract G53 G0 Z0 is the tool up to the program's highest Z, with a "
          "warning",
          "[gcode]") {
    const auto p = read("G21 G90\nG0 Z15\nG1 Z-1 F100\nG1 X10\nG53 G0 Z0.\nG0 X0\n");
    REQUIRE(p.moves.size() == 5);
    CHECK(p.moves[3].line == 5);
    CHECK(p.moves[3].motion == decks::GcodeMotion::rapid);
    CHECK(p.moves[3].to.z() == Approx(15 / 25.4));
    CHECK(p.moves[3].to.x() == Approx(10 / 25.4));
    CHECK(p.moves[4].from.z() == Approx(15 / 25.4)); // the tool stays up
    REQUIRE(p.warnings.size() == 2);
    CHECK_THAT(p.warnings[1], Contains("p.ngc:5: G53 G0 Z0. ignored: a retract to machine zero: "
                                       "read as the tool up"));
    SECTION("a program that never rises above its zero: the tool up is Z 0") {
        const auto q = read("G20\nG1 Z-0.1\nG53 G0 Z0\n");
        REQUIRE(q.moves.size() == 2);
        CHECK(q.moves[1].to.z() == 0);
    }
    SECTION("any other G53 is refused, and the retract under --strict") {
        CHECK_THAT(refusal("G20\nG53 G0 X0\n"), Contains("p.ngc:2: G53: machine coordinates"));
        CHECK_THAT(refusal("G20\nG53 G0 Z-2\n"), Contains("p.ngc:2: G53: machine coordinates"));
        CHECK_THAT(refusal("G20\nG53 G1 Z0\n"), Contains("p.ngc:2: G53: machine coordinates"));
        CHECK_THAT(refusal("G20 G91\nG53 G0 Z0\n"), Contains("p.ngc:2: G53: a retract"));
        try {
            decks::read_gcode("G20\nG1 Z-1\nG53 G0 Z0\n", "p.ngc", {.strict = true});
            FAIL("no refusal");
        } catch (const cardreader::DeckError& e) {
            CHECK_THAT(e.what(), Contains("p.ngc:3: G53 G0 Z0: a retract to machine zero"));
        }
    }
}

TEST_CASE("G-code: grbl's $ commands and ? queries are skipped with a warning", "[gcode]") {
    const auto p = read("$H\n$X\n?\nG20 G1 X1\n$$\n");
    REQUIRE(p.moves.size() == 1);
    REQUIRE(p.warnings.size() == 1);
    CHECK_THAT(p.warnings[0], Contains("p.ngc:1: $H ignored: a grbl command or status query"));
    CHECK_THAT(p.warnings[0], Contains("the same on 3 later lines"));
    CHECK_THAT(refusal("G20 G1 X1 $H\n"), Contains("p.ngc:1: $: not a G-code word"));
}

TEST_CASE("G-code commands: gen gcode - reads the program from standard input, as --help says",
          "[gcode][cli]") {
    test::TempDir dir;
    const std::string sample = test::source_path("decks/samples/bracket.ngc");
    auto r = test::run_shell("PARSONS gen gcode - -o " + test::q(dir.str("in.cbn")) + " < " +
                             test::q(sample));
    REQUIRE(r.exit_code == 0);
    r = test::run_parsons("gen gcode " + test::q(sample) + " -o " + test::q(dir.str("file.cbn")));
    REQUIRE(r.exit_code == 0);
    CHECK(test::read_bytes(dir.path("in.cbn")) == test::read_bytes(dir.path("file.cbn")));
    r = test::run_shell("printf 'G20\\nG41 X1\\n' | PARSONS gen gcode - -o " +
                        test::q(dir.str("x.cbn")));
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Contains("standard input:2: G41"));
}

TEST_CASE("G-code commands: a folder is refused as a folder, by every command that reads a file",
          "[gcode][cli]") {
    test::TempDir dir;
    std::filesystem::create_directory(dir.path("prog.ngc"));
    auto r = test::run_parsons("gen gcode " + test::q(dir.str("prog.ngc")) + " -o " +
                               test::q(dir.str("x.cbn")));
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Contains(dir.str("prog.ngc") + ": is a directory"));
    CHECK_THAT(r.output, !Contains("nothing to punch"));
    std::filesystem::create_directory(dir.path("deck.cbn"));
    for (const std::string command : {"run", "check", "show"}) {
        r = test::run_parsons(command + " " + test::q(dir.str("deck.cbn")));
        INFO(command);
        CHECK(r.exit_code == 2);
        CHECK_THAT(r.output, Contains(dir.str("deck.cbn") + ": is a directory"));
    }
    r = test::run_parsons("convert " + test::q(dir.str("deck.cbn")) + " -o " +
                          test::q(dir.str("y.csv")));
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Contains(dir.str("deck.cbn") + ": is a directory"));
    r = test::run_parsons("run " + test::q(test::source_path(test::kSample)) + " --profile " +
                          test::q(dir.str("deck.cbn")));
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.output, Contains(dir.str("deck.cbn") + ": is a directory"));
}

TEST_CASE("G-code commands: a program that begins with a byte-order mark makes the deck the "
          "program without one makes",
          "[gcode][cli]") {
    test::TempDir dir;
    const std::string sample = test::source_path("decks/samples/bracket.ngc");
    test::write_bytes(dir.path("bom.ngc"), "\xEF\xBB\xBF" + test::read_bytes(sample));
    auto r = test::run_parsons("gen gcode " + test::q(dir.str("bom.ngc")) + " -o " +
                               test::q(dir.str("bom.cbn")));
    REQUIRE(r.exit_code == 0);
    r = test::run_parsons("gen gcode " + test::q(sample) + " -o " + test::q(dir.str("b.cbn")));
    REQUIRE(r.exit_code == 0);
    CHECK(test::read_bytes(dir.path("bom.cbn")) == test::read_bytes(dir.path("b.cbn")));
}

TEST_CASE("G-code deck: an incremental millimetre program that comes back to its start keeps the "
          "work zero of its absolute twin",
          "[gcode]") {
    // Y +1 mm, +5 mm, -6 mm adds up to -2.8e-17 in, not 0: once read as a dip below zero, it
    // moved the cross slide's work zero by the margin, 0.5 in.
    const auto incremental = read("G21 G91\nG1 Y1\nY5\nY-6\nX10\n");
    const auto absolute = read("G21 G90\nG1 Y1\nY6\nY0\nX10\n");
    REQUIRE(incremental.moves.size() == 4);
    CHECK(incremental.moves[2].to.y() < 0); // the dust the rule is about
    decks::GcodeJobOptions o;
    const auto profile = axes::default_profile();
    const auto a = decks::make_gcode_deck(incremental, o, profile);
    const auto b = decks::make_gcode_deck(absolute, o, profile);
    CHECK(a.work_zero_in.y() == 0);
    CHECK(a.work_zero_in == b.work_zero_in);
    REQUIRE(a.cards.size() == b.cards.size());
    // A real dip below zero, however small on the counters, still moves it by the margin.
    const auto dip = decks::make_gcode_deck(read("G21 G91\nG1 Y1\nY-1.001\nX10\n"), o, profile);
    CHECK(dip.work_zero_in.y() == Approx(0.5 + 0.001 / 25.4));
}
