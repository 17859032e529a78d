// The tapered wing section of Fig. 5: "not only will the cutter itself be adjusted between
// operating steps but the table 14 and sine plate 16 will be adjusted between each step in
// order to produce the taper … during table travel it will be moved parallel to its long
// dimension … the whole upper surface … will be scalloped" (col. 10).
//
// The wing is the ruled surface between a root section (chord c, at span 0) and a tip section
// (chord c * taper, its leading edge swept back by span * tan(sweep)). Each chordwise station u
// is one straight cut along the span: the line through the cutter centres that touch the root
// and the tip sections at u, laid off by R along the surface's own (3-D) normal. The fixture
// turns the work so that line lies along the table's travel: the sine plate tilts it about
// hinge 19 (screws 24: sin(tilt) = travel / arm) and the bottom member swivels it about its
// pivot (screw 26: tan(swivel) = travel / arm); the cross slide and the vertical slide then set
// the line's place, and the table traverses the span — the cut, last in the sequence.
//
// Two cards a station: (1) retract the cutter above everything, turn the fixture, set the
// cross slide, bring the table to the start (beyond the root); (2) plunge the vertical slide to
// the line's height and traverse the table past the tip.
// Emulation note: the work is clamped with its root leading edge on the swivel pivot and the
// hinge line (the rotations are about axes through the work's origin); the cutter is a ball of
// radius R, so the swept region around each cut is a cylinder.
#pragma once

#include "axes/machine_profile.hpp"
#include "cardreader/orders.hpp"
#include "decks/airfoil.hpp"
#include "decks/template_job.hpp"

#include <Eigen/Core>

#include <array>
#include <vector>

namespace parsons::decks {

struct WingOptions {
    double root_chord_in = 4.0;
    double span_in = 5.0;
    double taper = 0.8;     // tip chord / root chord
    double sweep_deg = 5.0; // of the leading edge
    double cutter_radius_in = 0.25;
    int stations = 40;
    Spacing spacing = Spacing::cosine;
    double scallop_in = 0; // > 0: as many stations as keep the planned scallop under this
    double margin_in = 0.5;
};

struct WingStation {
    double u = 0;
    Eigen::Vector3d root_centre; // work frame: x chordwise, y spanwise, z up; inches
    Eigen::Vector3d tip_centre;
    double tilt_rad = 0;
    double swivel_rad = 0;
};

struct WingDeck {
    std::vector<WingStation> stations;
    std::vector<cardreader::CardOrders> cards;
    // Machine = rotated work + zero: cross = x + zero.x, table = y + zero.y, vertical = z + zero.z.
    Eigen::Vector3d zero;
    double planned_leftover_in = 0; // in the root and tip sections, before quantising
    double planned_gouge_in = 0;
};

// Throws JobError when the options cannot make a deck: sizes under the least the machine can
// cut or more cards than a deck can number (decks/deck_limits.hpp; refused before any station
// is computed), a job too big for the counters, a fixture screw past its travel.
WingDeck make_wing_deck(const Airfoil& airfoil, const WingOptions& options,
                        const axes::MachineProfile& profile);

// The five real axis positions turned back into the work frame (where the cutter centre is,
// relative to the wing), using the real swivel and tilt angles.
Eigen::Vector3d work_point(const std::array<double, 5>& real, const Eigen::Vector3d& zero,
                           const axes::MachineProfile& profile);

struct SectionProof {
    double max_gouge_in = 0;
    double max_leftover_in = 0;
    std::vector<Eigen::Vector2d> design;  // (x, z) of the section, inches
    std::vector<Eigen::Vector2d> normals; // outward, in the section plane
    std::vector<double> deviation_in;     // + leftover, - gouge
};
struct WingProof {
    SectionProof root;
    SectionProof tip;
};

// The cut in the root and tip sections: for each design point, its distance to the path the
// cutter centre really took (in the work frame) less R.
WingProof prove_wing(const std::vector<Eigen::Vector3d>& work_path, const Airfoil& airfoil,
                     const WingOptions& options, int points_per_section = 400);

// The root and tip sections, one above the other, drawn as decks/cut_svg.hpp draws a template:
// the design, where the cutter-centre path crossed the section plane, and the deviations.
std::string wing_cut_svg(const WingProof& proof, const std::vector<Eigen::Vector3d>& work_path,
                         const WingOptions& options, const std::string& title);

} // namespace parsons::decks
