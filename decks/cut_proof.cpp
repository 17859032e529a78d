#include "decks/cut_proof.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>

namespace parsons::decks {
namespace {

using Eigen::Vector2d;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kMergeTolerance_in = 1e-9; // collinear runs of the recorded path
constexpr std::size_t kMaxCells = 4'000'000;

double segment_distance_sq(const Vector2d& p, const Vector2d& a, const Vector2d& b) {
    const Vector2d ab = b - a;
    const double len_sq = ab.squaredNorm();
    const double s = len_sq > 0 ? std::clamp((p - a).dot(ab) / len_sq, 0.0, 1.0) : 0.0;
    return (a + s * ab - p).squaredNorm();
}

// An interval of the line parameter t; empty when lo > hi.
struct Interval {
    double lo = kInf;
    double hi = -kInf;
    bool empty() const { return lo > hi; }
};

// One straight run of the path: from a, along the unit vector u, for len inches. A run of length
// 0 stands for the path's last point, so that every vertex of the path starts exactly one run.
struct Run {
    Vector2d a;
    Vector2d u;
    double len = 0;
    Vector2d b() const { return a + len * u; }
};

std::vector<Run> make_runs(const std::vector<Vector2d>& pts) {
    std::vector<Run> runs;
    runs.reserve(pts.size());
    for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
        const Vector2d d = pts[k + 1] - pts[k];
        const double len = d.norm();
        runs.push_back({pts[k], len > 0 ? Vector2d(d / len) : Vector2d::Zero(), len});
    }
    runs.push_back({pts.back(), Vector2d::Zero(), 0});
    return runs;
}

// The t for which |p + t n - c| <= r (n a unit vector), with the numerically stable root
// formula so that shallow cusps (t near 0) keep their digits.
Interval disk_interval(const Vector2d& p, const Vector2d& n, const Vector2d& c, double r) {
    const Vector2d q = p - c;
    const double b = n.dot(q);
    const double k = q.squaredNorm() - r * r;
    const double disc = b * b - k;
    if (disc < 0) {
        return {};
    }
    const double root = std::sqrt(disc);
    const double big = b >= 0 ? -b - root : -b + root; // the root of larger magnitude
    if (big == 0) {
        return {0, 0};
    }
    const double small = k / big;
    return {std::min(big, small), std::max(big, small)};
}

// Clips t so that lo <= v0 + t dv <= hi (Liang-Barsky, one slab).
void clip_slab(Interval& iv, double v0, double dv, double lo, double hi) {
    if (dv == 0) {
        if (v0 < lo || v0 > hi) {
            iv = {};
        }
        return;
    }
    const double inv = 1 / dv;
    const double t1 = (lo - v0) * inv;
    const double t2 = (hi - v0) * inv;
    iv.lo = std::max(iv.lo, std::min(t1, t2));
    iv.hi = std::min(iv.hi, std::max(t1, t2));
}

// The t for which p + t n lies in the run's rectangle (its capsule without the end caps).
Interval rectangle_interval(const Vector2d& p, const Vector2d& n, const Run& run, double r) {
    if (run.len == 0) {
        return {};
    }
    const Vector2d q = p - run.a;
    const Vector2d v(-run.u.y(), run.u.x());
    Interval iv{-kInf, kInf};
    clip_slab(iv, q.dot(run.u), n.dot(run.u), 0, run.len);
    clip_slab(iv, q.dot(v), n.dot(v), -r, r);
    return iv;
}

// The path's runs bucketed in a uniform grid of square cells. A run is listed in every cell
// that a piece of it (cut into lengths of at most one cell) touches with its bounding box, so a
// box query finds every run that passes through the box.
class RunGrid {
public:
    RunGrid(std::vector<Run> runs, double cell_in) : runs_(std::move(runs)) {
        lo_ = hi_ = runs_.front().a;
        for (const Run& run : runs_) {
            lo_ = lo_.cwiseMin(run.a);
            hi_ = hi_.cwiseMax(run.a);
        }
        const Vector2d size = hi_ - lo_;
        cell_ = cell_in;
        while ((size.x() / cell_ + 1) * (size.y() / cell_ + 1) > double(kMaxCells)) {
            cell_ *= 2;
        }
        nx_ = static_cast<int>(size.x() / cell_) + 1;
        ny_ = static_cast<int>(size.y() / cell_) + 1;
        build();
        stamp_.assign(runs_.size(), 0);
    }

    const Run& run(std::size_t k) const { return runs_[k]; }
    double cell() const { return cell_; }

    // Calls f(index, run) once for each run listed in a cell that overlaps [lo, hi] and for which
    // keep_cell(cell centre) is true.
    template <class KeepCell, class F>
    void visit(const Vector2d& lo, const Vector2d& hi, KeepCell keep_cell, F f) {
        const auto [i0, j0] = cell_of(lo);
        const auto [i1, j1] = cell_of(hi);
        ++query_;
        for (int j = j0; j <= j1; ++j) {
            for (int i = i0; i <= i1; ++i) {
                const std::size_t c = index(i, j);
                if (start_[c] == start_[c + 1] ||
                    !keep_cell(lo_ + cell_ * Vector2d(i + 0.5, j + 0.5))) {
                    continue;
                }
                for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
                    const std::uint32_t s = entries_[k];
                    if (stamp_[s] != query_) {
                        stamp_[s] = query_;
                        f(s, runs_[s]);
                    }
                }
            }
        }
    }

private:
    std::pair<int, int> cell_of(const Vector2d& q) const {
        const auto clampi = [](double v, int n) {
            return static_cast<int>(std::clamp(std::floor(v), 0.0, double(n - 1)));
        };
        return {clampi((q.x() - lo_.x()) / cell_, nx_), clampi((q.y() - lo_.y()) / cell_, ny_)};
    }
    std::size_t index(int i, int j) const { return std::size_t(j) * std::size_t(nx_) + i; }

    // Calls f(cell) for the cells the bounding boxes of the pieces of run k touch.
    template <class F>
    void for_cells(std::size_t k, F f) const {
        const Run& run = runs_[k];
        const int pieces = 1 + static_cast<int>(run.len / cell_);
        for (int m = 0; m < pieces; ++m) {
            const Vector2d p0 = run.a + run.u * (run.len * m / pieces);
            const Vector2d p1 = run.a + run.u * (run.len * (m + 1) / pieces);
            const auto [i0, j0] = cell_of(p0.cwiseMin(p1));
            const auto [i1, j1] = cell_of(p0.cwiseMax(p1));
            for (int j = j0; j <= j1; ++j) {
                for (int i = i0; i <= i1; ++i) {
                    f(index(i, j));
                }
            }
        }
    }

    // Two passes over the runs: count the entries of each cell, then fill them (CSR).
    void build() {
        const std::size_t cells = std::size_t(nx_) * std::size_t(ny_);
        constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
        std::vector<std::uint32_t> last(cells, kNone); // a run's pieces may share a cell
        start_.assign(cells + 1, 0);
        for (std::size_t k = 0; k < runs_.size(); ++k) {
            for_cells(k, [&](std::size_t c) {
                if (last[c] != k) {
                    last[c] = static_cast<std::uint32_t>(k);
                    ++start_[c + 1];
                }
            });
        }
        for (std::size_t c = 0; c < cells; ++c) {
            start_[c + 1] += start_[c];
        }
        entries_.resize(start_[cells]);
        std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
        std::fill(last.begin(), last.end(), kNone);
        for (std::size_t k = 0; k < runs_.size(); ++k) {
            for_cells(k, [&](std::size_t c) {
                if (last[c] != k) {
                    last[c] = static_cast<std::uint32_t>(k);
                    entries_[fill[c]++] = static_cast<std::uint32_t>(k);
                }
            });
        }
    }

    std::vector<Run> runs_;
    Vector2d lo_, hi_;
    double cell_ = 1;
    int nx_ = 1, ny_ = 1;
    std::vector<std::uint32_t> start_;   // cell c lists entries_[start_[c] .. start_[c+1])
    std::vector<std::uint32_t> entries_; // run indices
    std::vector<std::uint32_t> stamp_;   // the last query that reported each run
    std::uint32_t query_ = 0;
};

// One design point against the swept region, in two looks along its normal: first close by
// (t in [-R, R/4]: is p cut, and how deep; or is there a cut just above it), then, for a point
// left standing with nothing close above it, farther out (t up to reach + R). Most points are
// settled by the first look, which only meets the runs of the finishing cut.
class Prover {
public:
    Prover(const std::vector<Vector2d>& path, double radius_in, double reach_in)
        : r_(radius_in), reach_(reach_in), grid_(make_runs(path), radius_in / 4) {}

    double deviation(const Vector2d& p, const Vector2d& n) {
        const double near_top = r_ / 4;
        gather(p, n, -r_, near_top);
        bool covered = false;
        double first_above = kInf; // the lowest cut above p
        for (const Interval& iv : hits_) {
            covered = covered || (iv.lo <= 0 && iv.hi >= 0);
            if (iv.lo > 0) {
                first_above = std::min(first_above, iv.lo);
            }
        }
        if (covered) {
            return r_ <= reach_ || within_reach(p) ? cut_floor() : kNaN;
        }
        if (!within_reach(p)) {
            return kNaN;
        }
        if (first_above == kInf) {
            gather(p, n, near_top, reach_ + r_);
            for (const Interval& iv : hits_) {
                first_above = std::min(first_above, iv.lo);
            }
        }
        return first_above == kInf ? kNaN : first_above;
    }

private:
    // hits_ = the t intervals, clipped to [t_lo, t_hi], of the rectangles and start disks of
    // every run near the piece of normal line. Together they make up the swept region there.
    void gather(const Vector2d& p, const Vector2d& n, double t_lo, double t_hi) {
        hits_.clear();
        const Vector2d e0 = p + t_lo * n;
        const Vector2d e1 = p + t_hi * n;
        const Vector2d pad = Vector2d::Constant(r_);
        const double keep_sq = std::pow(r_ + grid_.cell() * 0.7072, 2);
        const auto add = [&](Interval iv) {
            iv.lo = std::max(iv.lo, t_lo);
            iv.hi = std::min(iv.hi, t_hi);
            if (!iv.empty()) {
                hits_.push_back(iv);
            }
        };
        grid_.visit(
            e0.cwiseMin(e1) - pad, e0.cwiseMax(e1) + pad,
            [&](const Vector2d& centre) { return segment_distance_sq(centre, e0, e1) <= keep_sq; },
            [&](std::size_t, const Run& run) {
                add(rectangle_interval(p, n, run, r_));
                add(disk_interval(p, n, run.a, r_));
            });
    }

    // The lower end of the covered stretch that contains t = 0 (no deeper than the window):
    // lowered by every interval that reaches it until none does. Overlapping cuts settle this in
    // two or three sweeps; a long chain of them falls back to one sort.
    double cut_floor() {
        double floor = 0;
        for (int sweep = 0; sweep < 4; ++sweep) {
            const double before = floor;
            for (const Interval& iv : hits_) {
                if (iv.lo < floor && iv.hi >= floor) {
                    floor = iv.lo;
                }
            }
            if (floor == before) {
                return floor < 0 ? floor : 0.0; // never -0
            }
        }
        std::sort(hits_.begin(), hits_.end(),
                  [](const Interval& x, const Interval& y) { return x.hi > y.hi; });
        for (const Interval& iv : hits_) {
            if (iv.hi < floor) {
                break;
            }
            floor = std::min(floor, iv.lo);
        }
        return floor;
    }

    bool within_reach(const Vector2d& p) {
        const double reach_sq = reach_ * reach_;
        bool found = false;
        const Vector2d pad = Vector2d::Constant(reach_);
        grid_.visit(
            p - pad, p + pad, [&](const Vector2d&) { return !found; },
            [&](std::size_t, const Run& run) {
                found = found || segment_distance_sq(p, run.a, run.b()) <= reach_sq;
            });
        return found;
    }

    double r_;
    double reach_;
    RunGrid grid_;
    std::vector<Interval> hits_;
};

// The design contour as material: how far the line p - s n runs inside the material from
// design point i before it comes out through the design contour again (at a thin trailing edge,
// through the other surface). A gouge is measured inside the material only, so a cut that goes
// right through a thin part reports the part's thickness there, not the depth of the cutter.
// Emulation note: the contour is taken as one polyline in order; a point that coincides with a
// point elsewhere on it (the trailing edge where the surfaces meet) has thickness 0.
class Material {
public:
    Material(const std::vector<Vector2d>& points, double cell_in)
        : grid_(make_runs(points), cell_in) {}

    // The first s in [0, depth] where p - s n crosses a run of the contour that does not start
    // or end at point i; depth when there is none.
    double thickness(std::size_t i, const Vector2d& p, const Vector2d& n, double depth) {
        const Vector2d e1 = p - depth * n;
        const double keep_sq = std::pow(grid_.cell() * 0.7072, 2);
        double first = depth;
        grid_.visit(
            p.cwiseMin(e1), p.cwiseMax(e1),
            [&](const Vector2d& centre) { return segment_distance_sq(centre, p, e1) <= keep_sq; },
            [&](std::size_t k, const Run& run) {
                const double det = cross(n, run.u);
                if (k + 1 == i || k == i || run.len == 0) {
                    return;
                }
                // Another stretch of the contour that starts or ends at p itself (the seam of
                // a closed contour, where the two surfaces meet at a sharp trailing edge, up to
                // the rounding of the fit): there is no material between them.
                if ((run.a - p).squaredNorm() < kSeam * kSeam ||
                    (run.a + run.len * run.u - p).squaredNorm() < kSeam * kSeam) {
                    first = 0;
                    return;
                }
                if (det == 0) {
                    return;
                }
                const Vector2d d = run.a - p;
                const double s = -cross(d, run.u) / det;
                const double along = cross(d, n) / det;
                if (s >= 0 && s < first && along >= -kTouch && along <= run.len + kTouch) {
                    first = s;
                }
            });
        return first;
    }

private:
    static constexpr double kTouch = 1e-12;
    static constexpr double kSeam = 1e-9; // inches
    static double cross(const Vector2d& x, const Vector2d& y) {
        return x.x() * y.y() - x.y() * y.x();
    }
    RunGrid grid_;
};

} // namespace

// Cusps: local maxima of the deviation with strictly lower deviation on both sides, inside one
// machined stretch (equal neighbours form a plateau that is judged as one).
double max_cusp(const std::vector<double>& dev) {
    double best = 0;
    std::size_t i = 0;
    while (i < dev.size()) {
        if (std::isnan(dev[i])) {
            ++i;
            continue;
        }
        std::size_t end = i; // one past the machined stretch starting at i
        while (end < dev.size() && !std::isnan(dev[end])) {
            ++end;
        }
        std::vector<double> levels; // the stretch with plateaus folded
        for (std::size_t k = i; k < end; ++k) {
            if (levels.empty() || levels.back() != dev[k]) {
                levels.push_back(dev[k]);
            }
        }
        for (std::size_t k = 1; k + 1 < levels.size(); ++k) {
            if (levels[k] > levels[k - 1] && levels[k] > levels[k + 1]) {
                best = std::max(best, levels[k]);
            }
        }
        i = end;
    }
    return best;
}

std::vector<Vector2d> simplify_path(const std::vector<Vector2d>& path, double tolerance_in) {
    if (path.size() <= 2) {
        return path;
    }
    const double tol_sq = tolerance_in * tolerance_in;
    std::vector<char> keep(path.size(), 0);
    keep.front() = keep.back() = 1;
    std::vector<std::pair<std::size_t, std::size_t>> stack{{0, path.size() - 1}};
    while (!stack.empty()) {
        const auto [first, last] = stack.back();
        stack.pop_back();
        double worst = -1;
        std::size_t worst_at = first;
        for (std::size_t k = first + 1; k < last; ++k) {
            const double d = segment_distance_sq(path[k], path[first], path[last]);
            if (d > worst) {
                worst = d;
                worst_at = k;
            }
        }
        if (worst > tol_sq) {
            keep[worst_at] = 1;
            stack.emplace_back(first, worst_at);
            stack.emplace_back(worst_at, last);
        }
    }
    std::vector<Vector2d> out;
    for (std::size_t k = 0; k < path.size(); ++k) {
        if (keep[k]) {
            out.push_back(path[k]);
        }
    }
    return out;
}

CutProof prove_cut(const std::vector<Vector2d>& path, double radius_in, const DesignContour& design,
                   double reach_in) {
    if (!(radius_in > 0) || !(reach_in > 0)) {
        throw std::invalid_argument("prove_cut: cutter radius and reach must be positive");
    }
    if (design.points.size() != design.normals.size()) {
        throw std::invalid_argument("prove_cut: the design needs one normal per point");
    }
    CutProof proof;
    const std::size_t n = design.points.size();
    proof.deviation_in.assign(n, kNaN);
    proof.cut_contour.assign(n, Vector2d::Constant(kNaN));
    if (path.empty() || n == 0) {
        return proof;
    }
    Prover prover(simplify_path(path, kMergeTolerance_in), radius_in, reach_in);
    Material material(design.points, radius_in / 4);
    for (std::size_t i = 0; i < n; ++i) {
        const Vector2d& p = design.points[i];
        const Vector2d normal = design.normals[i].normalized();
        double dev = prover.deviation(p, normal);
        if (dev < 0) {
            const double depth = material.thickness(i, p, normal, -dev);
            dev = depth > 0 ? -depth : 0.0;
        }
        proof.deviation_in[i] = dev;
        if (std::isnan(dev)) {
            continue;
        }
        ++proof.machined_points;
        proof.cut_contour[i] = p + dev * normal;
        proof.max_gouge_in = std::max(proof.max_gouge_in, -dev);
        proof.max_leftover_in = std::max(proof.max_leftover_in, dev);
    }
    proof.max_scallop_in = max_cusp(proof.deviation_in);
    return proof;
}

} // namespace parsons::decks
