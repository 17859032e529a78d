// A G-code program as a deck the 1952 machine runs (`parsons gen gcode`; docs/gcode.md).
//
// X is the table, Y the cross slide, Z the vertical slide; the fixture (swivel, tilt) stands
// level. The program's path is cut into stations and one card goes from each station to the
// next, as the template job's do: the axes that move do so one after another (the sequence
// pattern), so between two stations the cutter follows a staircase whose corners stand off the
// straight line. The stations are placed so that neither the chords of an arc nor the
// staircase corners stray from the program's path by more than a third of the tolerance each;
// the last third is left to the counters' thousandth and the machine's half-thousandth stop.
//
// Each axis's start speed and slow-downs come from the move planner (decks/move_planner.hpp),
// and where the program's path turns sharper than corner_limit_deg at a station the card going
// to it runs at the lowest speed (EP 0636958's corner slow-down). The program's F words choose
// nothing: the 1952 machine's speeds are its speed switches'.
//
// Order of the axes on a card: going down, the table and the cross slide first and the
// vertical slide last; going up (or level), the vertical slide first. The first card brings the
// machine from the reference zero to the program's origin (the work zero): vertical first, then
// table, then cross slide.
#pragma once

#include "axes/machine_profile.hpp"
#include "cardreader/orders.hpp"
#include "decks/gcode_program.hpp"

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace parsons::decks {

struct GcodeJobOptions {
    double tolerance_in = 0.005; // the path as cut stays this close to the program's
    std::optional<Eigen::Vector3d> work_zero_in; // none: automatic (see make_gcode_deck)
    double margin_in = 0.5;
    bool corner_slowdown = true;
    double corner_limit_deg = 30;
};

// The least tolerance: the counters' thousandth and the half-thousandth stop take 0.001 in of
// the budget, which is a third of this.
inline constexpr double kLeastGcodeToleranceIn = 0.003;

struct GcodeDeck {
    std::vector<cardreader::CardOrders> cards;
    // Machine position (table, cross, vertical) of the program's origin: the counters read
    // program + zero. Automatic: an axis whose every position (and the origin) lies within
    // 0 .. 9.999 in is not moved; any other is moved so its lowest point lies margin_in inside.
    Eigen::Vector3d work_zero_in = Eigen::Vector3d::Zero();
    // Every station, machine coordinates, inches (thousandths exactly); stations[0] is the
    // reference zero and stations[1] the work zero, reached by the first card.
    std::vector<Eigen::Vector3d> stations;
    int approach_cards = 1;          // cards before the program's first move
    int corner_cards = 0;            // cards slowed for a corner
    std::int64_t arcs = 0;           // G2/G3 moves
    std::int64_t lines = 0;          // G0/G1 moves
    double planned_deviation_in = 0; // the farthest a chord or staircase corner strays
};

// Throws JobError when the program does not fit the counters or makes too many cards, and
// PlanError when the profile cannot stop exactly.
GcodeDeck make_gcode_deck(const GcodeProgram& program, const GcodeJobOptions& options,
                          const axes::MachineProfile& profile);

} // namespace parsons::decks
