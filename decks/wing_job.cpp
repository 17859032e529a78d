#include "decks/wing_job.hpp"

#include "decks/cut_proof.hpp"
#include "decks/cut_svg.hpp"
#include "decks/deck_limits.hpp"
#include "decks/move_planner.hpp"
#include "decks/number_text.hpp"
#include "decks/units.hpp"

#include <Eigen/Geometry>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <tuple>

namespace parsons::decks {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;
// Two cards a station (wing_job.hpp); by scallop, at most this many stations.
constexpr std::int64_t kCardsPerStation = 2;
constexpr int kMostScallopStations = 400;
static_assert(kCardsPerStation * kMostScallopStations <= kMaxDeckCards,
              "a wing by scallop always fits a deck");

struct Section {
    double chord;
    double le_x;
    double y;
};

Section section_at(const WingOptions& o, double y) {
    return {o.root_chord_in * (1 + (o.taper - 1) * y / o.span_in),
            y * std::tan(o.sweep_deg * std::numbers::pi / 180), y};
}

Vector3d point_on(const Airfoil& a, const Section& s, double u) {
    const Vector2d p = a.sample(Side::upper, u).point;
    return {s.le_x + s.chord * p.x(), s.y, s.chord * p.y()};
}

// The cutter centre touching the ruled surface at station u of section s: R along the
// surface's own normal (section tangent x ruling), on the outer side.
Vector3d centre_on(const Airfoil& a, const WingOptions& o, double u, double y) {
    const Section root = section_at(o, 0);
    const Section tip = section_at(o, o.span_in);
    const Section here = section_at(o, y);
    const SurfaceSample s = a.sample(Side::upper, u);
    const Vector3d along(here.chord * s.tangent.x(), 0, here.chord * s.tangent.y());
    const Vector3d ruling = point_on(a, tip, u) - point_on(a, root, u);
    Vector3d n = along.cross(ruling).normalized();
    const Vector3d outward2d(-s.tangent.y(), 0, s.tangent.x());
    if (n.dot(outward2d) < 0) {
        n = -n;
    }
    return point_on(a, here, u) + o.cutter_radius_in * n;
}

Eigen::Matrix3d fixture_rotation(double tilt, double swivel) {
    return (Eigen::AngleAxisd(swivel, Vector3d::UnitZ()) *
            Eigen::AngleAxisd(tilt, Vector3d::UnitX()))
        .toRotationMatrix();
}

double segment_distance(const Vector3d& p, const Vector3d& a, const Vector3d& b) {
    const Vector3d ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (a + t * ab - p).norm();
}

std::vector<double> stations_u(int n, Spacing spacing) {
    std::vector<double> us;
    for (int k = 0; k < n; ++k) {
        const double f = static_cast<double>(k) / (n - 1);
        us.push_back(spacing == Spacing::uniform ? f : (1 - std::cos(std::numbers::pi * f)) / 2);
    }
    return us;
}

SectionProof section_proof(const Airfoil& a, const WingOptions& o, double y,
                           const std::vector<std::pair<Vector3d, Vector3d>>& segments, int points) {
    SectionProof sp;
    const Section s = section_at(o, y);
    for (double u : stations_u(points, Spacing::cosine)) {
        const Vector3d p = point_on(a, s, u);
        const Vector2d t = a.sample(Side::upper, u).tangent;
        sp.normals.emplace_back(-t.y(), t.x());
        double best = 1e9;
        for (const auto& [sa, sb] : segments) {
            best = std::min(best, segment_distance(p, sa, sb));
        }
        const double dev = best - o.cutter_radius_in;
        sp.design.emplace_back(p.x(), p.z());
        sp.deviation_in.push_back(dev);
        sp.max_leftover_in = std::max(sp.max_leftover_in, dev);
        sp.max_gouge_in = std::max(sp.max_gouge_in, -dev);
    }
    return sp;
}

// Planned deviation: the ideal lines, each run past both ends of the span.
std::pair<double, double> planned(const Airfoil& a, const WingOptions& o,
                                  const std::vector<WingStation>& stations) {
    std::vector<std::pair<Vector3d, Vector3d>> lines;
    for (const auto& st : stations) {
        const Vector3d d = (st.tip_centre - st.root_centre).normalized();
        lines.emplace_back(st.root_centre - o.cutter_radius_in * 4 * d,
                           st.tip_centre + o.cutter_radius_in * 4 * d);
    }
    double leftover = 0;
    double gouge = 0;
    for (double y : {0.0, o.span_in}) {
        const SectionProof sp = section_proof(a, o, y, lines, 400);
        leftover = std::max(leftover, sp.max_leftover_in);
        gouge = std::max(gouge, sp.max_gouge_in);
    }
    return {leftover, gouge};
}

std::vector<WingStation> make_stations(const Airfoil& a, const WingOptions& o, int n) {
    std::vector<WingStation> out;
    for (double u : stations_u(n, o.spacing)) {
        WingStation st;
        st.u = u;
        st.root_centre = centre_on(a, o, u, 0);
        st.tip_centre = centre_on(a, o, u, o.span_in);
        const Vector3d d = st.tip_centre - st.root_centre;
        st.tilt_rad = std::atan2(-d.z(), d.y());
        st.swivel_rad = std::atan2(d.x(), std::hypot(d.y(), d.z()));
        out.push_back(st);
    }
    return out;
}

// Refuses, before anything is computed, sizes the machine cannot cut: a root or tip chord or
// a span under a hundred impulses, a cutter radius under one, anything not a finite number, a
// sweep of 60 degrees or more.
void check_sizes(const WingOptions& o) {
    refuse_unless_shape("--chord", o.root_chord_in, "chord");
    refuse_unless_shape("--span", o.span_in, "span");
    refuse_unless_cutter("--cutter-radius", o.cutter_radius_in);
    refuse_unless_finite("--taper", o.taper);
    refuse_unless_finite("--sweep", o.sweep_deg);
    refuse_unless_finite("--scallop", o.scallop_in);
    const double tip_in = o.root_chord_in * o.taper;
    if (!(tip_in >= kLeastShapeIn)) {
        throw JobError(fmt::format(
            "--taper {}: the tip chord would be {:.4g} in ({:.3f} in x {}); a chord under "
            "{:.3f} in is no shape to the machine, which moves in impulses of {:.3f} in: give a "
            "taper of at least {:.4f}",
            o.taper, tip_in, o.root_chord_in, o.taper, kLeastShapeIn, kImpulseIn,
            std::ceil(kLeastShapeIn / o.root_chord_in * 1e4) / 1e4));
    }
    if (std::abs(o.sweep_deg) >= 60) {
        throw JobError(fmt::format("--sweep {}: the sweep must be under 60 degrees", o.sweep_deg));
    }
}

// Refuses, before a station is computed, a count that cannot make a deck.
void check_station_count(const WingOptions& o) {
    if (o.stations < 2) {
        throw JobError(fmt::format("--stations {}: need at least 2", o.stations));
    }
    refuse_past_deck_limit(kCardsPerStation * o.stations, fmt::format("--stations {}", o.stations),
                           false, fmt::format("{} a station", kCardsPerStation));
}

} // namespace

WingDeck make_wing_deck(const Airfoil& airfoil, const WingOptions& o,
                        const axes::MachineProfile& profile) {
    check_sizes(o);
    WingDeck deck;
    if (o.scallop_in > 0) {
        int n = 6;
        for (; n <= kMostScallopStations; n = n * 5 / 4 + 1) {
            deck.stations = make_stations(airfoil, o, n);
            if (planned(airfoil, o, deck.stations).first <= o.scallop_in) {
                break;
            }
        }
    } else {
        check_station_count(o);
        deck.stations = make_stations(airfoil, o, o.stations);
    }
    std::tie(deck.planned_leftover_in, deck.planned_gouge_in) = planned(airfoil, o, deck.stations);

    const auto& tilt = profile.axes.at(4);
    const auto& swivel = profile.axes.at(3);
    struct Setting {
        int tilt_screw, swivel_screw;
        Eigen::Matrix3d rotation;
        Vector3d root, tip; // rotated centres
    };
    std::vector<Setting> settings;
    for (const WingStation& st : deck.stations) {
        Setting s;
        s.tilt_screw = thousandths(tilt.level_in + tilt.pivot_to_screw_in * std::sin(st.tilt_rad));
        s.swivel_screw =
            thousandths(swivel.level_in + swivel.pivot_to_screw_in * std::tan(st.swivel_rad));
        // The line is placed for the angles the quantised screws really make.
        const double tilt_q = std::asin(std::clamp(
            (s.tilt_screw / 1000.0 - tilt.level_in) / tilt.pivot_to_screw_in, -1.0, 1.0));
        const double swivel_q =
            std::atan((s.swivel_screw / 1000.0 - swivel.level_in) / swivel.pivot_to_screw_in);
        s.rotation = fixture_rotation(tilt_q, swivel_q);
        s.root = s.rotation * st.root_centre;
        s.tip = s.rotation * st.tip_centre;
        settings.push_back(s);
    }
    // Where everything goes: the lines, the traverse past both ends, the retract height over
    // the whole wing at every setting.
    const double overrun = o.cutter_radius_in + 0.2;
    Vector3d lo = Vector3d::Constant(1e9);
    Vector3d hi = Vector3d::Constant(-1e9);
    double top = -1e9;
    bool finite = true; // false: a point overflowed (inf - inf is NaN, which min and max skip)
    for (const Setting& s : settings) {
        for (const Vector3d& p : {s.root, s.tip}) {
            finite = finite && p.allFinite();
            lo = lo.cwiseMin(p);
            hi = hi.cwiseMax(p);
        }
        lo.y() = std::min(lo.y(), s.root.y() - overrun);
        hi.y() = std::max(hi.y(), s.tip.y() + overrun);
        for (double y : {0.0, o.span_in}) {
            const Section sec = section_at(o, y);
            for (double u : stations_u(24, Spacing::cosine)) {
                const double z = (s.rotation * point_on(airfoil, sec, u)).z();
                finite = finite && std::isfinite(z);
                top = std::max(top, z);
            }
        }
    }
    top += o.cutter_radius_in + 0.1;
    finite = finite && std::isfinite(top);
    hi.z() = std::max(hi.z(), top);
    deck.zero = Vector3d::Constant(o.margin_in) - lo;
    const Vector3d extent = hi - lo;
    const double room = 9.999 - 2 * o.margin_in;
    if (!finite || !extent.allFinite()) { // a span or chord near the largest double
        throw JobError(fmt::format(
            "wing: a root chord of {} in, a tip chord of {} in (taper {}), a span of {} in and a "
            "cutter radius of {} in make a job too large to lay out, more than the {:.3f} in the "
            "counters leave: use a smaller wing",
            fixed(o.root_chord_in), fixed(o.root_chord_in * o.taper), o.taper, fixed(o.span_in),
            fixed(o.cutter_radius_in), room));
    }
    if (extent.maxCoeff() > room) {
        throw JobError(fmt::format("wing: the job spans {} x {} x {} in (cross, table, "
                                   "vertical), more than the {:.3f} in the counters leave: use a "
                                   "smaller wing",
                                   fixed(extent.x()), fixed(extent.y()), fixed(extent.z()), room));
    }
    for (std::size_t i = 0; i < settings.size(); ++i) {
        const Setting& s = settings[i];
        const WingStation& st = deck.stations[i];
        const std::array<std::tuple<const char*, int, double, const axes::AxisProfile*>, 2> screws =
            {{{"tilt", s.tilt_screw, st.tilt_rad, &tilt},
              {"swivel", s.swivel_screw, st.swivel_rad, &swivel}}};
        for (const auto& [what, screw, angle, axis] : screws) {
            if (screw < 0 || screw > 9999) {
                throw JobError(fmt::format(
                    "wing: at chord station {:.3f} the fixture must {} {:.2f} deg, which puts its "
                    "screw at {:.3f} in, outside the counters' 0.000 .. 9.999 in (level at "
                    "{:.3f} in, arm {:.1f} in): use less sweep or taper, or a shorter span",
                    st.u, what, angle * 180 / std::numbers::pi, screw / 1000.0, axis->level_in,
                    axis->pivot_to_screw_in));
            }
        }
    }

    // Two cards a station. Sequence: retract first, then the fixture, the cross slide, and the
    // table last; then the plunge and the cut, the table's traverse, last.
    std::array<int, 5> at{}; // table, cross, vertical, swivel, tilt (thousandths)
    auto card = [&](const std::array<int, 5>& to, const std::array<int, 5>& seq) {
        cardreader::CardOrders c;
        c.number = static_cast<int>(deck.cards.size() + 1) % 10000;
        c.spindle = cardreader::Spindle::forward;
        for (std::size_t i = 0; i < 5; ++i) {
            c.axes.at(i) = plan_move({at.at(i), to.at(i), i == 0 ? 2 : 1, false,
                                      static_cast<cardreader::SequencePattern>(1u << seq.at(i))},
                                     profile.axes.at(i), profile);
        }
        deck.cards.push_back(c);
        at = to;
    };
    const int z_top = thousandths(top + deck.zero.z());
    for (const Setting& s : settings) {
        const int cross = thousandths((s.root.x() + s.tip.x()) / 2 + deck.zero.x());
        const int z = thousandths((s.root.z() + s.tip.z()) / 2 + deck.zero.z());
        const int start = thousandths(s.root.y() - overrun + deck.zero.y());
        const int end = thousandths(s.tip.y() + overrun + deck.zero.y());
        //     table  cross  vertical  swivel  tilt
        card({start, cross, z_top, s.swivel_screw, s.tilt_screw}, {4, 3, 0, 1, 2});
        card({end, cross, z, s.swivel_screw, s.tilt_screw}, {4, 0, 3, 1, 2});
    }
    return deck;
}

Eigen::Vector3d work_point(const std::array<double, 5>& real, const Eigen::Vector3d& zero,
                           const axes::MachineProfile& profile) {
    const auto& tilt = profile.axes.at(4);
    const auto& swivel = profile.axes.at(3);
    const double t =
        std::asin(std::clamp((real[4] - tilt.level_in) / tilt.pivot_to_screw_in, -1.0, 1.0));
    const double s = std::atan((real[3] - swivel.level_in) / swivel.pivot_to_screw_in);
    const Vector3d machine(real[1] - zero.x(), real[0] - zero.y(), real[2] - zero.z());
    return fixture_rotation(t, s).transpose() * machine;
}

WingProof prove_wing(const std::vector<Eigen::Vector3d>& work_path, const Airfoil& airfoil,
                     const WingOptions& options, int points_per_section) {
    // Merge straight runs: consecutive points on one line add nothing.
    std::vector<std::pair<Vector3d, Vector3d>> segments;
    std::size_t start = 0;
    for (std::size_t k = 1; k < work_path.size(); ++k) {
        const bool last = k + 1 == work_path.size();
        bool straight = !last;
        if (!last) {
            const Vector3d a = work_path[k] - work_path[start];
            const Vector3d b = work_path[k + 1] - work_path[start];
            straight = a.cross(b).norm() <= 1e-9 * b.norm() && a.dot(b) >= 0;
        }
        if (!straight) {
            segments.emplace_back(work_path[start], work_path[k]);
            start = k;
        }
    }
    if (work_path.size() == 1) {
        segments.emplace_back(work_path[0], work_path[0]);
    }
    WingProof proof;
    proof.root = section_proof(airfoil, options, 0, segments, points_per_section);
    proof.tip = section_proof(airfoil, options, options.span_in, segments, points_per_section);
    return proof;
}

namespace {

// Where the path crossed the plane y = y0, as (x, z) points in order.
std::vector<Vector2d> crossings(const std::vector<Vector3d>& path, double y0) {
    std::vector<Vector2d> out;
    for (std::size_t k = 1; k < path.size(); ++k) {
        const Vector3d& a = path[k - 1];
        const Vector3d& b = path[k];
        if (a.y() == b.y() || (a.y() - y0) * (b.y() - y0) > 0) {
            continue;
        }
        const Vector3d p = a + (b - a) * ((y0 - a.y()) / (b.y() - a.y()));
        out.emplace_back(p.x(), p.z());
    }
    return out;
}

std::string section_svg(const SectionProof& s, const std::vector<Vector3d>& path, double y0,
                        double radius, const std::string& title) {
    CutProof cp;
    cp.max_gouge_in = s.max_gouge_in;
    cp.max_leftover_in = s.max_leftover_in;
    cp.max_scallop_in = s.max_leftover_in;
    cp.deviation_in = s.deviation_in;
    cp.machined_points = s.design.size();
    for (std::size_t i = 0; i < s.design.size(); ++i) {
        cp.cut_contour.push_back(s.design[i] + s.deviation_in[i] * s.normals[i]);
    }
    return cut_svg(cp, crossings(path, y0), DesignContour{s.design, s.normals}, radius, title);
}

// "0 0 W H" of an svg's viewBox.
std::pair<double, double> view_size(const std::string& svg) {
    const auto at = svg.find("viewBox=\"");
    double x = 0;
    double y = 0;
    double w = 1200;
    double h = 600;
    if (at != std::string::npos) {
        std::sscanf(svg.c_str() + at + 9, "%lf %lf %lf %lf", &x, &y, &w, &h);
    }
    return {w, h};
}

std::string nested(std::string svg, double y) {
    const auto decl = svg.find("?>");
    if (svg.rfind("<?xml", 0) == 0 && decl != std::string::npos) {
        svg.erase(0, decl + 2);
    }
    const auto open = svg.find("<svg");
    svg.insert(open + 4, fmt::format(" x=\"0\" y=\"{}\"", y));
    return svg;
}

} // namespace

std::string wing_cut_svg(const WingProof& proof, const std::vector<Eigen::Vector3d>& work_path,
                         const WingOptions& o, const std::string& title) {
    const std::string root = section_svg(proof.root, work_path, 0, o.cutter_radius_in,
                                         title + ": root section (span 0)");
    const std::string tip =
        section_svg(proof.tip, work_path, o.span_in, o.cutter_radius_in,
                    fmt::format("{}: tip section (span {:.3f} in)", title, o.span_in));
    const auto [w1, h1] = view_size(root);
    const auto [w2, h2] = view_size(tip);
    const double w = std::max(w1, w2);
    return fmt::format("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                       "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" "
                       "viewBox=\"0 0 {0} {1}\">\n<rect width=\"{0}\" height=\"{1}\" "
                       "fill=\"#ffffff\"/>\n{2}{3}</svg>\n",
                       w, h1 + h2, nested(root, 0), nested(tip, h1));
}

} // namespace parsons::decks
