// Reading a G-code (RS-274) program: the moves it makes, for `parsons gen gcode` to turn into
// a deck the 1952 machine can run (decks/gcode_job.hpp).
//
// What is read (docs/gcode.md): G0 and G1 lines, G2 and G3 arcs in the XY plane (centre by I J,
// incremental, or radius by R; a Z word makes a helix), G20 and G21 units, G90 and G91
// distances, X Y Z, line numbers N, comments in parentheses and after ';', '%' lines, and M2 or
// M30 ending the program. M3, M4 and M5 set the card's spindle column (forward, reverse, off).
// The modal words that state what parsons assumes are read and change nothing: G17, G40, G49,
// G54, G61, G80, G94, G91.1.
//
// Words a post-processor writes for a machine the 1952 one is not are ignored, each kind told
// once as a warning (its first line, and how many later lines hold one): F (the deck's speeds
// come from the slow-down rule), S, M7 M8 M9, a program number O1234 or O<name>, the tool T and
// M6 (one tool; a second one is refused), G43 with its H, G64 with its P and Q, and G28 after
// the last move. Under GcodeReading::strict each of them is refused instead.
//
// Everything else is refused with the file, the line and the word: cutter compensation, a
// second tool, dwells, canned cycles, other planes, rotary axes, parameters, expressions and
// subroutines, a move after G28, a move before the units are given, an arc whose end is not
// on its circle. A refusal is a DeckError (exit 2).
#pragma once

#include <Eigen/Core>

#include <string>
#include <string_view>
#include <vector>

namespace parsons::decks {

enum class GcodeMotion { rapid, linear, arc_cw, arc_ccw };

struct GcodeMove {
    std::int64_t line = 0; // 1-based line of the program
    GcodeMotion motion = GcodeMotion::linear;
    Eigen::Vector3d from = Eigen::Vector3d::Zero(); // inches, the program's own frame
    Eigen::Vector3d to = Eigen::Vector3d::Zero();
    Eigen::Vector2d centre = Eigen::Vector2d::Zero(); // arcs: the centre in XY
    double sweep_rad = 0; // arcs: the signed angle swept, + counter-clockwise seen from +Z
    int spindle = 0;      // 0 off (M5, the start), 1 forward (M3), 2 reverse (M4): column 165
};

struct GcodeProgram {
    std::string file;
    std::vector<GcodeMove> moves;
    std::vector<std::string> ignored;  // "F (first on line 3): ..." once per kind, in order
    std::vector<std::string> warnings; // "FILE:LINE: WORD ignored: why", the same kinds
    std::int64_t lines = 0;
    bool millimetres = false; // the units of the first move (inches or millimetres)
};

struct GcodeReading {
    bool strict = false; // refuse the words that would be ignored (gen gcode --strict)
};

// Throws cardreader::DeckError naming the file, the line and the word.
GcodeProgram read_gcode(std::string_view text, const std::string& file,
                        const GcodeReading& how = {});

// The point of a move at fraction f (0..1) of it: along the line, or round the arc (a helix
// rises linearly with the angle).
Eigen::Vector3d point_on(const GcodeMove& move, double f);

} // namespace parsons::decks
