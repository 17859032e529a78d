// The 2-D template of Fig. 4: stations along the chord, the cutter-centre ordinate on the cross
// slide, the table carrying the work along the chord; one card per station.
//
// The cutter (a disk of radius R in this side view) must touch the surface at each station, so
// its centre lies on the surface normal at distance R: outward for a male contour, and for the
// patent's female template on the other side (centre ordinate = work ordinate - R cos theta,
// centre abscissa = work abscissa + R sin theta). Between stations the machine can only move
// one screw at a time at a fixed speed, so each card is a staircase of two moves; the corner of
// the staircase is always put on the cutter's side of the line between the two centres, so
// the first move never runs into the material:
//
//        cutter side                     c(i+1)           corner A = (x(i), y(i+1)):
//          A ------------ c(i+1)           |                cross slide first, then table
//          |                               |              corner B = (x(i+1), y(i)):
//        c(i)      material         c(i) --B                table first, then cross slide
//
// The idle axes (vertical, swivel, tilt) are punched at sequence positions 1-3 and stop at
// once (check 0); the first move is at position 4 and the cut, as the patent says, is made by
// the last axis of the sequence, at 5.
#pragma once

#include "axes/machine_profile.hpp"
#include "cardreader/orders.hpp"
#include "decks/airfoil.hpp"

#include <vector>

namespace parsons::decks {

enum class Surface { upper, lower, both };
enum class Spacing { uniform, cosine };

struct TemplateOptions {
    double chord_in = 6.0;
    double cutter_radius_in = 0.25;
    Surface surface = Surface::upper;
    bool female = false;
    int stations = 60; // by count (per surface), when scallop_in is 0
    Spacing spacing = Spacing::cosine;
    double scallop_in = 0; // > 0: choose stations so the planned scallop stays under this
    bool corner_slowdown = true;
    double corner_limit_deg = 30; // a turn sharper than this is approached at the lowest speed
    double margin_in = 0.5;       // clearance around the job inside the counters' range
};

struct Station {
    Side side = Side::upper;
    double u = 0;                  // chord station (airfoil.hpp)
    Eigen::Vector2d work;          // point on the surface, inches from the leading edge
    Eigen::Vector2d centre;        // cutter centre, inches from the leading edge
    Eigen::Vector2d toward_cutter; // unit normal from the surface toward the cutter
};

struct TemplateDeck {
    std::vector<Station> stations;
    std::vector<cardreader::CardOrders> cards;
    // Machine position (table, cross) of the work's origin, the leading edge: the counters
    // read work + zero. Chosen so the whole job lies margin_in inside 0 .. 9.999 in.
    Eigen::Vector2d work_zero_in;
    double planned_leftover_in = 0; // largest scallop the stations leave (before quantising)
    double planned_gouge_in = 0;    // deepest the staircase traverses dip into the design
    int corner_cards = 0;           // cards slowed for a corner
};

class JobError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Throws JobError when the options cannot make a deck (part too big for the counters,
// female on both surfaces, more cards than a deck can number, a chord or cutter under the
// least the machine can cut: decks/deck_limits.hpp, ...) and PlanError when the profile cannot
// stop exactly. A count of stations past the deck's limit is refused before any is computed.
TemplateDeck make_template_deck(const Airfoil& airfoil, const TemplateOptions& options,
                                const axes::MachineProfile& profile);

// The design surfaces the job cuts, densely sampled, in machine coordinates (inches as the
// counters read them), each point with its unit normal toward the cutter.
struct DesignSamples {
    std::vector<Eigen::Vector2d> points;
    std::vector<Eigen::Vector2d> toward_cutter;
};
DesignSamples design_samples(const Airfoil& airfoil, const TemplateOptions& options,
                             const Eigen::Vector2d& work_zero_in, int per_surface = 1500);

} // namespace parsons::decks
