#include "decks/template_job.hpp"

#include "decks/deck_limits.hpp"
#include "decks/move_planner.hpp"
#include "decks/number_text.hpp"
#include "decks/units.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

namespace parsons::decks {
namespace {

using Eigen::Vector2d;
// The approach (make_template_deck) takes three cards from the reference zero to the first
// station, or four when it goes over the top of the job.
constexpr std::int64_t kLeastApproachCards = 3;

// The stations run along a track: one surface LE -> TE, or both surfaces as one loop, the
// upper from TE to LE and on round the leading edge along the lower back to the TE.
struct Track {
    Surface surface;
    // Where the stations start: the leading edge's own x. For a coordinate file the fitted
    // leading edge is rarely at x = 0 exactly; every source clamps a station below it to it.
    double u0 = 0;
    double end() const { return surface == Surface::both ? 2.0 : 1.0; }
    double u_of(double f) const { return u0 + (1 - u0) * f; }
    std::pair<Side, double> at(double w) const {
        switch (surface) {
        case Surface::upper:
            return {Side::upper, u_of(w)};
        case Surface::lower:
            return {Side::lower, u_of(w)};
        case Surface::both:
            break;
        }
        return w < 1.0 ? std::pair{Side::upper, u_of(1.0 - w)}
                       : std::pair{Side::lower, u_of(w - 1.0)};
    }
};

Track make_track(const Airfoil& airfoil, Surface surface) {
    return {surface, std::min(0.0, airfoil.sample(Side::upper, -1.0).point.x())};
}

Vector2d outward(Side side, const Vector2d& t) {
    return side == Side::upper ? Vector2d(-t.y(), t.x()) : Vector2d(t.y(), -t.x());
}

Station station_at(const Airfoil& airfoil, const TemplateOptions& o, const Track& track, double w) {
    const auto [side, u] = track.at(w);
    const SurfaceSample s = airfoil.sample(side, u);
    Station st;
    st.side = side;
    st.u = u;
    st.work = s.point * o.chord_in;
    const Vector2d n = outward(side, s.tangent);
    st.toward_cutter = o.female ? Vector2d(-n) : n;
    st.centre = st.work + o.cutter_radius_in * st.toward_cutter;
    return st;
}

double segment_distance(const Vector2d& p, const Vector2d& a, const Vector2d& b) {
    const Vector2d ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (a + t * ab - p).norm();
}

// The staircase corner on the cutter's side of the line between two centres.
Vector2d corner_between(const Station& a, const Station& b) {
    const Vector2d m = a.toward_cutter + b.toward_cutter;
    const double dx = b.centre.x() - a.centre.x();
    const double dy = b.centre.y() - a.centre.y();
    const bool cross_first = -dx * m.x() + dy * m.y() > 0;
    return cross_first ? Vector2d(a.centre.x(), b.centre.y())
                       : Vector2d(b.centre.x(), a.centre.y());
}

struct Deviation {
    double leftover = 0;
    double gouge = 0;
};

// The least t >= 0 at which p + t n (n a unit vector) comes within r of the segment a-b: where
// the ray enters the capsule the cutter sweeps along it (two flat sides, two round ends).
// kNever if it never does. Exact, by the quadratic and linear equations of those boundaries.
double ray_enters_capsule(const Vector2d& p, const Vector2d& n, const Vector2d& a,
                          const Vector2d& b, double r) {
    double best = std::numeric_limits<double>::infinity();
    for (const Vector2d& c : {a, b}) { // the round ends
        const Vector2d pc = p - c;
        const double half_b = n.dot(pc);
        const double disc = half_b * half_b - (pc.squaredNorm() - r * r);
        if (disc >= 0) {
            const double near = -half_b - std::sqrt(disc);
            const double far = -half_b + std::sqrt(disc);
            if (far >= 0) {
                best = std::min(best, std::max(near, 0.0)); // 0: p is inside already
            }
        }
    }
    const Vector2d ab = b - a;
    const double len = ab.norm();
    if (len > 0) { // the flat sides, r either side of the segment
        const Vector2d u = ab / len;
        const Vector2d m(-u.y(), u.x());
        const double y0 = m.dot(p - a);
        const double x0 = u.dot(p - a);
        const double ny = m.dot(n);
        const double nx = u.dot(n);
        if (ny != 0) {
            for (double side : {-r, r}) {
                const double t = (side - y0) / ny;
                const double x = x0 + t * nx;
                if (t >= 0 && x >= 0 && x <= len) {
                    best = std::min(best, t);
                }
            }
        }
    }
    return best;
}

// How far the surface between two stations ends up from the staircase cut between them,
// measured as the proof of the cut measures it (decks/cut_proof.hpp): a point the cutter
// came nearer than R to is gouged by the difference; a point it did not reach has material
// left standing up to where, out along its normal, the cutter's swept region begins. The span
// is judged at evenly spaced points, one every kJudgeStep inches of chord-wise parameter but
// never fewer than 8 nor more than `samples`, coarse to fine (the ends, the middle, the quarters
// ...): the deviation is the largest of them, whatever their order. A caller that only asks
// whether the span stays within `limit` is answered at the first point past it (the deviation
// returned then exceeds the limit, and is not the span's largest).
Deviation span_deviation(const Airfoil& airfoil, const TemplateOptions& o, const Track& track,
                         double wa, double wb, const Station& a, const Station& b, int samples = 16,
                         double limit = std::numeric_limits<double>::infinity()) {
    const Vector2d corner = corner_between(a, b);
    const double r = o.cutter_radius_in;
    auto dist = [&](const Vector2d& p) {
        return std::min(segment_distance(p, a.centre, corner),
                        segment_distance(p, corner, b.centre));
    };
    constexpr double kJudgeStep = 0.05 / 256; // the densest: 256 points in the widest span
    const double length = (b.work - a.work).norm() / o.chord_in;
    // Counted in double first: a span too long for an int (a chord of 1e300 in) is judged at
    // the most points, where the cast itself would be undefined.
    const double wanted = std::ceil(length / kJudgeStep);
    const int n =
        std::isnan(wanted) || wanted >= samples ? samples : std::max(8, static_cast<int>(wanted));
    Deviation d;
    auto judge = [&](int k) {
        const Station s = station_at(airfoil, o, track, wa + (wb - wa) * k / n);
        const double d0 = dist(s.work);
        if (d0 <= r) {
            d.gouge = std::max(d.gouge, r - d0);
        } else {
            const double t_max = 2 * r + d0;
            const double t =
                std::min(ray_enters_capsule(s.work, s.toward_cutter, a.centre, corner, r),
                         ray_enters_capsule(s.work, s.toward_cutter, corner, b.centre, r));
            d.leftover = std::max(d.leftover, std::min(t, t_max));
        }
        return std::max(d.leftover, d.gouge) <= limit;
    };
    // Point k is judged at the widest stride that divides it: each of 0 .. n once.
    int top = 1;
    while (top < n) {
        top *= 2;
    }
    for (int stride = top; stride >= 1; stride /= 2) {
        for (int k = 0; k <= n; k += stride) {
            if ((stride == top || (k / stride) % 2 == 1) && !judge(k)) {
                return d;
            }
        }
    }
    return d;
}

// The stations --stations asks for along the track (both surfaces: the leading edge once).
std::int64_t stations_asked(const TemplateOptions& o) {
    const std::int64_t n = o.stations;
    return o.surface == Surface::both ? 2 * n - 1 : n;
}

// Refuses, before a station is computed, a count that cannot make a deck: fewer than two, or
// more than a deck can number with the fewest approach cards.
void check_station_count(const TemplateOptions& o) {
    if (o.stations < 2) {
        throw JobError(fmt::format("--stations {}: need at least 2", o.stations));
    }
    const std::int64_t stations = stations_asked(o);
    refuse_past_deck_limit(
        kLeastApproachCards + stations - 1, fmt::format("--stations {}", o.stations), true,
        fmt::format("{} to approach the first of {} stations{}, then one to each of the others",
                    kLeastApproachCards, count_text(stations),
                    o.surface == Surface::both ? " round both surfaces" : ""));
}

std::vector<double> stations_by_count(const TemplateOptions& o, const Track& track) {
    std::vector<double> per_surface;
    for (int k = 0; k < o.stations; ++k) {
        const double f = static_cast<double>(k) / (o.stations - 1);
        per_surface.push_back(
            o.spacing == Spacing::uniform ? f : (1 - std::cos(std::numbers::pi * f)) / 2);
    }
    if (track.surface != Surface::both) {
        return per_surface;
    }
    // Both: the upper surface from TE to LE (w = 1 - u), then the lower without the LE again.
    std::vector<double> ws;
    for (auto it = per_surface.rbegin(); it != per_surface.rend(); ++it) {
        ws.push_back(1.0 - *it);
    }
    for (std::size_t k = 1; k < per_surface.size(); ++k) {
        ws.push_back(1.0 + per_surface[k]);
    }
    return ws;
}

// Stations as far apart as the scallop target allows, span by span.
std::vector<double> stations_by_scallop(const Airfoil& airfoil, const TemplateOptions& o,
                                        const Track& track) {
    constexpr double kMaxStep = 0.05;
    constexpr double kMinStep = 1e-4;
    std::vector<double> ws{0.0};
    double w = 0;
    Station a = station_at(airfoil, o, track, w);
    auto fits = [&](double step) {
        const double wb = std::min(track.end(), w + step);
        const Station b = station_at(airfoil, o, track, wb);
        const Deviation d = span_deviation(airfoil, o, track, w, wb, a, b, 256, o.scallop_in);
        return std::max(d.leftover, d.gouge) <= o.scallop_in;
    };
    while (w < track.end()) {
        double step = kMaxStep;
        if (!fits(step)) {
            double lo = kMinStep;
            double hi = kMaxStep;
            for (int i = 0; i < 30; ++i) {
                const double mid = (lo + hi) / 2;
                (fits(mid) ? lo : hi) = mid;
            }
            step = lo;
        }
        w = std::min(track.end(), w + step);
        if (track.end() - w < kMinStep) {
            w = track.end();
        }
        ws.push_back(w);
        // Refused as soon as the stations (at least one more to come) outnumber what a deck
        // can hold, before the rest of the path is computed.
        const auto stations = static_cast<std::int64_t>(ws.size());
        if (w < track.end() && kLeastApproachCards + stations > kMaxDeckCards) {
            refuse_past_deck_limit(
                kLeastApproachCards + stations, fmt::format("--scallop {}", o.scallop_in), true,
                fmt::format("{} stations so far to hold it, and {:.0f} % of the path still to go",
                            count_text(stations), 100 * (track.end() - w) / track.end()));
        }
        a = station_at(airfoil, o, track, w);
    }
    return ws;
}

cardreader::CardOrders idle_card(int number) {
    cardreader::CardOrders c;
    c.number = number % 10000;
    c.spindle = cardreader::Spindle::forward;
    for (cardreader::Axis a : cardreader::kAxes) {
        cardreader::AxisOrder& o = c.axis(a);
        o.start_speed = 3;
        o.stop = 0;
        o.check = 0;
    }
    c.axis(cardreader::Axis::vertical).sequence = 0b00001;
    c.axis(cardreader::Axis::swivel).sequence = 0b00010;
    c.axis(cardreader::Axis::tilt).sequence = 0b00100;
    return c;
}

struct CardMaker {
    const axes::MachineProfile& profile;
    std::vector<cardreader::CardOrders>& cards;
    int x = 0; // where the table and the cross slide stand, thousandths
    int y = 0;

    void move(int to_x, int to_y, bool table_first, bool corner) {
        cardreader::CardOrders c = idle_card(static_cast<int>(cards.size()) + 1);
        const cardreader::SequencePattern first = 0b01000;
        const cardreader::SequencePattern last = 0b10000;
        c.axis(cardreader::Axis::table) = plan_move(
            {x, to_x, 2, corner, table_first ? first : last}, profile.axes.at(0), profile);
        c.axis(cardreader::Axis::cross) = plan_move(
            {y, to_y, 1, corner, table_first ? last : first}, profile.axes.at(1), profile);
        cards.push_back(c);
        x = to_x;
        y = to_y;
    }
};

// The cutter cannot reach into a hollow tighter than itself: where the surface curves toward
// the cutter (concave, seen from the cutter) with a radius smaller than the cutter's, any deck
// would gouge. Refuse such a job, naming where and how tight.
void check_cutter_fits(const Airfoil& airfoil, const TemplateOptions& o, const Track& track) {
    constexpr int kSamples = 4000;
    constexpr int kGap = 3; // points between the three used for each circle, against noise
    std::vector<Station> pts;
    for (int k = 0; k <= kSamples; ++k) {
        const double f = static_cast<double>(k) / kSamples * track.end();
        const double whole = std::floor(std::min(f, track.end() - 1e-12));
        pts.push_back(station_at(airfoil, o, track,
                                 whole + (1 - std::cos(std::numbers::pi * (f - whole))) / 2));
    }
    double tightest = std::numeric_limits<double>::infinity(); // no hollow: any cutter fits
    Vector2d where = Vector2d::Zero();
    for (std::size_t i = kGap; i + kGap < pts.size(); ++i) {
        const Vector2d& p0 = pts[i - kGap].work;
        const Vector2d& p1 = pts[i].work;
        const Vector2d& p2 = pts[i + kGap].work;
        const Vector2d a = p1 - p0;
        const Vector2d b = p2 - p1;
        const double cross = a.x() * b.y() - a.y() * b.x();
        if (std::abs(cross) < 1e-15) {
            continue;
        }
        const bool concave = ((p0 + p2) / 2 - p1).dot(pts[i].toward_cutter) > 0;
        const double radius = a.norm() * b.norm() * (p2 - p0).norm() / (2 * std::abs(cross));
        if (concave && radius < tightest) {
            tightest = radius;
            where = p1;
        }
    }
    if (tightest < o.cutter_radius_in) {
        throw JobError(fmt::format("the cutter (radius {:.4f} in) cannot reach into the surface "
                                   "where it curves round toward the cutter with a radius of "
                                   "{:.4f} in (at x = {:.3f} in from the leading edge): every "
                                   "deck would gouge there; use a cutter of radius under "
                                   "{:.4f} in",
                                   o.cutter_radius_in, tightest,
                                   std::abs(where.x()) < 0.0005 ? 0.0 : where.x(), tightest));
    }
}

// Where a point of the work stands on the counters, thousandths (table, cross).
std::pair<int, int> machine_at(const Vector2d& p, const Vector2d& work_zero_in) {
    const Vector2d m = p + work_zero_in;
    return {thousandths(m.x()), thousandths(m.y())};
}

// Where one card takes the table and the cross slide, and which of them goes first.
struct Target {
    int x = 0;
    int y = 0;
    bool table_first = false;
};

// The approach from the reference zero (below and left of the whole job, whose cutter centres
// lie within lo .. hi) to the first station. The last stretch comes in along the first
// station's own normal, from a point A a little way out on the cutter's side, by a staircase
// whose corner is on the cutter's side (so the cutter never passes nearer the surface than R:
// a cambered nose tilts its normal away from the horizontal, and a plain vertical drop would
// graze it). A is reached from the reference zero from the left when A lies left of the whole
// job, otherwise over the top (the cutter works above the surface) or from underneath (it
// works below). Three cards, or four over the top (kLeastApproachCards).
std::vector<Target> approach_targets(const TemplateDeck& deck, const TemplateOptions& o,
                                     const Vector2d& lo, const Vector2d& hi) {
    const Station& first = deck.stations.front();
    const Vector2d out = first.centre + (o.margin_in / 2) * first.toward_cutter;
    const auto [ax, ay] = machine_at(out, deck.work_zero_in);
    double side = 0;
    for (const Station& s : deck.stations) {
        side += s.toward_cutter.y();
    }
    std::vector<Target> to;
    if (out.x() < lo.x()) { // A left of the job
        to = {{0, ay, false}, {ax, ay, true}};
    } else if (o.surface == Surface::both || side >= 0) {
        const int top = thousandths(hi.y() + deck.work_zero_in.y() + o.margin_in / 2);
        to = {{0, top, false}, {ax, top, true}, {ax, ay, false}};
    } else {
        to = {{ax, 0, true}, {ax, ay, false}};
    }
    Station approach = first;
    approach.centre = out;
    const Vector2d last_corner = corner_between(approach, first);
    const auto [fx, fy] = machine_at(first.centre, deck.work_zero_in);
    to.push_back({fx, fy, last_corner.y() == approach.centre.y()});
    return to;
}

} // namespace

TemplateDeck make_template_deck(const Airfoil& airfoil, const TemplateOptions& o,
                                const axes::MachineProfile& profile) {
    if (o.female && o.surface == Surface::both) {
        throw JobError("a female template is the edge of a plate: cut one surface at a time "
                       "(--surface upper or lower)");
    }
    refuse_unless_shape("--chord", o.chord_in, "chord");
    refuse_unless_cutter("--cutter-radius", o.cutter_radius_in);
    refuse_unless_finite("--scallop", o.scallop_in);
    if (!(o.scallop_in > 0)) {
        check_station_count(o);
    }
    const Track track = make_track(airfoil, o.surface);
    check_cutter_fits(airfoil, o, track);
    const std::vector<double> ws =
        o.scallop_in > 0 ? stations_by_scallop(airfoil, o, track) : stations_by_count(o, track);

    TemplateDeck deck;
    for (double w : ws) {
        deck.stations.push_back(station_at(airfoil, o, track, w));
    }
    for (std::size_t i = 0; i + 1 < ws.size(); ++i) {
        const Deviation d = span_deviation(airfoil, o, track, ws[i], ws[i + 1], deck.stations[i],
                                           deck.stations[i + 1], 256); // dense: the figure reported
        deck.planned_leftover_in = std::max(deck.planned_leftover_in, d.leftover);
        deck.planned_gouge_in = std::max(deck.planned_gouge_in, d.gouge);
    }

    // Work zero: the job margin_in inside the counters' 0 .. 9.999 in.
    Vector2d lo(1e9, 1e9);
    Vector2d hi(-1e9, -1e9);
    for (const Station& s : deck.stations) {
        lo = lo.cwiseMin(s.centre);
        hi = hi.cwiseMax(s.centre);
    }
    deck.work_zero_in = Vector2d(o.margin_in, o.margin_in) - lo;
    const Vector2d extent = hi - lo;
    const double room = 9.999 - 2 * o.margin_in;
    if (extent.x() > room || extent.y() > room) {
        throw JobError(fmt::format("the cutter path spans {} x {} in, more than the {:.3f} in the "
                                   "four-digit counters leave inside a {:.3f} in margin: use a "
                                   "shorter chord",
                                   fixed(extent.x()), fixed(extent.y()), room, o.margin_in));
    }
    auto machine = [&](const Vector2d& p) { return machine_at(p, deck.work_zero_in); };

    const std::vector<Target> approach = approach_targets(deck, o, lo, hi);
    // Every card counted before one is made: the approach, and one from each station to the
    // next.
    const auto approach_cards = static_cast<std::int64_t>(approach.size());
    const auto spans = static_cast<std::int64_t>(deck.stations.size()) - 1;
    refuse_past_deck_limit(approach_cards + spans,
                           o.scallop_in > 0 ? fmt::format("--scallop {}", o.scallop_in)
                                            : fmt::format("--stations {}", o.stations),
                           false,
                           fmt::format("{} to approach, {} from station to station", approach_cards,
                                       count_text(spans)));

    CardMaker maker{profile, deck.cards};
    for (const Target& t : approach) {
        maker.move(t.x, t.y, t.table_first, false);
    }
    const double limit = o.corner_limit_deg * std::numbers::pi / 180;
    for (std::size_t i = 1; i < deck.stations.size(); ++i) {
        const Station& a = deck.stations[i - 1];
        const Station& b = deck.stations[i];
        bool corner = false;
        if (o.corner_slowdown && i + 1 < deck.stations.size()) {
            const Vector2d d1 = b.centre - a.centre;
            const Vector2d d2 = deck.stations[i + 1].centre - b.centre;
            if (d1.norm() > 0 && d2.norm() > 0) {
                const double turn =
                    std::acos(std::clamp(d1.dot(d2) / (d1.norm() * d2.norm()), -1.0, 1.0));
                corner = turn > limit;
            }
        }
        deck.corner_cards += corner ? 1 : 0;
        const Vector2d c = corner_between(a, b);
        const bool table_first = c.y() == a.centre.y();
        const auto [bx, by] = machine(b.centre);
        maker.move(bx, by, table_first, corner);
    }
    return deck;
}

DesignSamples design_samples(const Airfoil& airfoil, const TemplateOptions& o,
                             const Eigen::Vector2d& work_zero_in, int per_surface) {
    const Track track = make_track(airfoil, o.surface);
    DesignSamples out;
    const int n = per_surface * static_cast<int>(track.end());
    for (int k = 0; k <= n; ++k) {
        // Cosine spacing within each surface: dense at both ends, where the surface bends most.
        const double f = static_cast<double>(k) / per_surface;
        const double whole = std::floor(std::min(f, track.end() - 1e-12));
        const double frac = f - whole;
        const double w = whole + (1 - std::cos(std::numbers::pi * frac)) / 2;
        const Station s = station_at(airfoil, o, track, std::min(w, track.end()));
        out.points.push_back(s.work + work_zero_in);
        out.toward_cutter.push_back(s.toward_cutter);
    }
    return out;
}

} // namespace parsons::decks
