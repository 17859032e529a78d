// A G-code program as a deck (decks/gcode_job.hpp; docs/gcode.md).
#include "decks/gcode_job.hpp"

#include "decks/deck_limits.hpp"
#include "decks/move_planner.hpp"
#include "decks/template_job.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace parsons::decks {
namespace {

using Eigen::Vector3d;

constexpr double kCounterMaxIn = 9.999;
// Arithmetic dust (inches): an incremental (G91) program in millimetres that comes back to its
// start adds up to -5e-17 in, not 0; so little is no excursion below zero (it shifted the work
// zero by the margin, 0.5 in).
constexpr double kDustIn = 1e-9;
// A move that arrives at a sharp turn runs fast to this far before it, and the rest at the
// lowest speed (inches).
constexpr double kCornerApproachIn = 0.05;

const std::array<const char*, 3> kAxisLetters = {"X (table)", "Y (cross slide)",
                                                 "Z (vertical slide)"};

// Stations along one move, after its start: the end of a line; points round an arc whose
// chords stand off the arc by no more than `sagitta` (and no more than 10 degrees apart).
std::vector<Vector3d> stations_of(const GcodeMove& move, double sagitta) {
    if (move.motion == GcodeMotion::rapid || move.motion == GcodeMotion::linear) {
        return {move.to};
    }
    const double r = std::max((move.from.head<2>() - move.centre).norm(),
                              (move.to.head<2>() - move.centre).norm());
    double step = std::numbers::pi / 18;
    if (sagitta < r) {
        step = std::min(step, 2 * std::acos(1 - sagitta / r));
    }
    const std::int64_t n = std::max(
        std::int64_t{1}, static_cast<std::int64_t>(std::ceil(std::abs(move.sweep_rad) / step)));
    std::vector<Vector3d> out;
    for (std::int64_t i = 1; i <= n; ++i) {
        out.push_back(i == n ? move.to : point_on(move, static_cast<double>(i) / n));
    }
    return out;
}

double distance_to_segment(const Vector3d& x, const Vector3d& p, const Vector3d& q) {
    const Vector3d d = q - p;
    const double len2 = d.squaredNorm();
    const double t = len2 == 0 ? 0 : std::clamp((x - p).dot(d) / len2, 0.0, 1.0);
    return (x - (p + t * d)).norm();
}

// The axes that move from p to q, in the order they move (gcode_job.hpp): 0 table, 1 cross,
// 2 vertical.
std::vector<int> axis_order(const Eigen::Vector3i& p, const Eigen::Vector3i& q) {
    std::vector<int> order;
    const bool down = q.z() < p.z();
    if (!down && q.z() != p.z()) {
        order.push_back(2);
    }
    for (int k = 0; k < 2; ++k) {
        if (q[k] != p[k]) {
            order.push_back(k);
        }
    }
    if (down) {
        order.push_back(2);
    }
    return order;
}

// How far the corners of the staircase from p to q (moving the axes in `order`) stand off the
// straight line.
double staircase_offset(const Vector3d& p, const Vector3d& q, const std::vector<int>& order) {
    double worst = 0;
    Vector3d corner = p;
    for (std::size_t i = 0; i + 1 < order.size(); ++i) {
        corner[order[i]] = q[order[i]];
        worst = std::max(worst, distance_to_segment(corner, p, q));
    }
    return worst;
}

Eigen::Vector3i thousandths(const Vector3d& inches) {
    return {static_cast<int>(std::lround(inches.x() * 1000)),
            static_cast<int>(std::lround(inches.y() * 1000)),
            static_cast<int>(std::lround(inches.z() * 1000))};
}

cardreader::Spindle spindle_column(int spindle) {
    return spindle == 1   ? cardreader::Spindle::forward
           : spindle == 2 ? cardreader::Spindle::reverse
                          : cardreader::Spindle::off;
}

// One card from p to q (thousandths): the moving axes in order at the last sequence positions,
// the standing ones (swivel and tilt always, and any of the three that does not move) stopping
// at once at the first.
cardreader::CardOrders card(int number, const Eigen::Vector3i& p, const Eigen::Vector3i& q,
                            const std::vector<int>& order, bool corner, int spindle,
                            const axes::MachineProfile& profile) {
    cardreader::CardOrders c;
    c.number = number % 10000;
    c.spindle = spindle_column(spindle);
    const int standing = 5 - static_cast<int>(order.size());
    int next_standing = 0;
    for (int k = 0; k < 5; ++k) {
        const bool moves = std::find(order.begin(), order.end(), k) != order.end();
        int position = 0;
        if (moves) {
            position = standing +
                       static_cast<int>(std::find(order.begin(), order.end(), k) - order.begin());
        } else {
            position = next_standing++;
        }
        const int from = k < 3 ? p[k] : 0;
        const int to = k < 3 ? q[k] : 0;
        MoveRequest move;
        move.from = from;
        move.to = to;
        move.slow_down_fields = k == 0 ? 2 : 1;
        move.corner = corner;
        move.sequence = static_cast<cardreader::SequencePattern>(1u << position);
        c.axes.at(static_cast<std::size_t>(k)) =
            plan_move(move, profile.axes.at(static_cast<std::size_t>(k)), profile);
    }
    return c;
}

// A design station, in the program's frame, with the line it comes from.
struct Design {
    Vector3d at;
    std::int64_t line;
    int spindle;
};

// A station the cards go to.
struct Station {
    Eigen::Vector3i at;
    bool corner; // the card arriving here runs at the lowest speed
    int spindle;
};

// The design stations, the program's frame, each with the line it comes from; counts the
// deck's lines and arcs.
std::vector<Design> design_of(const GcodeProgram& program, double third, GcodeDeck& deck) {
    std::vector<Design> design{{Vector3d::Zero(), 0, program.moves.front().spindle}};
    for (const GcodeMove& m : program.moves) {
        const bool is_arc = m.motion == GcodeMotion::arc_cw || m.motion == GcodeMotion::arc_ccw;
        (is_arc ? deck.arcs : deck.lines) += 1;
        for (const Vector3d& s : stations_of(m, third)) {
            design.push_back({s, m.line, m.spindle});
        }
    }
    return design;
}

// The work zero, and the counters' range.
void place_work_zero(const std::vector<Design>& design, const GcodeProgram& program,
                     const GcodeJobOptions& o, GcodeDeck& deck) {
    Vector3d lo = Vector3d::Zero();
    Vector3d hi = Vector3d::Zero();
    std::array<std::int64_t, 3> lo_line{};
    std::array<std::int64_t, 3> hi_line{};
    for (const Design& d : design) {
        for (int k = 0; k < 3; ++k) {
            if (d.at[k] < lo[k]) {
                lo[k] = d.at[k];
                lo_line[static_cast<std::size_t>(k)] = d.line;
            }
            if (d.at[k] > hi[k]) {
                hi[k] = d.at[k];
                hi_line[static_cast<std::size_t>(k)] = d.line;
            }
        }
    }
    for (int k = 0; k < 3; ++k) {
        const auto K = static_cast<std::size_t>(k);
        double zero = 0;
        if (o.work_zero_in) {
            zero = (*o.work_zero_in)[k];
        } else if (lo[k] < -kDustIn || hi[k] > kCounterMaxIn + kDustIn) {
            zero = o.margin_in - lo[k];
        }
        deck.work_zero_in[k] = zero;
        if (lo[k] + zero < -kDustIn || hi[k] + zero > kCounterMaxIn + 0.0005) {
            const bool low = lo[k] + zero < -kDustIn;
            throw JobError(fmt::format(
                "{}:{}: {} reaches {:.4f} in, {:.4f} in on the counters, which hold 0 to 9.999 in "
                "(the program spans {:.4f} to {:.4f} in; work zero {:.4f} in{})",
                program.file, low ? lo_line[K] : hi_line[K], kAxisLetters[K], low ? lo[k] : hi[k],
                (low ? lo[k] : hi[k]) + zero, lo[k], hi[k], zero,
                o.work_zero_in ? ", given by --work-zero" : ""));
        }
    }
}

// A design point where the path turns sharper than the corner limit is a corner: the card
// arriving there runs at the lowest speed (EP 0636958), over its last kCornerApproachIn.
std::vector<char> corners_of(const std::vector<Design>& design, const GcodeJobOptions& o) {
    const double limit = o.corner_limit_deg * std::numbers::pi / 180;
    std::vector<char> corner_at(design.size(), 0);
    for (std::size_t i = 1; o.corner_slowdown && i + 1 < design.size(); ++i) {
        const Vector3d d1 = design[i].at - design[i - 1].at;
        std::size_t j = i + 1;
        while (j + 1 < design.size() && (design[j].at - design[i].at).norm() < 1e-12) {
            ++j;
        }
        const Vector3d d2 = design[j].at - design[i].at;
        if (d1.norm() > 1e-12 && d2.norm() > 1e-12) {
            const double turn =
                std::acos(std::clamp(d1.normalized().dot(d2.normalized()), -1.0, 1.0));
            corner_at[i] = turn > limit ? 1 : 0;
        }
    }
    return corner_at;
}

// The stations the cards go to: each chord cut so its staircase stays within a third of
// the tolerance, rounded to the thousandth.
std::vector<Station> card_stations(const std::vector<Design>& design,
                                   const std::vector<char>& corner_at, const GcodeProgram& program,
                                   const GcodeJobOptions& o, double third, const GcodeDeck& deck) {
    std::vector<Station> stations;
    const Eigen::Vector3i reference = Eigen::Vector3i::Zero();
    stations.push_back({reference, false, design.front().spindle});
    stations.push_back({thousandths(deck.work_zero_in), false, design.front().spindle});
    for (std::size_t i = 1; i < design.size(); ++i) {
        const Vector3d p = design[i - 1].at + deck.work_zero_in;
        const Vector3d q = design[i].at + deck.work_zero_in;
        const Vector3d d = q - p;
        if (d.norm() < 1e-12) {
            continue;
        }
        const auto order = axis_order(thousandths(p), thousandths(q));
        const double offset = staircase_offset(p, q, order);
        const std::int64_t n =
            std::max(std::int64_t{1}, static_cast<std::int64_t>(std::ceil(offset / third)));
        std::vector<Vector3d> ats;
        for (std::int64_t s = 1; s <= n; ++s) {
            ats.push_back(s == n ? q : Vector3d(p + d * (static_cast<double>(s) / n)));
        }
        const Vector3d before = ats.size() == 1 ? p : ats[ats.size() - 2];
        if (corner_at[i] != 0 && (q - before).norm() > 2 * kCornerApproachIn) {
            ats.insert(ats.end() - 1, Vector3d(q - kCornerApproachIn * d.normalized()));
        }
        for (std::size_t s = 0; s < ats.size(); ++s) {
            const Eigen::Vector3i t = thousandths(ats[s]);
            if (t == stations.back().at) {
                continue;
            }
            stations.push_back({t, s + 1 == ats.size() && corner_at[i] != 0, design[i].spindle});
            // A card from each station to the next; none to the work zero when it is the
            // reference zero. Refused at the first card past the limit, before the rest.
            const bool at_reference = stations[0].at == stations[1].at;
            const auto cards = static_cast<std::int64_t>(stations.size()) - (at_reference ? 2 : 1);
            if (cards > kMaxDeckCards) {
                throw JobError(fmt::format(
                    "{}:{}: more than {} cards at a tolerance of {} in, the most a deck can "
                    "number (card numbers are four digits, columns 77-80): give a larger "
                    "--tolerance, or cut the program in two",
                    program.file, design[i].line, count_text(kMaxDeckCards), o.tolerance_in));
            }
        }
    }
    return stations;
}

// The cards, the stations the deck records, and the farthest the planned path strays from
// the design.
void punch_cards(const std::vector<Station>& stations, const axes::MachineProfile& profile,
                 GcodeDeck& deck) {
    for (std::size_t i = 1; i < stations.size(); ++i) {
        const Station& a = stations[i - 1];
        const Station& b = stations[i];
        if (a.at == b.at) {
            continue; // the work zero is the reference zero
        }
        const bool corner = b.corner;
        deck.corner_cards += corner ? 1 : 0;
        std::vector<int> order;
        if (i == 1) {
            for (int k : {2, 0, 1}) {
                if (a.at[k] != b.at[k]) {
                    order.push_back(k);
                }
            }
        } else {
            order = axis_order(a.at, b.at);
        }
        deck.cards.push_back(card(static_cast<int>(deck.cards.size()) + 1, a.at, b.at, order,
                                  corner, b.spindle, profile));
    }
    const bool at_reference = stations[0].at == stations[1].at;
    deck.approach_cards = at_reference ? 0 : 1;
    for (std::size_t i = 0; i < stations.size(); ++i) {
        if (i != 1 || !at_reference) {
            deck.stations.push_back(stations[i].at.cast<double>() / 1000.0);
        }
    }

    // The farthest the planned path strays from the design: chords and staircases.
    for (std::size_t i = 2; i < stations.size(); ++i) {
        const Vector3d p = stations[i - 1].at.cast<double>() / 1000.0;
        const Vector3d q = stations[i].at.cast<double>() / 1000.0;
        deck.planned_deviation_in =
            std::max(deck.planned_deviation_in,
                     staircase_offset(p, q, axis_order(stations[i - 1].at, stations[i].at)));
    }
}

} // namespace

GcodeDeck make_gcode_deck(const GcodeProgram& program, const GcodeJobOptions& o,
                          const axes::MachineProfile& profile) {
    if (!(o.tolerance_in >= kLeastGcodeToleranceIn) || !std::isfinite(o.tolerance_in)) {
        throw JobError(fmt::format("tolerance {} in: at least {} in (the counters' thousandth "
                                   "and the machine's half-thousandth stop take 0.001 in of it)",
                                   o.tolerance_in, kLeastGcodeToleranceIn));
    }
    if (program.moves.empty()) {
        throw JobError(fmt::format("{}: no moves: nothing to punch", program.file));
    }
    const double third = o.tolerance_in / 3;
    GcodeDeck deck;
    const std::vector<Design> design = design_of(program, third, deck);
    place_work_zero(design, program, o, deck);
    const std::vector<char> corner_at = corners_of(design, o);
    punch_cards(card_stations(design, corner_at, program, o, third, deck), profile, deck);
    return deck;
}

} // namespace parsons::decks
