#include "cardreader/tap_review.hpp"

#include "cardreader/layout.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace parsons::cardreader {
namespace {

constexpr double kHundredThousandths = 1e5;

int tap_column(FieldKind kind) {
    const LayoutField* f = fig8_layout().find_tap(kind);
    return f ? f->first_column : 0;
}

std::string held_tools(const SpindleLimits& limits) {
    std::string held;
    for (const SpindleLimits::Head& h : limits.heads) {
        held += fmt::format("{}{}", held.empty() ? "" : ", ", h.tool);
    }
    return held.empty() ? std::string("none") : held;
}

} // namespace

std::optional<int> motor_revs_per_tool_rev(double ratio) {
    if (!(ratio > 0)) {
        return std::nullopt;
    }
    const double n = 1.0 / ratio;
    const double whole = std::round(n);
    if (whole < 1 || whole > 1000 || std::abs(n - whole) > 1e-6 * whole) {
        return std::nullopt;
    }
    return static_cast<int>(whole);
}

const SpindleLimits::Head* SpindleLimits::head(int tool) const {
    for (const Head& h : heads) {
        if (h.tool == tool) {
            return &h;
        }
    }
    return nullptr;
}

double SpindleLimits::feed_in_per_min(int pitch, int rpm, double ratio) {
    return pitch / kHundredThousandths * rpm * ratio;
}

int SpindleLimits::max_pitch(int rpm, double ratio) const {
    const double tool_rpm = rpm * ratio;
    if (tool_rpm <= 0) {
        return kMaxPitch;
    }
    const double most = std::floor(drive_max_in_per_min / tool_rpm * kHundredThousandths + 1e-9);
    return static_cast<int>(std::min<double>(most, kMaxPitch));
}

int SpindleLimits::min_pitch(int rpm, double ratio) {
    const double tool_rpm = rpm * ratio;
    if (tool_rpm <= 0) {
        return kMaxPitch;
    }
    const double least = std::ceil(kLeastTapFeedInPerMin / tool_rpm * kHundredThousandths - 1e-9);
    return static_cast<int>(std::min<double>(least, kMaxPitch));
}

// The faster retract (an addition): motor 27 reverses to k x S, and the feed follows the tool
// out through the head's ratio, k x pitch x S x A in/min; either past its limit is column 20.
void TapReview::retract_findings(std::int64_t index, const TapOrder& t,
                                 const SpindleLimits::Head* head,
                                 std::vector<TapFinding>& found) const {
    const int out_rpm = t.retract * t.rpm;
    if (out_rpm > limits_.max_rpm + 1e-9) {
        found.push_back(
            {index, tap_column(FieldKind::tap_retract), t.axis,
             fmt::format(
                 "tap retract multiple {}: out at {} x S {} = {} rev/min, "
                 "above spindle motor 27's fastest, {:g} rev/min (max_rpm of "
                 "profile {}): at most {} at that speed",
                 t.retract, t.retract, t.rpm, out_rpm, limits_.max_rpm, profile_,
                 std::max(1, static_cast<int>(std::floor(limits_.max_rpm / t.rpm + 1e-9))))});
        return;
    }
    if (!head) {
        return;
    }
    const double feed = SpindleLimits::feed_in_per_min(t.pitch, out_rpm, head->ratio);
    if (feed > limits_.drive_max_in_per_min + 1e-9) {
        found.push_back(
            {index, tap_column(FieldKind::tap_retract), t.axis,
             fmt::format("tap retract multiple {}: out at {} rev/min the {} axis must follow at "
                         "{:.2f} in/min (pitch {} through tool {}'s gear ratio {:.4g}); the "
                         "follower drive follows at most {:g} in/min",
                         t.retract, out_rpm, axis_name(t.axis), feed, format_pitch(t.pitch), t.tool,
                         head->ratio, limits_.drive_max_in_per_min)});
    }
}

std::vector<TapFinding> TapReview::card(std::int64_t index, const CardOrders& orders) const {
    std::vector<TapFinding> found;
    if (orders.kind != CardKind::tap) {
        return found;
    }
    const TapOrder& t = orders.tap;
    if (!allowed_) {
        found.push_back({index, fig8_layout().extension_column, std::nullopt,
                         fmt::format("a tap card (an addition after EP 0360190, Mitsubishi): "
                                     "profile {} has no spindle synchronisation; the built-in "
                                     "profile parsons-extended has it (--profile "
                                     "parsons-extended)",
                                     profile_)});
        return found; // the rest is judged against a spindle the profile does not have
    }
    const SpindleLimits::Head* head = limits_.head(t.tool);
    if (!head) {
        found.push_back({index, tap_column(FieldKind::tap_tool), t.axis,
                         fmt::format("tap tool {}: no spindle head 31 of profile {} holds it "
                                     "(its heads hold tools {}): PC 130 has nothing to put on",
                                     t.tool, profile_, held_tools(limits_))});
    } else if (!head->tap) {
        found.push_back({index, tap_column(FieldKind::tap_tool), t.axis,
                         fmt::format("tap tool {}: its spindle head 31 holds a cutter, not a tap "
                                     "(profile {}): a tap card feeds the axis one pitch a turn of "
                                     "the tool, which only a tap may be fed",
                                     t.tool, profile_)});
    }
    if (head && t.index_wait && !motor_revs_per_tool_rev(head->ratio)) {
        found.push_back({index, tap_column(FieldKind::tap_index), t.axis,
                         fmt::format("tap index wait: tool {}'s gear ratio {:.4g} is not 1/n, so "
                                     "no index of encoder 32 (once a motor revolution) puts the "
                                     "tool at one angle every pass; leave column 19 blank",
                                     t.tool, head->ratio)});
    }
    if (t.rpm > limits_.max_rpm + 1e-9) {
        found.push_back({index, tap_column(FieldKind::tap_rpm), t.axis,
                         fmt::format("tap speed S {} rev/min is above spindle motor 27's fastest, "
                                     "{:g} rev/min (max_rpm of profile {})",
                                     t.rpm, limits_.max_rpm, profile_)});
    }
    if (t.retract > 1) {
        retract_findings(index, t, head, found);
    }
    if (head) {
        const double feed = SpindleLimits::feed_in_per_min(t.pitch, t.rpm, head->ratio);
        if (feed > limits_.drive_max_in_per_min + 1e-9) {
            found.push_back(
                {index, tap_column(FieldKind::tap_pitch), t.axis,
                 fmt::format("tap pitch {} in at S {} rev/min through tool {}'s gear ratio "
                             "{:.4g} needs the {} axis to feed {:.2f} in/min; the follower drive "
                             "follows at most {:g} in/min: at most {} in per tool revolution at "
                             "that speed",
                             format_pitch(t.pitch), t.rpm, t.tool, head->ratio, axis_name(t.axis),
                             feed, limits_.drive_max_in_per_min,
                             format_pitch(limits_.max_pitch(t.rpm, head->ratio)))});
        } else if (feed < kLeastTapFeedInPerMin - 1e-9) {
            found.push_back(
                {index, tap_column(FieldKind::tap_pitch), t.axis,
                 fmt::format("tap pitch {} in at S {} rev/min through tool {}'s gear ratio "
                             "{:.4g} feeds the {} axis {:.3f} in/min; the follower drive feeds "
                             "no slower than {:g} in/min: at least {} in per tool revolution at "
                             "that speed",
                             format_pitch(t.pitch), t.rpm, t.tool, head->ratio, axis_name(t.axis),
                             feed, kLeastTapFeedInPerMin,
                             format_pitch(SpindleLimits::min_pitch(t.rpm, head->ratio)))});
        }
    }
    return found;
}

} // namespace parsons::cardreader
