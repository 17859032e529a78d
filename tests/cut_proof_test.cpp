#include "decks/cut_proof.hpp"
#include "decks/cut_svg.hpp"

#include "tests/test_support.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

using namespace parsons::decks;
using Eigen::Vector2d;
using parsons::test::count;

namespace {

constexpr double kStep = 0.001; // one impulse of the 0.001-inch commutator
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The path as the machine records it: one point per 0.001-inch impulse, one axis at a time
// (the table moves x, then the cross slide moves y).
class ImpulseRecorder {
public:
    explicit ImpulseRecorder(Vector2d start) : path_{start} {}
    ImpulseRecorder& x_to(double x) { return move(0, x); }
    ImpulseRecorder& y_to(double y) { return move(1, y); }
    const std::vector<Vector2d>& path() const { return path_; }

private:
    ImpulseRecorder& move(int axis, double target) {
        Vector2d p = path_.back();
        const long steps = std::lround((target - p[axis]) / kStep);
        const double dir = steps < 0 ? -1.0 : 1.0;
        const double start = p[axis];
        for (long k = 1; k <= std::labs(steps); ++k) {
            p[axis] = start + dir * kStep * double(k);
            path_.push_back(p);
        }
        path_.back()[axis] = target; // no rounding drift at the end of a run
        return *this;
    }
    std::vector<Vector2d> path_;
};

// The line y = 0 from x0 to x1, material below.
DesignContour flat_design(double x0, double x1, double spacing) {
    DesignContour d;
    const long n = std::lround((x1 - x0) / spacing);
    for (long k = 0; k <= n; ++k) {
        d.points.emplace_back(x0 + spacing * double(k), 0.0);
        d.normals.emplace_back(0.0, 1.0);
    }
    return d;
}

// Plunges to centres (k delta, R), k = 0..cuts-1, lifting to `lift` between them.
std::vector<Vector2d> plunge_path(double r, double delta, int cuts, double lift) {
    ImpulseRecorder rec(Vector2d(0, lift));
    for (int k = 0; k < cuts; ++k) {
        rec.x_to(k * delta).y_to(r).y_to(lift);
    }
    return rec.path();
}

// True when every element opened is closed in order (self-closing tags allowed).
bool balanced_tags(const std::string& xml) {
    std::vector<std::string> open;
    for (std::size_t pos = xml.find('<'); pos != std::string::npos; pos = xml.find('<', pos + 1)) {
        const std::size_t end = xml.find('>', pos);
        if (end == std::string::npos) {
            return false;
        }
        const std::string tag = xml.substr(pos + 1, end - pos - 1);
        const bool closing = tag.front() == '/';
        const std::string name = tag.substr(closing, tag.find_first_of(" />", closing) - closing);
        if (closing) {
            if (open.empty() || open.back() != name) {
                return false;
            }
            open.pop_back();
        } else if (tag.back() != '/') {
            open.push_back(name);
        }
    }
    return open.empty();
}

// The deliberately simple model: distance to every segment of the raw recording, marched along
// the normal in 0.0005-in steps and then bisected. Slow, but nothing to get wrong.
double reference_deviation(const std::vector<Vector2d>& path, double r, const Vector2d& p,
                           const Vector2d& n) {
    const auto cut = [&](double t) {
        const Vector2d q = p + t * n;
        for (std::size_t k = 0; k + 1 < path.size(); ++k) {
            const Vector2d ab = path[k + 1] - path[k];
            const double s = std::clamp((q - path[k]).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
            if ((path[k] + s * ab - q).norm() <= r) {
                return true;
            }
        }
        return false;
    };
    const bool at_zero = cut(0);
    const double dir = at_zero ? -1.0 : 1.0; // down through the cut, or up to it
    double inside = 0;                       // last t with cut(t) == at_zero
    double outside = kNaN;
    for (double t = 5e-4; t <= 2 * r; t += 5e-4) {
        if (cut(dir * t) != at_zero) {
            outside = t;
            break;
        }
        inside = t;
    }
    if (std::isnan(outside)) {
        return at_zero ? -r : kNaN;
    }
    for (int k = 0; k < 40; ++k) {
        const double mid = (inside + outside) / 2;
        (cut(dir * mid) == at_zero ? inside : outside) = mid;
    }
    return dir * (at_zero ? inside : outside);
}

} // namespace

TEST_CASE("Cut proof: plunges at spacing delta leave scallops R - sqrt(R^2 - delta^2/4) (Fig. 6)",
          "[cut]") {
    const double r = 0.25;
    const double delta = 0.05;
    const int cuts = 21;
    const auto path = plunge_path(r, delta, cuts, 2 * r);
    const DesignContour design = flat_design(0, delta * (cuts - 1), delta / 20);
    const CutProof proof = prove_cut(path, r, design, 2 * r);

    const double expected = r - std::sqrt(r * r - delta * delta / 4);
    CHECK(proof.max_scallop_in == Approx(expected).margin(1e-6));
    CHECK(proof.max_leftover_in == Approx(expected).margin(1e-6));
    CHECK(proof.max_gouge_in < 1e-9);
    CHECK(proof.machined_points == design.points.size());
    // Under each plunge the cut touches the design; half-way between two plunges the cusp.
    CHECK(proof.deviation_in[20] == Approx(0).margin(1e-9));
    CHECK(proof.deviation_in[30] == Approx(expected).margin(1e-9));
    CHECK(proof.cut_contour[30].y() == Approx(expected).margin(1e-9));
}

TEST_CASE("Cut proof: a path that dips 0.003 in below the offset gouges 0.003 in", "[cut]") {
    const double r = 0.25;
    const auto path = ImpulseRecorder(Vector2d(-0.5, r))
                          .x_to(1.0)
                          .y_to(r - 0.003)
                          .x_to(1.5)
                          .y_to(r)
                          .x_to(3.0)
                          .path();
    const DesignContour design = flat_design(0, 2.5, 0.01);
    const CutProof proof = prove_cut(path, r, design, 2 * r);

    CHECK(proof.max_gouge_in == Approx(0.003).margin(1e-6));
    CHECK(proof.max_leftover_in < 1e-9);
    CHECK(proof.deviation_in[125] == Approx(-0.003).margin(1e-9)); // x = 1.25
    CHECK(proof.deviation_in[50] == Approx(0).margin(1e-9));       // x = 0.5, on the design
}

TEST_CASE("Cut proof: a convex circle cut from centres on radius rho + R leaves the exact cusp",
          "[cut]") {
    const double rho = 2.0;
    const double r = 0.25;
    const double alpha = 5.0 * std::numbers::pi / 180; // angle between stations
    const int stations = 19;
    const auto at = [](double radius, double angle) {
        return Vector2d(radius * std::cos(angle), radius * std::sin(angle));
    };
    // Plunge radially to each station and back out, crossing over well clear of the work.
    std::vector<Vector2d> path;
    for (int k = 0; k < stations; ++k) {
        path.push_back(at(rho + 2 * r, k * alpha));
        path.push_back(at(rho + r, k * alpha));
        path.push_back(at(rho + 2 * r, k * alpha));
    }
    DesignContour design;
    const int per_station = 10;
    for (int k = 0; k <= (stations - 1) * per_station; ++k) {
        const double angle = k * alpha / per_station;
        design.points.push_back(at(rho, angle));
        design.normals.push_back(at(1, angle));
    }
    const CutProof proof = prove_cut(path, r, design, 2 * r);

    // On the bisector of two stations, the nearer intersection of the two cutter circles.
    const double centre = rho + r;
    const double cusp_radius =
        centre * std::cos(alpha / 2) - std::sqrt(r * r - std::pow(centre * std::sin(alpha / 2), 2));
    CHECK(proof.max_scallop_in == Approx(cusp_radius - rho).margin(1e-6));
    CHECK(proof.deviation_in[5] == Approx(cusp_radius - rho).margin(1e-9));
    CHECK(proof.max_gouge_in < 1e-9);
}

TEST_CASE("Cut proof: design points out of the cutter's reach are not machined (NaN)", "[cut]") {
    const double r = 0.25;
    const double delta = 0.05;
    const auto path = plunge_path(r, delta, 21, 2 * r); // cuts x in [0 - R, 1 + R]
    const DesignContour design = flat_design(-3, 3, delta / 20);
    const CutProof proof = prove_cut(path, r, design, 2 * r);

    REQUIRE(proof.deviation_in.size() == design.points.size());
    CHECK(std::isnan(proof.deviation_in.front())); // x = -3
    CHECK(std::isnan(proof.deviation_in.back()));  // x = +3
    CHECK(std::isnan(proof.cut_contour.front().x()));
    CHECK(!std::isnan(proof.deviation_in[1200])); // x = 0, under the first plunge
    CHECK(proof.machined_points < design.points.size());
    CHECK(proof.machined_points > 400);
    const double expected = r - std::sqrt(r * r - delta * delta / 4);
    CHECK(proof.max_scallop_in == Approx(expected).margin(1e-6));
    CHECK(std::isfinite(proof.max_leftover_in));
    CHECK(proof.max_gouge_in < 1e-9);
}

TEST_CASE("Cut proof: simplify_path keeps every corner and drops collinear points", "[cut]") {
    const auto staircase =
        ImpulseRecorder(Vector2d(0, 0)).x_to(0.010).y_to(0.003).x_to(0.020).y_to(0.001).path();
    const auto runs = simplify_path(staircase, 1e-6);
    const std::vector<Vector2d> corners{
        {0, 0}, {0.010, 0}, {0.010, 0.003}, {0.020, 0.003}, {0.020, 0.001}};
    REQUIRE(runs.size() == corners.size());
    for (std::size_t k = 0; k < corners.size(); ++k) {
        CHECK((runs[k] - corners[k]).norm() < 1e-12);
    }
    // Going back along the same line is a corner too: the far end stays.
    const std::vector<Vector2d> reversal{{0, 0}, {0.5, 0}, {1, 0}, {0.25, 0}};
    CHECK(simplify_path(reversal, 1e-6).size() == 3);
    CHECK(simplify_path({{0, 0}, {1, 1}}, 1e-6).size() == 2);
}

TEST_CASE("Cut proof: the picture is one well-formed SVG that states the worst numbers",
          "[cut][svg]") {
    const double r = 0.25;
    const auto path = ImpulseRecorder(Vector2d(-0.5, 2 * r))
                          .y_to(r)
                          .x_to(0.5)
                          .y_to(r - 0.002)
                          .x_to(0.7)
                          .y_to(2 * r)
                          .x_to(0.9)
                          .y_to(r)
                          .x_to(2.0)
                          .path();
    const DesignContour design = flat_design(-1, 2, 0.005);
    const CutProof proof = prove_cut(path, r, design, 2 * r);
    const std::string svg = cut_svg(proof, path, design, r, "flat <test> & dip", 50);

    CHECK(count(svg, "<svg") == 1);
    CHECK(count(svg, "</svg>") == 1);
    CHECK(count(svg, "<g") == count(svg, "</g>"));
    CHECK(balanced_tags(svg));
    CHECK(svg.find("flat &lt;test&gt; &amp; dip") != std::string::npos);
    CHECK(svg.find(fmt::format("{:.4f} in", proof.max_gouge_in)) != std::string::npos);
    CHECK(svg.find(fmt::format("{:.4f} in", proof.max_leftover_in)) != std::string::npos);
    CHECK(svg.find(fmt::format("{:.4f} in", proof.max_scallop_in)) != std::string::npos);
    CHECK(proof.max_gouge_in == Approx(0.002).margin(1e-6));
    CHECK(svg.find("nan") == std::string::npos);
}

TEST_CASE("Cut proof: five passes over a steep bump, 10^5 impulses against 5000 points (timing)",
          "[cut]") {
    // A bump y = 3 sin(pi x / 10) over 10 in (slopes up to 43 degrees), cut in five passes at
    // 0.2, 0.1, 0.05, 0.02 and 0 in of stock, each from centres offset along the normal at
    // stations 0.01 in apart, joined by 0.001-in staircases that hug the straight line.
    const double r = 0.25;
    const auto surface = [](double x) { return 3.0 * std::sin(std::numbers::pi * x / 10); };
    const auto normal = [](double x) {
        return Vector2d(-0.3 * std::numbers::pi * std::cos(std::numbers::pi * x / 10), 1)
            .normalized();
    };
    DesignContour design;
    for (int k = 0; k <= 5000; ++k) {
        const double x = 10.0 * k / 5000;
        design.points.emplace_back(x, surface(x));
        design.normals.push_back(normal(x));
    }
    const auto station = [&](int s, double stock) {
        const double x = s * 0.01;
        const Vector2d n = normal(x);
        return Vector2d(x + (r + stock) * n.x(), surface(x) + (r + stock) * n.y());
    };
    ImpulseRecorder rec(station(0, 0.2));
    for (double stock : {0.2, 0.1, 0.05, 0.02, 0.0}) {
        rec.y_to(std::round(station(0, stock).y() / kStep) * kStep);
        for (int s = (stock == 0.2 ? 1 : 0); s <= 1000; ++s) {
            const Vector2d c = station(s, stock);
            const Vector2d from = rec.path().back();
            const int n = int(std::lround((c - from).cwiseAbs().maxCoeff() / kStep));
            for (int k = 1; k <= n; ++k) {
                rec.x_to(std::round((from.x() + (c.x() - from.x()) * k / n) / kStep) * kStep);
                rec.y_to(std::round((from.y() + (c.y() - from.y()) * k / n) / kStep) * kStep);
            }
        }
        rec.y_to(4.0).x_to(station(0, 0).x()); // lift clear of the bump and go back
    }
    const auto t0 = std::chrono::steady_clock::now();
    const auto runs = simplify_path(rec.path(), 1e-9);
    const auto t1 = std::chrono::steady_clock::now();
    const CutProof proof = prove_cut(rec.path(), r, design, 2 * r);
    const auto t2 = std::chrono::steady_clock::now();
    const auto ms = [](auto d) { return std::chrono::duration<double, std::milli>(d).count(); };
    std::cout << fmt::format("cut proof timing: {} design points, {} recorded points -> {} runs; "
                             "merging {:.1f} ms, whole proof {:.1f} ms (max gouge {:.5f}, "
                             "leftover {:.5f}, scallop {:.5f} in)\n",
                             design.points.size(), rec.path().size(), runs.size(), ms(t1 - t0),
                             ms(t2 - t1), proof.max_gouge_in, proof.max_leftover_in,
                             proof.max_scallop_in);
    // The staircase (corners rounded to the 0.001-in grid) strays less than two steps.
    CHECK(proof.max_gouge_in < 2 * kStep);
    CHECK(proof.max_leftover_in < 2 * kStep);
    CHECK(proof.machined_points > 4900);
}

TEST_CASE("Cut proof: agrees with brute-force bisection on a raw staircase recording", "[cut]") {
    // A slope y = 0.6 x cut from stations 0.05 in apart, every third one pushed 0.002 in into
    // the work, joined table-first then cross-slide: leftover, gouges and the steps between.
    const double r = 0.25;
    const Vector2d n = Vector2d(-0.6, 1).normalized();
    const auto station = [&](int s) {
        const double x = 0.05 * s;
        const double push = s % 3 == 0 ? 0.002 : 0.0;
        const Vector2d c = Vector2d(x, 0.6 * x) + (r - push) * n;
        return Vector2d(std::round(c.x() / kStep) * kStep, std::round(c.y() / kStep) * kStep);
    };
    ImpulseRecorder rec(station(0));
    for (int s = 1; s <= 30; ++s) {
        rec.y_to(station(s).y()).x_to(station(s).x());
    }
    DesignContour design;
    for (int k = 0; k <= 60; ++k) {
        const double x = 0.1 + 0.4 * k / 60;
        design.points.emplace_back(x, 0.6 * x);
        design.normals.push_back(n);
    }
    const CutProof proof = prove_cut(rec.path(), r, design, 2 * r);
    int gouged = 0;
    for (std::size_t k = 0; k < design.points.size(); ++k) {
        INFO("design point " << k);
        const double expected = reference_deviation(rec.path(), r, design.points[k], n);
        CHECK(proof.deviation_in[k] == Approx(expected).margin(1e-7));
        gouged += expected < -1e-6;
    }
    CHECK(gouged > 10);
    CHECK(proof.max_gouge_in > 0.001);
    CHECK(proof.max_leftover_in > 0.001);
}

TEST_CASE("Cut proof: a single plunge cuts a dimple, bad arguments are refused", "[cut]") {
    const DesignContour design = flat_design(-1, 1, 0.01);
    const CutProof proof = prove_cut({Vector2d(0, 0.249)}, 0.25, design, 0.5);
    CHECK(proof.max_gouge_in == Approx(0.001).margin(1e-9));
    CHECK(proof.deviation_in[100] == Approx(-0.001).margin(1e-9));
    CHECK(std::isnan(proof.deviation_in[0])); // x = -1: 1.03 in from the cutter
    CHECK_THROWS_AS(prove_cut({Vector2d(0, 0.25)}, 0, design, 0.5), std::invalid_argument);
    DesignContour lopsided = design;
    lopsided.normals.pop_back();
    CHECK_THROWS_AS(prove_cut({Vector2d(0, 0.25)}, 0.25, lopsided, 0.5), std::invalid_argument);
}

TEST_CASE("Cut proof: a cut right through a thin part gouges the part's thickness, not R",
          "[cut]") {
    // A plate 0.01 in thick (upper face out, lower face back, as an airfoil contour runs round
    // its trailing edge) with a slot cut straight through it at x = 0.5.
    DesignContour design;
    for (int k = 0; k <= 100; ++k) {
        design.points.emplace_back(0.01 * k, 0.005);
        design.normals.emplace_back(0, 1);
    }
    for (int k = 100; k >= 0; --k) {
        design.points.emplace_back(0.01 * k, -0.005);
        design.normals.emplace_back(0, -1);
    }
    const double r = 0.25;
    const auto path = ImpulseRecorder(Vector2d(0.5, 1)).y_to(-1).path();
    const CutProof proof = prove_cut(path, r, design, 2 * r);
    CHECK(proof.max_gouge_in == Approx(0.01).margin(1e-9));
    CHECK(proof.deviation_in[50] == Approx(-0.01).margin(1e-9));  // upper face, in the slot
    CHECK(proof.deviation_in[151] == Approx(-0.01).margin(1e-9)); // lower face, x = 0.5
    CHECK(std::isnan(proof.deviation_in[0]));                     // x = 0, 0.5 in away
}

TEST_CASE("Cut proof: at the seam of a closed contour, where the surfaces meet to within the "
          "fit's rounding, no material lies between them and nothing is gouged",
          "[cut]") {
    using parsons::decks::DesignContour;
    // A thin wedge: the upper surface from the trailing edge to the nose, the lower back to a
    // trailing edge a hair to the right of the first point (a spline fit's rounding).
    DesignContour design;
    design.points = {{1.0, 0.0}, {0.5, 0.02}, {0.0, 0.0}, {0.5, -0.02}, {1.0 + 1e-10, 0.0}};
    design.normals = {{0.04, 1.0}, {0.0, 1.0}, {-1.0, 0.0}, {0.0, -1.0}, {0.04, -1.0}};
    for (auto& n : design.normals) {
        n.normalize();
    }
    // Cutters a fifth of a thousandth nearer the trailing edge than R (the coast), above it and
    // below it: the overcut there is a fifth of a thousandth, not the depth through the wedge.
    const double r = 0.1;
    const double near = r - 0.0002;
    const std::vector<Eigen::Vector2d> path = {{1.0, near}, {1.0, 0.3},  {1.3, 0.3},
                                               {1.3, -0.3}, {1.0, -0.3}, {1.0, -near}};
    const auto proof = parsons::decks::prove_cut(path, r, design, 3 * r);
    CHECK(proof.max_gouge_in < 0.001);
}
