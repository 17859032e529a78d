// A picture of the proof of the cut, the kind a teacher would put beside Fig. 4 and Fig. 6 of the
// patent: the design contour (thin black), the path of the cutter centre (thin blue), a few
// cutter circles drawn faintly along it, the surface the cutter left with its deviation from the
// design exaggerated (red; the patent's Fig. 6 also shows "the scallops in exaggerated
// condition"), and a colour band along the design (blue = gouge, white = on the design, red =
// leftover, grey = not machined) with a legend in thousandths of an inch and the worst gouge,
// leftover and scallop.
//
// The view is the design with room for the cutter around it; the part of the path outside it
// (approach from the reference zero, say) is clipped. Equal scales on x and y, ticks in inches.
#pragma once

#include "decks/cut_proof.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace parsons::decks {

// An SVG document about 1200 px wide. `exaggerate` multiplies the deviation of the red line.
std::string cut_svg(const CutProof& proof, const std::vector<Eigen::Vector2d>& path,
                    const DesignContour& design, double radius_in, const std::string& title,
                    double exaggerate = 50);

} // namespace parsons::decks
