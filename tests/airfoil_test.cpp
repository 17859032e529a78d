#include "decks/airfoil.hpp"

#include "cardreader/deck_error.hpp"

#include "tests/test_support.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace parsons::decks;
using parsons::cardreader::DeckError;

namespace {

std::string data_path(const std::string& name) {
    return std::string(PARSONS_SOURCE_DIR) + "/decks/airfoils/" + name;
}

// A Selig file's points, read independently of read_dat: the surface each lies on (split at the
// first point of least x, which is listed on both) and the point itself.
struct FilePoint {
    Side side;
    Eigen::Vector2d p;
    bool least_x; // the file's leading-edge point
};

std::vector<FilePoint> selig_points(const std::string& name) {
    std::ifstream in(data_path(name), std::ios::binary);
    REQUIRE(in);
    std::string line;
    std::getline(in, line); // the name
    std::vector<Eigen::Vector2d> pts;
    double x = 0, y = 0;
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        if (fields >> x >> y) {
            pts.emplace_back(x, y);
        }
    }
    const auto le = std::min_element(pts.begin(), pts.end(),
                                     [](const auto& a, const auto& b) { return a.x() < b.x(); }) -
                    pts.begin();
    std::vector<FilePoint> out;
    for (long k = 0; k < static_cast<long>(pts.size()); ++k) {
        const auto& p = pts[static_cast<std::size_t>(k)];
        if (k <= le) {
            out.push_back({Side::upper, p, k == le});
        }
        if (k >= le) {
            out.push_back({Side::lower, p, k == le});
        }
    }
    return out;
}

// Camber abscissa u whose NACA surface point has x = target (bisection; clamped to the ends).
double camber_station(const Airfoil& foil, Side side, double target) {
    double lo = 1e-4; // past the few-micron forward bulge of a cambered upper surface near u = 0
    double hi = 1.0;
    if (foil.sample(side, hi).point.x() <= target) {
        return hi;
    }
    if (target <= 0) {
        return 0;
    }
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (foil.sample(side, mid).point.x() < target ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

std::string airfoil_error(const std::string& path) {
    try {
        read_dat(path);
    } catch (const DeckError& e) {
        return e.what();
    }
    return "no error";
}

// The largest distance from a file point to the sample at the point's own x on its surface.
// The file's point of least x is usually not the curve's leading edge, which lies a little
// to one side of it, so that point is on one surface only: the nearer sample counts.
double knot_error(const Airfoil& foil, const std::string& name) {
    double worst = 0;
    for (const auto& fp : selig_points(name)) {
        double error = (foil.sample(fp.side, fp.p.x()).point - fp.p).norm();
        if (fp.least_x) {
            error = std::min(error, (foil.sample(Side::upper, fp.p.x()).point - fp.p).norm());
            error = std::min(error, (foil.sample(Side::lower, fp.p.x()).point - fp.p).norm());
        }
        worst = std::max(worst, error);
    }
    return worst;
}

} // namespace

TEST_CASE("Airfoil: NACA 0012 equations reproduce naca0012.dat to 1e-6 chord", "[airfoil]") {
    const auto foil = naca4("0012");
    CHECK(foil->name() == "NACA 0012");
    double worst = 0;
    for (const auto& fp : selig_points("naca0012.dat")) {
        const auto s = foil->sample(fp.side, fp.p.x());
        CHECK(s.point.x() == fp.p.x()); // symmetric: surface x is the camber x
        worst = std::max(worst, std::abs(s.point.y() - fp.p.y()));
    }
    INFO("NACA 0012: largest |y - file| = " << worst);
    CHECK(worst < 1e-6);
}

TEST_CASE("Airfoil: NACA 2412 equations match naca2412.dat to 2e-4 at the same surface x",
          "[airfoil]") {
    const auto foil = naca4("2412");
    CHECK(foil->name() == "NACA 2412");
    double worst = 0;
    for (const auto& fp : selig_points("naca2412.dat")) {
        const double u = camber_station(*foil, fp.side, fp.p.x());
        const auto s = foil->sample(fp.side, u);
        if (u > 0 && u < 1) {
            CHECK(s.point.x() == Approx(fp.p.x()).margin(1e-12));
        }
        worst = std::max(worst, std::abs(s.point.y() - fp.p.y()));
    }
    INFO("NACA 2412: largest |y - file| at the same surface x = " << worst);
    CHECK(worst < 2e-4);
}

TEST_CASE("Airfoil: the closed-TE NACA thickness (0.1036) differs from the open one near the TE",
          "[airfoil]") {
    const auto open = naca4("0012");
    const auto closed = naca4("0012", true);
    // y_t(0.95) differs by 5 t (0.1036 - 0.1015) 0.95^4.
    const double dyt = 5 * 0.12 * (0.1036 - 0.1015) * std::pow(0.95, 4);
    CHECK(open->sample(Side::upper, 0.95).point.y() - closed->sample(Side::upper, 0.95).point.y() ==
          Approx(dyt).epsilon(1e-9));
    // Closed: the two surfaces meet at the TE; open: 2 x 0.00126 apart.
    CHECK(closed->sample(Side::upper, 1).point.y() == Approx(0).margin(1e-15));
    CHECK(closed->sample(Side::lower, 1).point.y() == Approx(0).margin(1e-15));
    CHECK(open->sample(Side::upper, 1).point.y() == Approx(0.00126).margin(1e-9));

    // Against the 2412 table at x = 0.95 (upper 0.0114): open fits, closed gives 0.0103.
    const auto open2412 = naca4("2412");
    const auto closed2412 = naca4("2412", true);
    const auto y_at = [](const Airfoil& f) {
        return f.sample(Side::upper, camber_station(f, Side::upper, 0.95)).point.y();
    };
    CHECK(y_at(*open2412) == Approx(0.0114).margin(2e-4));
    CHECK(y_at(*closed2412) == Approx(0.0103).margin(1e-4));
}

TEST_CASE("Airfoil: NACA tangents are the exact derivative, unit, toward the TE, finite at u = 0",
          "[airfoil]") {
    const auto foil = naca4(GENERATE(as<std::string>{}, "0012", "2412", "4415", "6409"));
    const double h = 1e-7;
    for (Side side : {Side::upper, Side::lower}) {
        // u = p = 0.4 is left out: the camber curvature jumps there, so the surface tangent
        // has a small corner (about 3e-4 rad for 2412). The difference runs from u - h to
        // u + h, so agreeing with it also means pointing toward the TE.
        for (double u : {0.002, 0.01, 0.05, 0.2, 0.35, 0.45, 0.7, 0.95, 0.999}) {
            const auto s = foil->sample(side, u);
            const Eigen::Vector2d fd =
                (foil->sample(side, u + h).point - foil->sample(side, u - h).point).normalized();
            CHECK(s.tangent.norm() == Approx(1).epsilon(1e-14));
            CHECK((s.tangent - fd).norm() < 1e-6);
        }
        const auto le = foil->sample(side, 0);
        CHECK(std::isfinite(le.tangent.x()));
        CHECK(le.point.norm() == 0);
        // The tangent turns continuously into its limit at u = 0, by about sqrt(u) / 0.09 rad
        // for these thicknesses, and never becomes NaN.
        CHECK((le.tangent - foil->sample(side, 1e-16).tangent).norm() < 1e-6);
        CHECK((le.tangent - foil->sample(side, 1e-10).tangent).norm() < 1e-3);
        CHECK(std::isfinite(foil->sample(side, 1e-310).tangent.y()));
        CHECK((le.tangent - foil->sample(side, -1).tangent).norm() == 0); // clamped
        CHECK(foil->sample(side, std::nan("")).point == le.point);
        CHECK(foil->sample(side, 7).point == foil->sample(side, 1).point);
    }
}

TEST_CASE("Airfoil: at the leading edge the NACA tangent is normal to the camber line",
          "[airfoil]") {
    const auto symmetric = naca4("0012");
    CHECK((symmetric->sample(Side::upper, 0).tangent - Eigen::Vector2d(0, 1)).norm() < 1e-15);
    CHECK((symmetric->sample(Side::lower, 0).tangent - Eigen::Vector2d(0, -1)).norm() < 1e-15);
    const auto cambered = naca4("2412"); // dy_c/dx(0) = 2m/p = 0.1
    const double theta = std::atan(0.1);
    const Eigen::Vector2d up(-std::sin(theta), std::cos(theta));
    CHECK((cambered->sample(Side::upper, 0).tangent - up).norm() < 1e-15);
    CHECK((cambered->sample(Side::lower, 0).tangent + up).norm() < 1e-15);
}

TEST_CASE("Airfoil: NACA digits other than four with a thickness are refused", "[airfoil]") {
    for (const char* bad : {"", "241", "24120", "24a2", "2400", " 241", "-012"}) {
        CHECK_THROWS_AS(naca4(bad), std::invalid_argument);
    }
    CHECK_THROWS_WITH(naca4("23012"), "NACA 4-digit section '23012': expected exactly four "
                                      "digits MPXX, e.g. 2412");
    CHECK_THROWS_WITH(naca4("2400"), "NACA 4-digit section '2400': thickness XX = 00, the "
                                     "section has no thickness");
    CHECK_NOTHROW(naca4("0001"));
}

TEST_CASE("Airfoil: the spline of a Selig file passes through every file point", "[airfoil]") {
    const auto name = GENERATE(as<std::string>{}, "naca0012.dat", "naca2412.dat", "clarky.dat",
                               "e387.dat", "n63412.dat");
    const auto foil = read_dat(data_path(name));
    const double worst = knot_error(*foil, name);
    INFO(name << ": largest distance from a file point = " << worst);
    CHECK(worst < 1e-9);
}

TEST_CASE("Airfoil: names come from the header line, trimmed", "[airfoil]") {
    CHECK(read_dat(data_path("naca2412.dat"))->name() == "NACA 2412");
    CHECK(read_dat(data_path("clarky.dat"))->name() == "CLARK Y AIRFOIL"); // leading space
    CHECK(read_dat(data_path("e387.dat"))->name() == "E387");
    CHECK(read_dat(data_path("naca63412_lednicer.dat"))->name() == "NACA 63-412 AIRFOIL");
}

TEST_CASE("Airfoil: the Lednicer NACA 63-412 reads as the same section as the Selig file",
          "[airfoil]") {
    const auto lednicer = read_dat(data_path("naca63412_lednicer.dat"));
    const auto selig = read_dat(data_path("n63412.dat"));
    CHECK(knot_error(*lednicer, "n63412.dat") < 1e-9);
    for (Side side : {Side::upper, Side::lower}) {
        for (int k = 0; k <= 400; ++k) {
            const double u = k / 400.0;
            const auto a = lednicer->sample(side, u);
            const auto b = selig->sample(side, u);
            CHECK((a.point - b.point).norm() < 1e-12);
            CHECK((a.tangent - b.tangent).norm() < 1e-9);
        }
    }
    // The surfaces are the right way up: upper above lower at mid-chord.
    CHECK(selig->sample(Side::upper, 0.5).point.y() == Approx(0.075670));
    CHECK(selig->sample(Side::lower, 0.5).point.y() == Approx(-0.031640));
}

TEST_CASE("Airfoil: a blunt TE (Clark Y) keeps both TE points, u outside the chord clamps",
          "[airfoil]") {
    const auto foil = read_dat(data_path("clarky.dat"));
    CHECK(foil->sample(Side::upper, 1).point.y() == Approx(0.0005993).margin(1e-12));
    CHECK(foil->sample(Side::lower, 1).point.y() == Approx(-0.0005993).margin(1e-12));
    CHECK(foil->sample(Side::upper, 1.2).point == foil->sample(Side::upper, 1).point);
    CHECK(foil->sample(Side::lower, -0.5).point == foil->sample(Side::upper, -2).point);
    CHECK(foil->sample(Side::lower, std::nan("")).point == foil->sample(Side::upper, -2).point);
}

TEST_CASE("Airfoil: file surfaces meet at the curve's leading edge, continuous and vertical",
          "[airfoil]") {
    const auto name = GENERATE(as<std::string>{}, "naca0012.dat", "naca2412.dat", "clarky.dat",
                               "e387.dat", "n63412.dat");
    const auto foil = read_dat(data_path(name));
    const auto up = foil->sample(Side::upper, -1);
    const auto low = foil->sample(Side::lower, -1);
    CHECK(up.point == low.point);
    CHECK(up.point.x() <= 0.00044); // at or ahead of the file's point of least x
    CHECK((up.tangent - Eigen::Vector2d(0, 1)).norm() < 1e-6);
    CHECK((low.tangent - Eigen::Vector2d(0, -1)).norm() < 1e-6);
    // Just aft of the leading edge each surface is still next to it (x ~ x_LE + s^2 / 2R).
    for (Side side : {Side::upper, Side::lower}) {
        CHECK((foil->sample(side, up.point.x() + 1e-9).point - up.point).norm() < 1e-4);
        CHECK((foil->sample(side, up.point.x() + 1e-6).point - up.point).norm() < 3e-3);
    }
}

TEST_CASE("Airfoil: file tangents are unit, point toward the TE and match finite differences",
          "[airfoil]") {
    const auto name =
        GENERATE(as<std::string>{}, "clarky.dat", "e387.dat", "naca2412.dat", "n63412.dat");
    const auto foil = read_dat(data_path(name));
    const auto pts = selig_points(name);
    // At every file point, the tangent leads toward the next point along the surface (LE -> TE).
    for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
        const auto& a = pts[k];
        const auto& b = pts[k + 1];
        if (a.side != b.side) {
            continue;
        }
        const auto& [from, to] = a.side == Side::lower ? std::pair(a, b) : std::pair(b, a);
        const auto s = foil->sample(a.side, from.p.x());
        if ((s.point - from.p).norm() > 1e-9) {
            CHECK(from.least_x); // on the other surface
            continue;
        }
        CHECK(s.tangent.norm() == Approx(1).epsilon(1e-14));
        CHECK(s.tangent.dot(to.p - from.p) > 0);
    }
    const double h = 1e-6;
    for (Side side : {Side::upper, Side::lower}) {
        for (int k = 1; k < 100; ++k) {
            const double u = 0.02 + 0.97 * k / 100.0;
            const auto s = foil->sample(side, u);
            CHECK(s.tangent.x() > 0);
            const Eigen::Vector2d fd =
                (foil->sample(side, u + h).point - foil->sample(side, u - h).point).normalized();
            CHECK((s.tangent - fd).norm() < 1e-6);
            CHECK(s.point.x() == Approx(u).margin(1e-14));
        }
    }
}

TEST_CASE("Airfoil: CR-only or LF lines, tabs, percent tables and clockwise order read the same",
          "[airfoil]") {
    parsons::test::TempDir dir;
    const auto original = read_dat(data_path("naca2412.dat"));
    const auto pts = selig_points("naca2412.dat");
    std::string cr = "  NACA 2412\t \r";
    std::string percent = "NACA 2412\n";
    std::string clockwise = "NACA 2412\r\n";
    for (const auto& fp : pts) {
        if (fp.side == Side::lower && fp.p.x() == 0) {
            continue; // the LE is listed once
        }
        cr += "\t" + std::to_string(fp.p.x()) + "\t " + std::to_string(fp.p.y()) + "   \r";
        percent += std::to_string(100 * fp.p.x()) + " " + std::to_string(100 * fp.p.y()) + "\n";
        clockwise = clockwise + std::to_string(fp.p.x()) + " " + std::to_string(fp.p.y()) + "\r\n";
    }
    // clockwise: the same points, lower surface first (the lines read in reverse).
    std::istringstream lines(clockwise);
    std::vector<std::string> rows;
    for (std::string row; std::getline(lines, row);) {
        rows.push_back(row);
    }
    std::reverse(rows.begin() + 1, rows.end());
    std::string reversed;
    for (const auto& row : rows) {
        reversed += row + "\n";
    }
    parsons::test::write_bytes(dir.path("cr.dat"), cr);
    parsons::test::write_bytes(dir.path("percent.dat"), percent);
    parsons::test::write_bytes(dir.path("clockwise.dat"), reversed);
    for (const char* variant : {"cr.dat", "percent.dat", "clockwise.dat"}) {
        const auto foil = read_dat(dir.str(variant));
        CHECK(foil->name() == "NACA 2412");
        for (Side side : {Side::upper, Side::lower}) {
            for (int k = 0; k <= 50; ++k) {
                const auto a = foil->sample(side, k / 50.0);
                const auto b = original->sample(side, k / 50.0);
                CHECK((a.point - b.point).norm() < 1e-12);
            }
        }
    }
}

TEST_CASE("Airfoil: bad coordinate files name the file and the line", "[airfoil]") {
    parsons::test::TempDir dir;
    const auto bad = [&](const std::string& file, const std::string& bytes) {
        parsons::test::write_bytes(dir.path(file), bytes);
        return airfoil_error(dir.str(file));
    };
    const std::string good = "1.0 0.001\r\n0.5 0.05\r\n0.2 0.06\r\n0.1 0.04\r\n0.0 0.0\r\n"
                             "0.1 -0.03\r\n0.2 -0.04\r\n0.5 -0.03\r\n1.0 -0.001\r\n";
    REQUIRE(bad("good.dat", "GOOD\r\n" + good) == "no error");

    CHECK(bad("one.dat", "ONE NUMBER\r\n1.0 0.001\r\n0.5\r\n" + good) ==
          dir.str("one.dat") + ":3: expected two numbers 'x y', found '0.5'");
    CHECK(bad("word.dat", "WORD\r\n1.0 0.001\r\n\r\n0.5 0.05 \r\n0.2 abc\r\n" + good) ==
          dir.str("word.dat") + ":5: expected two numbers 'x y', found '0.2 abc'");
    CHECK(bad("three.dat", "X\n1 0\n0 0\n1 0.1\n") ==
          dir.str("three.dat") +
              ":4: 3 points: the upper surface has 2 and the lower 2 (split at the leading "
              "edge, the point of least x); each needs at least 5");
    CHECK(bad("header.dat", "JUST A NAME\n\n") ==
          dir.str("header.dat") + ":1: no coordinates follow the name line");
    CHECK(bad("empty.dat", "") ==
          dir.str("empty.dat") + ": empty file: no name line and no coordinates");
    CHECK(bad("blank.dat", " \r\n\t\r\n") ==
          dir.str("blank.dat") + ": empty file: no name line and no coordinates");
    CHECK(bad("nan.dat", "NAN\n1.0 0.001\n0.5 nan\n" + good) ==
          dir.str("nan.dat") + ":3: 'nan' is not a finite number");
    CHECK(bad("huge.dat", "HUGE\n1.0 0.001\n1e999 0.05\n" + good) ==
          dir.str("huge.dat") + ":3: '1e999' is out of range");
    CHECK(bad("back.dat", "BACK\n1.0 0.001\n0.5 0.05\n0.6 0.06\n0.1 0.04\n0.05 0.03\n0.0 0.0\n"
                          "0.1 -0.03\n0.2 -0.04\n0.5 -0.03\n1.0 -0.001\n") ==
          dir.str("back.dat") +
              ":3: the upper surface turns back (x = 0.5 after 0.6 from the leading edge); x "
              "must increase from the leading edge to the trailing edge");
    CHECK(airfoil_error(dir.str("missing.dat")) ==
          dir.str("missing.dat") + ": cannot open the airfoil file");
    // Found by the airfoil fuzzer: a y so large that the chord-length spline overflowed.
    CHECK(bad("tall.dat", "TALL\n1.0 0.001\n0.5 -3.5e138\n" + good) ==
          dir.str("tall.dat") + ":3: y = -3.5e+138 lies farther from the chord line than the "
                                "chord is long");
    CHECK(bad("tall_percent.dat", "TALL\n100 0.1\n50 101\n0 0\n50 -3\n100 -0.1\n") ==
          dir.str("tall_percent.dat") + ":3: y = 101 lies farther from the chord line than the "
                                        "chord is long");

    // Lednicer: 5 + 5 announced, 5 + 4 given.
    CHECK(bad("lednicer.dat", "LEDNICER\n  5.  5.\n\n0 0\n0.1 0.04\n0.2 0.06\n0.5 0.05\n1 0\n\n"
                              "0 0\n0.1 -0.03\n0.5 -0.03\n1 0\n") ==
          dir.str("lednicer.dat") + ":2: Lednicer point counts 5 upper + 5 lower = 10 points, "
                                    "but 9 coordinate lines follow");
    CHECK(bad("lednicer_ok.dat", "LEDNICER\n  5.  5.\n\n0 0\n0.1 0.04\n0.2 0.06\n0.5 0.05\n1 0\n\n"
                                 "0 0\n0.1 -0.03\n0.2 -0.04\n0.5 -0.03\n1 0\n") == "no error");
}

TEST_CASE("Airfoil: points closer than 1e-9 chord are one point, as exact repeats are",
          "[airfoil]") {
    // Two points 1e-300 apart got the same chord-length parameter and the spline divided by
    // their distance along it, zero (the fix for the fuzzer's tall file, made whole).
    parsons::test::TempDir dir;
    const std::string upper = "1.0 0.001\n0.5 0.05\n0.2 0.06\n0.1 0.04\n";
    const std::string lower = "0.1 -0.03\n0.2 -0.04\n0.5 -0.03\n1.0 -0.001\n";
    parsons::test::write_bytes(dir.path("once.dat"), "ONCE\n" + upper + "0 0\n" + lower);
    parsons::test::write_bytes(dir.path("near.dat"),
                               "NEAR\n" + upper + "0 0\n1e-300 0\n0 1e-12\n" + lower);
    const auto once = read_dat(dir.str("once.dat"));
    const auto near = read_dat(dir.str("near.dat"));
    for (Side side : {Side::upper, Side::lower}) {
        for (int k = 0; k <= 20; ++k) {
            const auto a = near->sample(side, k / 20.0);
            CHECK((a.point - once->sample(side, k / 20.0).point).norm() < 1e-9);
            CHECK(a.tangent.norm() == Approx(1));
        }
    }
}

TEST_CASE("Airfoil: the spline reproduces the NACA 0012 equations between the file's stations",
          "[airfoil]") {
    const auto file = read_dat(data_path("naca0012.dat"));
    const auto exact = naca4("0012");
    double worst_nose = 0, worst_aft = 0;
    for (Side side : {Side::upper, Side::lower}) {
        for (int k = 0; k <= 2000; ++k) {
            const double u = k / 2000.0;
            const double dy =
                std::abs(file->sample(side, u).point.y() - exact->sample(side, u).point.y());
            double& worst = u < 0.02 ? worst_nose : worst_aft;
            worst = std::max(worst, dy);
        }
    }
    INFO("naca0012.dat spline vs equations: nose (x < 0.02) " << worst_nose << ", aft "
                                                              << worst_aft);
    CHECK(worst_nose < 1e-4);
    CHECK(worst_aft < 1e-5);
}
