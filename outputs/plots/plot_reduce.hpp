// What the chart of run --plot does alike for the lead-screw panels (plot_svg.cpp,
// plot_chart.cpp) and the lanes of the additions under them (plot_press.cpp, plot_spindle.cpp):
// the "M4" reduction's time buckets (a sample folded in, the widening, the points kept), one
// signal kept that way (ReducedLine), and the intervals in which a 0/1 step signal is on.
// Templates, so each keeps its own point and bucket types (plot_svg.hpp, plot_press.hpp,
// plot_spindle.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace parsons::cli::plot {

// Folds sample p into the buckets of width bucket_s: the last bucket's last, lowest or highest
// point, or the first point of a new bucket (returns true then).
template <class Bucket, class Point>
bool add_to_buckets(std::vector<Bucket>& buckets, const Point& p, double bucket_s) {
    const std::int64_t slot = static_cast<std::int64_t>(std::floor(p.t / bucket_s));
    if (buckets.empty() || slot != buckets.back().slot) {
        buckets.push_back(Bucket{slot, p, p, p, p});
        return true;
    }
    Bucket& b = buckets.back();
    b.last = p;
    if (p.x < b.low.x) {
        b.low = p;
    }
    if (p.x > b.high.x) {
        b.high = p;
    }
    return false;
}

// The points the buckets keep, in time order, no point twice in a row.
template <class Point, class Bucket>
std::vector<Point> bucket_points(const std::vector<Bucket>& buckets) {
    std::vector<Point> out;
    out.reserve(buckets.size() * 4);
    for (const Bucket& b : buckets) {
        std::array<Point, 4> four = {b.first, b.low, b.high, b.last};
        std::stable_sort(four.begin(), four.end(),
                         [](const Point& p, const Point& q) { return p.t < q.t; });
        for (const Point& p : four) {
            if (out.empty() || out.back().t != p.t || out.back().x != p.x) {
                out.push_back(p);
            }
        }
    }
    return out;
}

// The buckets merged for a bucket width twice the one they were filled with (bucket_s is the
// new, doubled width): neighbours that now share a slot become one bucket that keeps the first
// bucket's first point, the last one's last point, and the lowest and highest points of all
// (the earlier of equal ones). Bucket has `long slot` and points `first`, `low`, `high` and
// `last`, each with a time `t` (seconds) and a value `x`.
template <class Bucket>
std::vector<Bucket> widened(const std::vector<Bucket>& buckets, double bucket_s) {
    std::vector<Bucket> merged;
    merged.reserve(buckets.size() / 2 + 1);
    for (const Bucket& b : buckets) {
        const std::int64_t slot = static_cast<std::int64_t>(std::floor(b.first.t / bucket_s));
        if (merged.empty() || merged.back().slot != slot) {
            Bucket m = b;
            m.slot = slot;
            merged.push_back(m);
            continue;
        }
        Bucket& m = merged.back();
        m.last = b.last;
        if (b.low.x < m.low.x) {
            m.low = b.low;
        }
        if (b.high.x > m.high.x) {
            m.high = b.high;
        }
    }
    return merged;
}

// One signal of a lane kept as a line: the M4 reduction, with buckets of its own that widen by
// themselves (a press or a spindle turns while the axes stand, so it cannot wait for theirs).
// Memory stays under 4 * kMaxBuckets points whatever the run's length. Point has a time `t`
// (seconds) and a value `x`.
template <class Point>
class ReducedLine {
public:
    static constexpr std::size_t kMaxBuckets = 1000;

    void add(Point p) {
        latest_ = p;
        if (add_to_buckets(buckets_, p, bucket_s_) && buckets_.size() > kMaxBuckets) {
            bucket_s_ *= 2;
            buckets_ = widened(buckets_, bucket_s_);
        }
    }
    std::vector<Point> points() const { return bucket_points<Point>(buckets_); } // time order
    std::optional<Point> latest() const { return latest_; }
    // The run ended at `seconds`: the line as it stands to the end.
    void hold_to(double seconds) {
        if (latest_ && seconds > latest_->t) {
            add(Point{seconds, latest_->x});
        }
    }

private:
    struct Bucket {
        std::int64_t slot = 0;
        Point first, low, high, last;
    };
    std::vector<Bucket> buckets_;
    std::optional<Point> latest_;
    double bucket_s_ = 1.0 / 64;
};

// The intervals in which a 0/1 step signal (its value at t = 0, then every change: points with
// a time `t` and a value `x`) is 1; one still on at the end is open until t_end.
template <class Point>
std::vector<std::pair<double, double>> on_intervals(const std::vector<Point>& steps, double t_end) {
    std::vector<std::pair<double, double>> out;
    bool on = false;
    double since = 0;
    for (const Point& s : steps) {
        if (s.x != 0 && !on) {
            on = true;
            since = s.t;
        } else if (s.x == 0 && on) {
            out.emplace_back(since, s.t);
            on = false;
        }
    }
    if (on) {
        out.emplace_back(since, t_end);
    }
    return out;
}

} // namespace parsons::cli::plot
