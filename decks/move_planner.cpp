#include "decks/move_planner.hpp"
#include "decks/units.hpp"

#include "cardreader/deck_review.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace parsons::decks {
namespace {

constexpr double kHalfThousandth = 0.0005;
constexpr int kMaxNudge = 60; // thousandths a slow-down may be moved to avoid a hazard

cardreader::Thousandths th(int v) {
    return static_cast<cardreader::Thousandths>(v);
}

} // namespace

int slow_down_room(const axes::AxisProfile& axis, int from, int to) {
    const double v = speed_in_per_s(axis, from);
    const double w = speed_in_per_s(axis, to);
    const double inches = (v * v - w * w) / (2 * axis.acceleration_in_per_s2);
    return static_cast<int>(std::ceil(1.5 * inches * 1000)) + 2;
}

cardreader::AxisOrder plan_move(const MoveRequest& move, const axes::AxisProfile& axis,
                                const axes::MachineProfile& profile) {
    const double v3 = speed_in_per_s(axis, 3);
    const double coast = v3 * v3 / (2 * axis.braking_in_per_s2);
    if (coast >= kHalfThousandth) {
        throw PlanError(fmt::format("{}: speed 3 ({} in/min) coasts {:.5f} in after the stop, "
                                    "more than half a thousandth: no exact deck can be made for "
                                    "this profile",
                                    axis.name, axis.speed_in_per_min[2], coast));
    }
    cardreader::AxisOrder o;
    o.motion = move.to >= move.from ? cardreader::Motion::forward : cardreader::Motion::reverse;
    o.stop = th(move.to);
    o.check = th(std::abs(move.to - move.from));
    o.sequence = move.sequence;
    o.start_speed = 3;
    const int sign = move.to >= move.from ? +1 : -1;
    const int travel = std::abs(move.to - move.from);
    auto followable = [&](int position) {
        return speed_in_per_s(axis, position) / 0.001 <= profile.max_stepping_rate_per_s;
    };
    if (move.corner || travel == 0) {
        return o;
    }
    const int room23 = slow_down_room(axis, 2, 3);
    const int room12 = slow_down_room(axis, 1, 2);
    for (int start = move.slow_down_fields >= 2 ? 1 : 2; start <= 2; ++start) {
        if (!followable(start)) {
            continue;
        }
        // Each slow-down may move up to kMaxNudge thousandths further from the stop; the
        // placement with the least total movement that has no spurious match wins.
        const int extra_max = start == 1 ? 2 * kMaxNudge : kMaxNudge;
        for (int extra = 0; extra <= extra_max; ++extra) {
            for (int nl = std::max(0, extra - kMaxNudge); nl <= std::min(extra, kMaxNudge); ++nl) {
                const int nf = start == 1 ? extra - nl : 0;
                if (start == 2 && nl != extra) {
                    continue;
                }
                const int last = room23 + nl; // the slow-down to speed 3, before the stop
                const int first = last + room12 + nf;
                const int needed = start == 1 ? first : last;
                if (needed + 2 > travel) {
                    continue; // the move is too short to start this fast with this room
                }
                cardreader::AxisOrder candidate = o;
                candidate.start_speed = start;
                if (start == 1) {
                    candidate.slow_down[0] = th(move.to - sign * first);
                    candidate.slow_down[1] = th(move.to - sign * last);
                } else {
                    candidate.slow_down[0] = th(move.to - sign * last);
                }
                if (!cardreader::spurious_match_on_path(candidate, th(move.from))) {
                    return candidate;
                }
            }
        }
    }
    return o;
}

} // namespace parsons::decks
