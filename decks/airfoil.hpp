// Airfoil sources: the shape the deck is computed from, in chord units (chord = 1, x from the
// leading edge to the trailing edge, y up).
//
// Two sources: the NACA 4-digit equations (thickness laid off perpendicular to the camber
// line; open trailing edge a4 = 0.1015 by default, closed 0.1036 as an option), and coordinate
// files in the Selig and Lednicer .dat layouts (see decks/airfoils/SOURCES.md), fitted
// with a smooth curve so that the surface normal is defined everywhere.
//
// Every source answers the same question: the point and unit tangent of the upper or lower
// surface at chord station u in [0, 1] (u = 0 at the leading edge, 1 at the trailing edge).
// For NACA sections u is the camber-line abscissa (the surface point's own x differs from it
// by -/+ y_t sin(theta)); for coordinate files u is the surface point's x.
#pragma once

#include <Eigen/Core>

#include <memory>
#include <string>
#include <string_view>

namespace parsons::decks {

enum class Side { upper, lower };

struct SurfaceSample {
    Eigen::Vector2d point;   // on the surface, chord units
    Eigen::Vector2d tangent; // unit, pointing from the leading edge toward the trailing edge
};

class Airfoil {
public:
    virtual ~Airfoil() = default;
    virtual std::string name() const = 0;
    virtual SurfaceSample sample(Side side, double u) const = 0;
};

// NACA 4-digit, e.g. "2412". Throws std::invalid_argument for anything but four digits with a
// thickness over zero.
std::unique_ptr<Airfoil> naca4(const std::string& digits, bool closed_trailing_edge = false);

// A Selig or Lednicer coordinate file (layout detected; CRLF accepted; scaled to chord 1 if
// tabulated in percent). Throws cardreader::DeckError naming the file and line.
std::unique_ptr<Airfoil> read_dat(const std::string& path);
// The same from the file's bytes, already read; `path` only names the file in messages.
std::unique_ptr<Airfoil> read_dat_text(std::string_view bytes, const std::string& path);

} // namespace parsons::decks
