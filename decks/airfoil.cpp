// Airfoil sources: the NACA 4-digit equations and Selig/Lednicer coordinate files.
//
// The shop that punched a Parsons deck worked from a table of ordinates (the NACA report
// tables, or a customer's drawing) and interpolated between stations by hand; here the same
// two kinds of source answer "point and unit tangent of a surface at chord station u".
//
// NACA 4-digit MPXX (Abbott & von Doenhoff, "Theory of Wing Sections", section 6.4):
//
//        y ^     upper: (x - y_t sin(theta), y_c + y_t cos(theta))
//          |    .-''''''-.._
//          |  .'  camber y_c  ''--..__
//       LE +-(-----------------------------)---> x     theta = atan(dy_c/dx)
//          |  '.                 __..--''   TE
//          |    '-......--''''''     lower: (x + y_t sin(theta), y_c - y_t cos(theta))
//
// u is the camber abscissa x. The tangent is the exact derivative of the surface point with
// respect to u, multiplied by sqrt(u) before normalising: y_t ~ sqrt(u) makes d/du infinite at
// the leading edge, while sqrt(u) d/du is finite there and has the same direction for u > 0,
// so u = 0 needs no special branch (its tangent is the limit, normal to the camber line).
//
// Coordinate files are read into one Selig loop (TE -> upper -> LE -> lower -> TE) and fitted
// with ONE parametric cubic spline x(s), y(s) in cumulative chord length s, natural end
// conditions (zero second derivative) at the two trailing-edge ends, a tridiagonal solve. The
// loop is then cut at the leading edge, the least x of the fitted curve (which is rarely the
// file point of least x), into two surfaces running LE -> TE; the file's points are knots.
// Emulation note: the brief asked for a spline per surface, split at the file point of least
// x. Fitting the whole loop keeps the curve C2 through the nose instead of forcing zero
// curvature where curvature is largest: on naca0012.dat the nose error between stations is
// 7.5e-5 chord for the loop fit against 1.4e-3 for two natural per-surface fits, which also
// leave a 10 degree kink at the LE. Cutting at the curve's own least x keeps sample(u)
// continuous at the LE (see cut_at_leading_edge).
// sample(side, u) finds the segment whose knot x values bracket u (binary search), then solves
// x(s) = u in that segment by Newton steps kept inside the bracket (bisection fallback): no
// allocation, O(log n).
#include "decks/airfoil.hpp"

#include "cardreader/deck_error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <vector>

namespace parsons::decks {
namespace {

using cardreader::DeckError;

// ---------------------------------------------------------------------------------------------
// NACA 4-digit

class Naca4 final : public Airfoil {
public:
    Naca4(const std::string& digits, bool closed_te)
        : name_("NACA " + digits), m_((digits[0] - '0') / 100.0), p_((digits[1] - '0') / 10.0),
          t_(((digits[2] - '0') * 10 + (digits[3] - '0')) / 100.0),
          a4_(closed_te ? 0.1036 : 0.1015) {}

    std::string name() const override { return name_; }

    SurfaceSample sample(Side side, double u) const override {
        const double x = u > 0 ? std::min(u, 1.0) : 0.0; // NaN too: the leading edge
        const double rx = std::sqrt(x);
        // Camber line, its slope and its curvature term (symmetric when m or p is zero). At
        // x = p the second derivative jumps; the aft branch is used there.
        double yc = 0, dyc = 0, d2yc = 0;
        if (m_ > 0 && p_ > 0) {
            const double k = x < p_ ? m_ / (p_ * p_) : m_ / ((1 - p_) * (1 - p_));
            yc = x < p_ ? k * (2 * p_ * x - x * x) : k * ((1 - 2 * p_) + 2 * p_ * x - x * x);
            dyc = 2 * k * (p_ - x);
            d2yc = -2 * k;
        }
        const double yt =
            5 * t_ * (0.2969 * rx + x * (-0.1260 + x * (-0.3516 + x * (0.2843 - a4_ * x))));
        // sqrt(x) * dy_t/dx, finite at x = 0.
        const double rx_dyt =
            5 * t_ *
            (0.2969 / 2 + rx * (-0.1260 + x * (-2 * 0.3516 + x * (3 * 0.2843 - 4 * a4_ * x))));
        const double c = 1 / std::sqrt(1 + dyc * dyc); // cos(theta)
        const double s = dyc * c;                      // sin(theta)
        const double dtheta = d2yc / (1 + dyc * dyc);
        const double sg = side == Side::upper ? 1.0 : -1.0;

        SurfaceSample out;
        out.point = {x - sg * yt * s, yc + sg * yt * c};
        // sqrt(x) times the derivative of the point with respect to x.
        const Eigen::Vector2d d{rx - sg * (rx_dyt * s + rx * yt * c * dtheta),
                                rx * dyc + sg * (rx_dyt * c - rx * yt * s * dtheta)};
        out.tangent = d.normalized();
        return out;
    }

private:
    std::string name_;
    double m_, p_, t_, a4_; // max camber, its position, thickness (chords); x^4 coefficient
};

// ---------------------------------------------------------------------------------------------
// Cubic spline of one surface, LE -> TE

struct Knot {
    double s;          // chord length along the curve
    Eigen::Vector2d p; // the point
    Eigen::Vector2d m; // d2p/ds2, linear in s between knots
};

// Point and first derivative at s of the cubic between knots a and b (a.s < b.s).
void eval_segment(const Knot& a, const Knot& b, double s, Eigen::Vector2d& p, Eigen::Vector2d& dp) {
    const double h = b.s - a.s;
    const double wa = (b.s - s) / h;
    const double wb = 1 - wa;
    p = wa * a.p + wb * b.p + ((wa * wa * wa - wa) * a.m + (wb * wb * wb - wb) * b.m) * (h * h / 6);
    dp = (b.p - a.p) / h - (3 * wa * wa - 1) * h / 6 * a.m + (3 * wb * wb - 1) * h / 6 * b.m;
}

// One surface of the fitted loop, knots in LE -> TE order with s increasing (the second
// derivatives do not change when the loop's parameter is reversed).
class SplineSurface {
public:
    explicit SplineSurface(std::vector<Knot> knots) : k_(std::move(knots)) {
        for (const auto& k : k_) {
            x_.push_back(k.p.x());
        }
    }

    SurfaceSample at_x(double u) const {
        const auto n = x_.size();
        if (!(u > x_.front())) { // also catches NaN: the leading edge
            return at(0, k_[0].s);
        }
        if (u >= x_.back()) {
            return at(n - 2, k_[n - 1].s);
        }
        const auto i =
            static_cast<std::size_t>(std::upper_bound(x_.begin(), x_.end(), u) - x_.begin() - 1);
        if (x_[i] == u) { // a knot: its own point exactly
            return at(i, k_[i].s);
        }
        return at(i, solve_x(i, u));
    }

private:
    SurfaceSample at(std::size_t i, double s) const {
        SurfaceSample out;
        Eigen::Vector2d d;
        eval_segment(k_[i], k_[i + 1], s, out.point, d);
        const double len = d.norm();
        out.tangent = len > 0 && std::isfinite(len) ? Eigen::Vector2d(d / len)
                                                    : (k_[i + 1].p - k_[i].p).normalized();
        return out;
    }

    // s in segment i with x(s) = u, given x_[i] < u < x_[i + 1]: Newton steps kept inside a
    // bracket with x(lo) <= u <= x(hi), bisection when a step leaves it, so a root is found
    // even where the cubic x(s) is not monotone.
    double solve_x(std::size_t i, double u) const {
        double lo = k_[i].s;
        double hi = k_[i + 1].s;
        double s = lo + (hi - lo) * (u - x_[i]) / (x_[i + 1] - x_[i]);
        Eigen::Vector2d p, d;
        for (int iter = 0; iter < 100 && hi - lo > 1e-15 * (1 + std::abs(hi)); ++iter) {
            eval_segment(k_[i], k_[i + 1], s, p, d);
            const double f = p.x() - u;
            if (f == 0) {
                return s;
            }
            (f < 0 ? lo : hi) = s;
            const double next = d.x() > 0 ? s - f / d.x() : lo - 1;
            const bool converged = std::abs(next - s) < 1e-15 * (1 + std::abs(s));
            s = next > lo && next < hi ? next : 0.5 * (lo + hi);
            if (converged) {
                break;
            }
        }
        return s;
    }

    std::vector<Knot> k_;
    std::vector<double> x_; // knot x, non-decreasing (binary search)
};

// The natural cubic spline through the loop's points in cumulative chord length: the second
// derivatives solve a symmetric, diagonally dominant tridiagonal system (Thomas algorithm),
// with zero second derivative at the two trailing-edge ends.
std::vector<Knot> fit_loop(const std::vector<Eigen::Vector2d>& q) {
    const std::size_t n = q.size();
    std::vector<Knot> knots(n, Knot{0.0, {0, 0}, {0, 0}});
    for (std::size_t k = 0; k < n; ++k) {
        knots[k].p = q[k];
        knots[k].s = k == 0 ? 0.0 : knots[k - 1].s + (q[k] - q[k - 1]).norm();
    }
    std::vector<double> diag(n, 1.0), upper(n, 0.0);
    std::vector<Eigen::Vector2d> rhs(n, Eigen::Vector2d::Zero());
    for (std::size_t k = 1; k + 1 < n; ++k) {
        const double h0 = knots[k].s - knots[k - 1].s;
        const double h1 = knots[k + 1].s - knots[k].s;
        diag[k] = (h0 + h1) / 3;
        upper[k] = h1 / 6;
        rhs[k] = (q[k + 1] - q[k]) / h1 - (q[k] - q[k - 1]) / h0;
        if (k > 1) { // eliminate the sub-diagonal h0 / 6
            const double w = (h0 / 6) / diag[k - 1];
            diag[k] -= w * upper[k - 1];
            rhs[k] -= w * rhs[k - 1];
        }
    }
    for (std::size_t k = n - 2; k >= 1 && n >= 3; --k) {
        knots[k].m = (rhs[k] - upper[k] * knots[k + 1].m) / diag[k];
    }
    return knots;
}

// The two surfaces of the fitted loop, cut at the leading edge: the least x of the curve, not
// of the file. Unless the file's point of least x (knot k) is also the curve's (as for a
// symmetric section), the nose lies inside segment k-1 or k, where dx/ds = 0; a quadratic
// in t = (s - s_j) / h:
//
//     dx/ds = [dx/h - h M_j / 3 - h M_j+1 / 6] + [h M_j] t + [h (M_j+1 - M_j) / 2] t^2
//
// The cut inserts a knot there with the curve's own point and (linear) second derivative, so
// both halves are the same cubics as before. Cutting at the file point instead would leave a
// sliver of nose that sample(u) cannot reach: 2 to 4e-3 chord jumps at u = x_LE on clarky,
// e387, n63412 and naca2412.
std::pair<SplineSurface, SplineSurface> cut_at_leading_edge(const std::vector<Knot>& loop,
                                                            std::size_t k) {
    Knot le = loop[k];
    std::size_t last_upper = k - 1; // the loop knots either side of the cut
    std::size_t first_lower = k + 1;
    for (std::size_t j = k - 1; j <= k; ++j) {
        const Knot& a = loop[j];
        const Knot& b = loop[j + 1];
        const double h = b.s - a.s;
        const double c0 = (b.p.x() - a.p.x()) / h - h * a.m.x() / 3 - h * b.m.x() / 6;
        const double c1 = h * a.m.x();
        const double c2 = h * (b.m.x() - a.m.x()) / 2;
        double roots[2] = {-1, -1};
        if (std::abs(c2) <= 1e-12 * (std::abs(c1) + std::abs(c0))) {
            roots[0] = c1 != 0 ? -c0 / c1 : -1;
        } else if (const double disc = c1 * c1 - 4 * c2 * c0; disc >= 0) {
            const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
            roots[0] = q / c2;
            roots[1] = q != 0 ? c0 / q : -1;
        }
        for (double t : roots) {
            if (!(t > 1e-9 && t < 1 - 1e-9)) {
                continue;
            }
            Knot cut{a.s + t * h, {0, 0}, a.m + t * (b.m - a.m)};
            Eigen::Vector2d d;
            eval_segment(a, b, cut.s, cut.p, d);
            if (cut.p.x() < le.p.x()) {
                le = cut;
                last_upper = j;
                first_lower = j + 1;
            }
        }
    }
    std::vector<Knot> upper{Knot{0.0, le.p, le.m}};
    for (std::size_t i = last_upper + 1; i-- > 0;) {
        upper.push_back({le.s - loop[i].s, loop[i].p, loop[i].m});
    }
    std::vector<Knot> lower{Knot{0.0, le.p, le.m}};
    for (std::size_t i = first_lower; i < loop.size(); ++i) {
        lower.push_back({loop[i].s - le.s, loop[i].p, loop[i].m});
    }
    return {SplineSurface(std::move(upper)), SplineSurface(std::move(lower))};
}

// ---------------------------------------------------------------------------------------------
// Reading the .dat file

struct FilePoint {
    Eigen::Vector2d p;
    std::int64_t line;
};

struct ParsedFile {
    std::string name;
    std::int64_t name_line = 0;
    std::int64_t last_line = 0;
    std::vector<FilePoint> points; // every numeric line in file order
};

constexpr const char* kBlank = " \t\v\f";

std::string trim(const std::string& text) {
    const auto first = text.find_first_not_of(kBlank);
    if (first == std::string::npos) {
        return {};
    }
    return text.substr(first, text.find_last_not_of(kBlank) - first + 1);
}

// Lines split at LF, CRLF or a lone CR.
std::vector<std::string> split_lines(std::string_view bytes) {
    std::vector<std::string> lines(1);
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        const char ch = bytes[i];
        if (ch == '\r' || ch == '\n') {
            if (ch == '\r' && i + 1 < bytes.size() && bytes[i + 1] == '\n') {
                ++i;
            }
            lines.emplace_back();
        } else {
            lines.back() += ch;
        }
    }
    return lines;
}

std::string shorten(const std::string& text) {
    return text.size() <= 40 ? text : text.substr(0, 37) + "...";
}

enum class Number { ok, not_a_number, out_of_range };

// One token as a number (a leading '+' accepted; "nan" and "inf" parse and are caught later).
Number parse_number(const std::string& token, double& value) {
    const char* first = token.data();
    const char* last = first + token.size();
    if (first != last && *first == '+') {
        ++first;
    }
#if defined(__cpp_lib_to_chars) && __cpp_lib_to_chars >= 201611L
    const auto [end, ec] = std::from_chars(first, last, value);
    if (end != last || first == last) {
        return Number::not_a_number;
    }
    return ec == std::errc() ? Number::ok : Number::out_of_range;
#else
    // A standard library without floating-point from_chars (the WebAssembly build's libc++):
    // strtod in the C locale parsons never leaves, refusing what from_chars would not read
    // (hexadecimal, a second sign, blanks).
    const std::string digits(first, last);
    if (digits.empty() || digits.front() == '+' ||
        digits.find_first_of("xX \t\r\n\v\f") != std::string::npos) {
        return Number::not_a_number;
    }
    errno = 0;
    char* end = nullptr;
    value = std::strtod(digits.c_str(), &end);
    if (end != digits.c_str() + digits.size()) {
        return Number::not_a_number;
    }
    return errno == ERANGE ? Number::out_of_range : Number::ok;
#endif
}

FilePoint parse_pair(const std::string& path, std::int64_t line, const std::string& text) {
    std::vector<std::string> tokens;
    for (std::size_t pos = text.find_first_not_of(kBlank); pos != std::string::npos;) {
        const auto end = text.find_first_of(kBlank, pos);
        tokens.push_back(text.substr(pos, end - pos));
        pos = text.find_first_not_of(kBlank, end);
    }
    double v[2] = {0, 0};
    Number kind[2] = {Number::not_a_number, Number::not_a_number};
    for (std::size_t k = 0; k < 2 && tokens.size() == 2; ++k) {
        kind[k] = parse_number(tokens[k], v[k]);
    }
    if (kind[0] == Number::not_a_number || kind[1] == Number::not_a_number) {
        throw DeckError::at_line(
            path, line, fmt::format("expected two numbers 'x y', found '{}'", shorten(text)));
    }
    for (std::size_t k = 0; k < 2; ++k) {
        if (kind[k] == Number::out_of_range) {
            throw DeckError::at_line(path, line,
                                     fmt::format("'{}' is out of range", shorten(tokens[k])));
        }
        if (!std::isfinite(v[k])) {
            throw DeckError::at_line(
                path, line, fmt::format("'{}' is not a finite number", shorten(tokens[k])));
        }
    }
    return {{v[0], v[1]}, line};
}

ParsedFile parse_file(const std::string& path, std::string_view bytes) {
    if (bytes.starts_with("\xEF\xBB\xBF")) { // UTF-8 byte order mark
        bytes.remove_prefix(3);
    }
    ParsedFile file;
    const auto lines = split_lines(bytes);
    for (std::size_t k = 0; k < lines.size(); ++k) {
        const auto text = trim(lines[k]);
        const std::int64_t line = static_cast<std::int64_t>(k) + 1;
        if (text.empty()) {
            continue;
        }
        file.last_line = line;
        if (file.name_line == 0) {
            file.name = text;
            file.name_line = line;
        } else {
            file.points.push_back(parse_pair(path, line, text));
        }
    }
    if (file.name_line == 0) {
        throw DeckError::in_file(path, "empty file: no name line and no coordinates");
    }
    return file;
}

bool is_count(double v) {
    return v >= 2 && v < 1e6 && v == std::floor(v);
}

// The points as one Selig loop (TE -> upper -> LE -> lower -> TE), from either layout. A
// Lednicer file starts with a line of two whole counts >= 2, confirmed by the counts matching
// the lines that follow or by the next point being at the leading edge (x about 0); a Selig
// file starts with a TE point (x about 1, |y| small).
std::vector<FilePoint> selig_loop(const std::string& path, const ParsedFile& file) {
    const auto& pts = file.points;
    if (pts.empty() || !is_count(pts[0].p.x()) || !is_count(pts[0].p.y())) {
        return pts;
    }
    const auto upper = static_cast<std::size_t>(pts[0].p.x());
    const auto lower = static_cast<std::size_t>(pts[0].p.y());
    const std::size_t follow = pts.size() - 1;
    double max_x = 0;
    for (std::size_t k = 1; k < pts.size(); ++k) {
        max_x = std::max(max_x, std::abs(pts[k].p.x()));
    }
    const bool le_next = follow > 0 && std::abs(pts[1].p.x()) <= 0.05 * max_x;
    if (upper + lower != follow && !le_next) {
        return pts; // a Selig file in percent whose TE happens to be whole numbers
    }
    if (upper + lower != follow) {
        throw DeckError::at_line(
            path, pts[0].line,
            fmt::format("Lednicer point counts {} upper + {} lower = {} points, but {} "
                        "coordinate lines follow",
                        upper, lower, upper + lower, follow));
    }
    std::vector<FilePoint> loop(pts.rend() - 1 - static_cast<std::int64_t>(upper), pts.rend() - 1);
    loop.insert(loop.end(), pts.begin() + 1 + static_cast<std::int64_t>(upper), pts.end());
    return loop;
}

class DatAirfoil final : public Airfoil {
public:
    DatAirfoil(std::string name, std::pair<SplineSurface, SplineSurface> surfaces)
        : name_(std::move(name)), upper_(std::move(surfaces.first)),
          lower_(std::move(surfaces.second)) {}

    std::string name() const override { return name_; }
    SurfaceSample sample(Side side, double u) const override {
        return (side == Side::upper ? upper_ : lower_).at_x(u);
    }

private:
    std::string name_;
    SplineSurface upper_;
    SplineSurface lower_;
};

// Consecutive points closer than this (chords) are one point: the spline's chord-length
// parameter could not tell them apart. Files give 4 to 6 decimals.
constexpr double kSamePointChords = 1e-9;

// Cleans the loop in place: percent tables scaled to chord 1, consecutive duplicates dropped,
// counter-clockwise order. Returns the index of the leading edge (minimum x).
std::size_t normalise_loop(const std::string& path, const ParsedFile& file,
                           std::vector<FilePoint>& loop) {
    double max_x = 0;
    for (const auto& q : loop) {
        max_x = std::max(max_x, std::abs(q.p.x()));
    }
    const double scale = max_x > 1.5 ? 100 : 1;
    if (max_x > 150) {
        throw DeckError::in_file(path, fmt::format("x reaches {}: coordinates are neither in "
                                                   "chords nor in percent of chord",
                                                   max_x));
    }
    for (auto& q : loop) {
        if (std::abs(q.p.y()) > scale) {
            throw DeckError::at_line(path, q.line,
                                     fmt::format("y = {} lies farther from the chord line than "
                                                 "the chord is long",
                                                 q.p.y()));
        }
        q.p /= scale;
    }
    loop.erase(std::unique(loop.begin(), loop.end(),
                           [](const FilePoint& a, const FilePoint& b) {
                               return (a.p - b.p).norm() <= kSamePointChords;
                           }),
               loop.end());
    double area2 = 0; // twice the signed (shoelace) area; positive counter-clockwise
    for (std::size_t k = 0; k < loop.size(); ++k) {
        const auto& a = loop[k].p;
        const auto& b = loop[(k + 1) % loop.size()].p;
        area2 += a.x() * b.y() - b.x() * a.y();
    }
    if (area2 < 0) {
        std::reverse(loop.begin(), loop.end());
    }
    if (loop.empty()) {
        throw DeckError::at_line(path, file.name_line, "no coordinates follow the name line");
    }
    const auto le = static_cast<std::size_t>(
        std::min_element(loop.begin(), loop.end(),
                         [](const FilePoint& a, const FilePoint& b) { return a.p.x() < b.p.x(); }) -
        loop.begin());
    const std::size_t n_upper = le + 1;
    const std::size_t n_lower = loop.size() - le;
    if (n_upper < 5 || n_lower < 5) {
        throw DeckError::at_line(
            path, file.last_line,
            fmt::format("{} points: the upper surface has {} and the lower {} (split at the "
                        "leading edge, the point of least x); each needs at least 5",
                        loop.size(), n_upper, n_lower));
    }
    return le;
}

// Each surface must run LE -> TE with x never decreasing, or sample(u) would be ambiguous.
void check_monotone(const std::string& path, const std::vector<FilePoint>& loop, std::size_t le) {
    for (const bool upper : {true, false}) { // upper: backwards through the loop from the LE
        const std::size_t steps = upper ? le : loop.size() - 1 - le;
        for (std::size_t k = 1; k <= steps; ++k) {
            const auto& prev = loop[upper ? le - k + 1 : le + k - 1];
            const auto& next = loop[upper ? le - k : le + k];
            if (next.p.x() < prev.p.x()) {
                throw DeckError::at_line(
                    path, next.line,
                    fmt::format("the {} surface turns back (x = {} after {} from the leading "
                                "edge); x must increase from the leading edge to the trailing "
                                "edge",
                                upper ? "upper" : "lower", next.p.x(), prev.p.x()));
            }
        }
    }
}

} // namespace

std::unique_ptr<Airfoil> naca4(const std::string& digits, bool closed_trailing_edge) {
    const bool four_digits =
        digits.size() == 4 &&
        std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!four_digits) {
        throw std::invalid_argument(fmt::format(
            "NACA 4-digit section '{}': expected exactly four digits MPXX, e.g. 2412", digits));
    }
    if (digits[2] == '0' && digits[3] == '0') {
        throw std::invalid_argument(
            fmt::format("NACA 4-digit section '{}': thickness XX = 00, the section has no "
                        "thickness",
                        digits));
    }
    return std::make_unique<Naca4>(digits, closed_trailing_edge);
}

std::unique_ptr<Airfoil> read_dat(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw DeckError::in_file(path, "cannot open the airfoil file");
    }
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    return read_dat_text(bytes, path);
}

std::unique_ptr<Airfoil> read_dat_text(std::string_view bytes, const std::string& path) {
    const ParsedFile file = parse_file(path, bytes);
    std::vector<FilePoint> loop = selig_loop(path, file);
    const std::size_t le = normalise_loop(path, file, loop);
    check_monotone(path, loop, le);

    std::vector<Eigen::Vector2d> q;
    for (const auto& fp : loop) {
        q.push_back(fp.p);
    }
    return std::make_unique<DatAirfoil>(file.name, cut_at_leading_edge(fit_loop(q), le));
}

} // namespace parsons::decks
