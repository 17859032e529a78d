// The other readers as fuzz targets: airfoil coordinate files (.dat), machine profiles and
// G-code programs.
//
// An airfoil the reader accepts must answer every chord station in [0, 1] of both surfaces
// with a finite point and a unit tangent. A profile the reader accepts must write out and read
// back the same, and run a short two-card deck on the machine as the machine target runs its
// decks (machine_run.hpp): to an end, and the same at both paces.
#include "tests/fuzz/fuzz_targets.hpp"
#include "tests/fuzz/machine_run.hpp"

#include "axes/profile_json.hpp"
#include "cardreader/deck_error.hpp"
#include "cardreader/layout.hpp"
#include "decks/airfoil.hpp"
#include "decks/gcode_job.hpp"
#include "decks/gcode_program.hpp"
#include "decks/move_planner.hpp"
#include "decks/template_job.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace parsons::fuzz {
namespace {

using namespace parsons::cardreader;

// Stations a deck generator asks for: the ends, the nose, and between.
constexpr std::array<double, 10> kStations = {0, 1e-9, 1e-4, 0.002, 0.03, 0.25, 0.5, 0.9, 0.999, 1};

AxisOrder move(int from, int stop, int speed, int gap, SequencePattern sequence) {
    AxisOrder o;
    const int direction = stop >= from ? 1 : -1;
    o.motion = direction > 0 ? Motion::forward : Motion::reverse;
    o.start_speed = speed;
    for (int i = 0; i < 3 - speed; ++i) {
        o.slow_down.at(static_cast<std::size_t>(i)) =
            static_cast<Thousandths>(stop - direction * gap * (3 - speed - i));
    }
    o.stop = static_cast<Thousandths>(stop);
    o.check = static_cast<Thousandths>(std::abs(stop - from));
    o.sequence = sequence;
    return o;
}

// Every axis out a little and back, in the patent's sequence (table and cross at 1 and 2,
// vertical and swivel at 3 and 4, tilt at 5), each start speed once: about 1500 impulses.
const std::vector<Card>& short_deck() {
    static const std::vector<Card> deck = [] {
        const std::array<int, kAxisCount> out = {300, 150, 40, 30, 20};
        const std::array<int, kAxisCount> speed = {1, 2, 3, 3, 3};
        const std::array<SequencePattern, kAxisCount> sequence = {0b00011, 0b00011, 0b01100,
                                                                  0b01100, 0b10000};
        std::vector<Card> cards;
        for (int number = 1; number <= 2; ++number) {
            CardOrders orders;
            orders.number = number;
            orders.spindle = Spindle::forward;
            for (Axis a : kAxes) {
                const std::size_t i = axis_index(a);
                const int from = number == 1 ? 0 : out.at(i);
                const int to = number == 1 ? out.at(i) : 0;
                orders.axis(a) = move(from, to, speed.at(i), 100, sequence.at(i));
            }
            cards.push_back(encode(orders, fig8_layout()).card);
        }
        return cards;
    }();
    return deck;
}

} // namespace

void fuzz_airfoil(Bytes input) {
    std::unique_ptr<decks::Airfoil> foil;
    try {
        foil = decks::read_dat_text(as_string(input), "fuzz.dat");
    } catch (const DeckError& e) {
        if (std::string_view(e.what()).rfind("fuzz.dat", 0) != 0) {
            throw Finding(
                fmt::format("airfoil: a DeckError that does not name the file: {}", e.what()));
        }
        return;
    }
    for (decks::Side side : {decks::Side::upper, decks::Side::lower}) {
        for (double u : kStations) {
            const decks::SurfaceSample s = foil->sample(side, u);
            if (!s.point.allFinite() || !(std::abs(s.tangent.norm() - 1) < 1e-9)) {
                throw Finding(fmt::format(
                    "airfoil: the {} surface at u = {} gives point ({}, {}), tangent ({}, {})",
                    side == decks::Side::upper ? "upper" : "lower", u, s.point.x(), s.point.y(),
                    s.tangent.x(), s.tangent.y()));
            }
        }
    }
}

void fuzz_profile(Bytes input) {
    axes::MachineProfile profile;
    try {
        profile = axes::profile_from_json(as_string(input), axes::default_profile());
    } catch (const axes::ProfileError&) {
        return;
    }
    const std::string written = axes::profile_to_json(profile);
    std::string again;
    try {
        again = axes::profile_to_json(axes::profile_from_json(written, axes::default_profile()));
    } catch (const axes::ProfileError& e) {
        throw Finding(
            fmt::format("profile: an accepted profile, written out, is refused: {}", e.what()));
    }
    if (again != written) {
        throw Finding("profile: an accepted profile reads back different:\n" + written +
                      "\nbecame\n" + again);
    }
    run_machine(short_deck(), profile, true);
}

// A G-code program the reader accepts is refused under --strict exactly when it has a warning,
// and has finite moves, each starting where the one before
// ended, arcs of a positive sweep no more than a turn whose end is on the circle; a deck made of
// it (or a clear refusal) has every card punchable, one station apart from the next, and ends
// where the program ends, to the thousandth.
void fuzz_gcode(Bytes input) {
    decks::GcodeProgram program;
    try {
        program = decks::read_gcode(as_string(input), "fuzz.ngc");
    } catch (const DeckError&) {
        return;
    }
    // --strict refuses exactly the programs that have a word to ignore (a warning).
    bool strict_reads = true;
    try {
        decks::read_gcode(as_string(input), "fuzz.ngc", {.strict = true});
    } catch (const DeckError&) {
        strict_reads = false;
    }
    if (strict_reads != program.warnings.empty()) {
        throw Finding(fmt::format("--strict {} a program with {} warnings",
                                  strict_reads ? "reads" : "refuses", program.warnings.size()));
    }
    Eigen::Vector3d at = Eigen::Vector3d::Zero();
    for (const decks::GcodeMove& m : program.moves) {
        if (!m.from.allFinite() || !m.to.allFinite() ||
            (m.from - at).norm() > 1e-9 * (1 + at.norm())) {
            throw Finding(fmt::format("line {}: a move not starting where the last ended", m.line));
        }
        at = m.to;
        if (m.motion == decks::GcodeMotion::arc_cw || m.motion == decks::GcodeMotion::arc_ccw) {
            const double s = std::abs(m.sweep_rad);
            const bool cw = m.motion == decks::GcodeMotion::arc_cw;
            if (!(s > 0 && s <= 2 * 3.14159265358979323846 + 1e-9) || (cw != (m.sweep_rad < 0))) {
                throw Finding(fmt::format("line {}: arc sweep {}", m.line, m.sweep_rad));
            }
            if ((decks::point_on(m, 1.0) - m.to).norm() > 1e-6 * (1 + m.to.norm())) {
                throw Finding(fmt::format("line {}: the arc does not end at its end", m.line));
            }
        }
    }
    decks::GcodeJobOptions o;
    o.tolerance_in = 0.05; // a few cards a move: the fuzzer's time is for the reader
    decks::GcodeDeck deck;
    try {
        deck = decks::make_gcode_deck(program, o, axes::default_profile());
    } catch (const decks::JobError&) {
        return;
    } catch (const decks::PlanError&) {
        return;
    }
    Eigen::Vector3i from = Eigen::Vector3i::Zero();
    for (const CardOrders& c : deck.cards) {
        const auto e = encode(c, fig8_layout());
        if (!e) {
            throw Finding(fmt::format("card {} cannot be punched: {}", c.number, *e.error));
        }
        const Eigen::Vector3i to(c.axes[0].stop, c.axes[1].stop, c.axes[2].stop);
        for (int k = 0; k < 3; ++k) {
            if (c.axes.at(static_cast<std::size_t>(k)).check != std::abs(to[k] - from[k])) {
                throw Finding(fmt::format("card {}: check is not the move", c.number));
            }
        }
        if (to == from) {
            throw Finding(fmt::format("card {} moves nothing", c.number));
        }
        from = to;
    }
    const Eigen::Vector3d end = (program.moves.back().to + deck.work_zero_in) * 1000;
    for (int k = 0; k < 3; ++k) {
        if (std::abs(end[k] - from[k]) > 0.5 + 1e-6) {
            throw Finding(fmt::format("the deck ends at {} on axis {}, the program at {}", from[k],
                                      k, end[k]));
        }
    }
}

} // namespace parsons::fuzz
