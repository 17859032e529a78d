// The proof of the cut: what surface did the machine really leave on the work piece?
//
// The real machine (US 2,820,187, Fig. 4) moves the cutter 184 from station to station in short
// straight runs, "in stepped relation to one another", and every cut is made within the radial
// reach of the one before, so the edge 182 comes out as a row of scallops (Fig. 6, "of the order
// of .002 inch high") that were filed off by hand (Fig. 7). Here we take the positions the
// emulated axes really went through (one point per 0.001-inch impulse: a staircase, table then
// cross slide) and measure, against the design contour, how much material was left standing
// and where the cutter went too deep.
//
// The setting is the side view (2-D, inches, x to the right, y up): the cutter is a disk of
// radius R, and it removes every point within R of the path of its centre. For each design point
// p with unit normal n (pointing out of the material, toward the cutter) we look along the line
// p + t n for the surface the cutter left, and call the t where we meet it the deviation:
//
//            .---.  .---.
//          /      \/      \          two cutter positions (centres o, radius R) overlapping:
//         |   o   /\   o   |         each cut within the reach of the one before
//          \     /  \     /
//   ........'---'-^--'---'........   design contour, material below; at t = 0 under each
//                 cusp               centre, and the cusp between two cuts stands t > 0 above
//                                    the design (a scallop, Fig. 6)
//
// t > 0: leftover, the material between p and p + t n was not cut. t < 0: gouge, the cut
// reaches below p, down to p + t n.
//
// Exactly: the swept region is the union of a disk of radius R at every vertex of the path and a
// rectangle of half-width R along every straight run. The line p + t n meets each of them in one
// interval of t, computed in closed form (no bisection); the union of those intervals is the cut
// along that line. Runs are found through a uniform grid of cells R/4 on a side, and most points
// need only look at t in [-R, R/4], so 5,000 design points against a recording of 10^5 impulses
// (6 x 10^4 runs, five passes) take about a tenth of a second.
//
// Emulation note: the cutter is a disk in the plane of the section; the end of a real end mill,
// the cutter's run-out and the spring of the work are not modelled.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace parsons::decks {

// The surface the deck was computed for: dense points in order along it, each with the unit
// normal pointing away from the material (toward where the cutter may be).
struct DesignContour {
    std::vector<Eigen::Vector2d> points;
    std::vector<Eigen::Vector2d> normals;
};

struct CutProof {
    // Deepest cut into the design material (the cutter came closer than R), in inches, >= 0.
    double max_gouge_in = 0;
    // Most material left standing above the design, in inches, >= 0.
    double max_leftover_in = 0;
    // Largest scallop: the highest cusp of material between two cuts. A cusp is a local maximum
    // of the deviation along the design, inside one machined stretch, with strictly lower
    // deviation on both sides (so leftover that only grows toward the end of a cut, where the
    // cutter ran out, is leftover but not a scallop). 0 when there is no such cusp.
    double max_scallop_in = 0;
    // Per design point: + leftover, - gouge, 0 = exactly on the design; NaN = not machined.
    std::vector<double> deviation_in;
    // The surface the cutter left, one point per design point: point + deviation * normal
    // (NaN where the point was not machined).
    std::vector<Eigen::Vector2d> cut_contour;
    // How many design points were machined (deviation not NaN).
    std::size_t machined_points = 0;
};

// Measures the cut of `path` (cutter centres in order; the real positions of the axes) with a
// cutter of `radius_in` against `design`.
//
// A design point is "not machined" (deviation NaN, left out of the maxima) when it lies farther
// than `reach_in` from the path, or when its normal line meets no cut within the search window
// t in [-R, reach_in + R]. A gouge is measured inside the material: it ends where the line
// p - s n leaves the material through the design contour again (a cut right through a thin
// trailing edge is as deep as the edge is thick), and at R at most (the window's floor). The
// contour is taken as one polyline in the order given.
//
// The path is first merged into straight runs (simplify_path with 1e-9 in), so a raw
// impulse-by-impulse recording may be passed as it is. Throws std::invalid_argument when the
// radius or reach is not positive or the design's points and normals differ in number.
CutProof prove_cut(const std::vector<Eigen::Vector2d>& path, double radius_in,
                   const DesignContour& design, double reach_in);

// The path with straight runs merged (Douglas-Peucker): an interior point is dropped when it lies
// within `tolerance_in` of the segment joining the points kept on either side. The first and last
// points are always kept; a corner of the staircase (0.001 in) is kept as long as the tolerance
// is below the machine's step, e.g. 1e-6 in. Reversals along a line are kept (the distance is to
// the segment, not to its line), so the swept region never shrinks by more than the tolerance.
std::vector<Eigen::Vector2d> simplify_path(const std::vector<Eigen::Vector2d>& path,
                                           double tolerance_in);

// The largest scallop of a deviation profile (CutProof::max_scallop_in): its highest cusp, a
// local maximum with strictly lower deviation on both sides inside one machined stretch (NaN
// ends a stretch; equal neighbours form one plateau); 0 when there is none.
double max_cusp(const std::vector<double>& deviation_in);

} // namespace parsons::decks
