// A screw's error table: how far the thing a screw drives stands from where a perfect screw
// would put it, as (position, error) pairs in inches, interpolated linearly between them and
// held at the end values beyond. Used for lead screw 22's lead error, instrument shaft 74's
// own error and the correction cam 160 gives (axes/lead_screw_nut.hpp,
// axes/instrument_shaft.hpp).
//
// How we represent it: y = x + e(x) must rise with x (the profile refuses a table that does
// not), so it has an inverse, also piecewise linear. Tables add: the sum of several, weighted,
// is one table on the union of their positions, exact at each position.
#pragma once

#include <algorithm>
#include <initializer_list>
#include <optional>
#include <utility>
#include <vector>

namespace parsons::axes {

using ErrorPoints = std::vector<std::pair<double, double>>;

class ScrewErrorTable {
public:
    ScrewErrorTable() = default;
    explicit ScrewErrorTable(ErrorPoints points) : points_(std::move(points)) {}

    // sum({{&a, 1}, {&b, -1}}): a - b on the union of their positions.
    static ScrewErrorTable sum(std::initializer_list<std::pair<const ErrorPoints*, double>> terms) {
        std::vector<double> xs;
        const ErrorPoints* only = nullptr;
        int nonempty = 0;
        for (const auto& [points, weight] : terms) {
            if (!points->empty()) {
                ++nonempty;
                only = weight == 1 ? points : nullptr;
            }
        }
        if (nonempty == 1 && only != nullptr) {
            return ScrewErrorTable(*only); // one table as it stands, to the last bit
        }
        for (const auto& [points, weight] : terms) {
            for (const auto& p : *points) {
                xs.push_back(p.first);
            }
        }
        std::sort(xs.begin(), xs.end());
        xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
        ErrorPoints out;
        for (double x : xs) {
            double e = 0;
            for (const auto& [points, weight] : terms) {
                if (!points->empty()) {
                    e += weight * ScrewErrorTable(*points).error_at(x);
                }
            }
            out.emplace_back(x, e);
        }
        return ScrewErrorTable(std::move(out));
    }

    bool empty() const { return points_.empty(); }
    const ErrorPoints& points() const { return points_; }

    // e(x), exact at each position of the table.
    double error_at(double x) const {
        if (points_.empty()) {
            return 0;
        }
        if (x <= points_.front().first) {
            return points_.front().second;
        }
        if (x >= points_.back().first) {
            return points_.back().second;
        }
        auto it = std::upper_bound(points_.begin(), points_.end(), x,
                                   [](double v, const auto& p) { return v < p.first; });
        const auto& [x1, e1] = *it;
        const auto& [x0, e0] = *(it - 1);
        return e0 + (e1 - e0) * (x - x0) / (x1 - x0);
    }

    // x + e(x).
    double apply(double x) const {
        if (points_.empty()) {
            return x;
        }
        if (x <= points_.front().first) {
            return x + points_.front().second;
        }
        if (x >= points_.back().first) {
            return x + points_.back().second;
        }
        auto it = std::upper_bound(points_.begin(), points_.end(), x,
                                   [](double v, const auto& p) { return v < p.first; });
        const auto& [x1, e1] = *it;
        const auto& [x0, e0] = *(it - 1);
        return x + e0 + (e1 - e0) * (x - x0) / (x1 - x0);
    }

    // The x with x + e(x) = y.
    double invert(double y) const {
        if (points_.empty()) {
            return y;
        }
        const auto& [xf, ef] = points_.front();
        if (y <= xf + ef) {
            return y - ef;
        }
        const auto& [xb, eb] = points_.back();
        if (y >= xb + eb) {
            return y - eb;
        }
        auto it = std::upper_bound(points_.begin(), points_.end(), y,
                                   [](double v, const auto& p) { return v < p.first + p.second; });
        const auto& [x1, e1] = *it;
        const auto& [x0, e0] = *(it - 1);
        return x0 + (y - (x0 + e0)) * (x1 - x0) / ((x1 + e1) - (x0 + e0));
    }

    // The least and the greatest slope of x + e(x) over the whole line (1 beyond the ends, and
    // everywhere for an empty table): how much faster or slower than the screw the driven
    // thing can move.
    std::pair<double, double> slope_range() const {
        double least = 1;
        double greatest = 1;
        for (std::size_t i = 1; i < points_.size(); ++i) {
            const auto& [x0, e0] = points_.at(i - 1);
            const auto& [x1, e1] = points_.at(i);
            const double slope = ((x1 + e1) - (x0 + e0)) / (x1 - x0);
            least = std::min(least, slope);
            greatest = std::max(greatest, slope);
        }
        return {least, greatest};
    }
    // The first position after which x + e(x) does not rise, if any.
    std::optional<double> falls_after() const {
        for (std::size_t i = 1; i < points_.size(); ++i) {
            const auto& [x0, e0] = points_.at(i - 1);
            const auto& [x1, e1] = points_.at(i);
            if ((x1 + e1) - (x0 + e0) <= 0) {
                return x0;
            }
        }
        return std::nullopt;
    }

private:
    ErrorPoints points_;
};

} // namespace parsons::axes
