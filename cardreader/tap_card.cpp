#include "cardreader/tap_card.hpp"

#include "cardreader/field_reading.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace parsons::cardreader {
namespace {

using detail::Problems;

using detail::r0;
using detail::r1;

const LayoutField& tap_field(const CardLayout& layout, FieldKind kind) {
    if (const LayoutField* f = layout.find_tap(kind)) {
        return *f;
    }
    throw std::logic_error("tap card field missing from the layout");
}

// A digit field that is always punched and never all zeros: its value, or 0 with the fault
// added to `problems` (blank: `blank`; all zeros: `zero`).
int read_required(const Card& card, const LayoutField& f, std::string_view blank,
                  std::string_view zero, Problems& problems) {
    Problems own;
    const std::optional<int> value = detail::read_number(card, f, own);
    if (const auto bad = own.first()) {
        problems.add(bad->column, bad->what);
        return 0;
    }
    if (!value) {
        problems.add(f.first_column, fmt::format("{} is blank: {}", tap_field_label(f), blank));
        return 0;
    }
    if (*value == 0) {
        problems.add(f.first_column,
                     fmt::format("{} is {:0{}}: {}", tap_field_label(f), 0, f.width, zero));
        return 0;
    }
    return *value;
}

// Column 4: one digit 1-5.
Axis read_axis(const Card& card, const LayoutField& f, Problems& problems) {
    Problems own;
    const std::optional<int> digit = detail::read_number(card, f, own);
    if (const auto bad = own.first()) {
        problems.add(bad->column, bad->what);
        return Axis::table;
    }
    if (!digit) {
        problems.add(f.first_column,
                     fmt::format("{} is blank: the axis that feeds in step with the tool, 1-5 "
                                 "(table, cross, vertical, swivel, tilt)",
                                 tap_field_label(f)));
        return Axis::table;
    }
    if (*digit < 1 || *digit > kAxisCount) {
        problems.add(f.first_column, fmt::format("{} is {}: expected 1-5 (table, cross, vertical, "
                                                 "swivel, tilt)",
                                                 tap_field_label(f), *digit));
        return Axis::table;
    }
    return kAxes.at(static_cast<std::size_t>(*digit - 1));
}

// Column 5: row 0 forward, row 1 reverse, exactly one.
Motion read_sense(const Card& card, const LayoutField& f, Problems& problems) {
    const ColumnWord s = card.column(f.first_column) & (r0 | r1);
    if (s == 0) {
        problems.add(f.first_column,
                     fmt::format("{} is blank: row 0 forward (counters count up), row 1 reverse "
                                 "(count down) into the work",
                                 tap_field_label(f)));
    } else if (s == (r0 | r1)) {
        problems.add(
            f.first_column,
            fmt::format("{} punched both forward (row 0) and reverse (row 1)", tap_field_label(f)));
    }
    return s == r1 ? Motion::reverse : Motion::forward;
}

// Column 19 (an addition after rigid tapping): blank, no wait (the feed follows from the tool's
// first turn); 1, the feed waits for encoder 32's index. Any other digit is refused.
bool read_index_wait(const Card& card, const LayoutField& f, Problems& problems) {
    Problems own;
    const std::optional<int> digit = detail::read_number(card, f, own);
    if (const auto bad = own.first()) {
        problems.add(bad->column, bad->what);
        return false;
    }
    if (digit && *digit != 1) {
        problems.add(f.first_column,
                     fmt::format("{} is {}: blank (the feed follows from the tool's first turn) "
                                 "or 1 (the feed waits for encoder 32's index)",
                                 tap_field_label(f), *digit));
        return false;
    }
    return digit.has_value();
}

// Column 20 (an addition after LinuxCNC G33.1): the retract multiple k, the return stroke at
// k x S. Blank is 1 (as before the addition); 1-4 read as punched; 0 and 5-9 are refused.
int read_retract(const Card& card, const LayoutField& f, Problems& problems) {
    Problems own;
    const std::optional<int> digit = detail::read_number(card, f, own);
    if (const auto bad = own.first()) {
        problems.add(bad->column, bad->what);
        return 1;
    }
    if (digit && (*digit < 1 || *digit > kMaxTapRetract)) {
        problems.add(f.first_column,
                     fmt::format("{} is {}: blank or 1 (out at S, as in), or 2-{} (out at that "
                                 "multiple of S)",
                                 tap_field_label(f), *digit, kMaxTapRetract));
        return 1;
    }
    return digit.value_or(1);
}

// Columns 21-24 (an addition after rigid peck tapping, G84 with Q): the peck depth Q, d.ddd in.
// Blank is one pass (as before the addition); 0000 is refused (blank is the way to say none).
Thousandths read_peck(const Card& card, const LayoutField& f, Problems& problems) {
    Problems own;
    const std::optional<int> value = detail::read_number(card, f, own);
    if (const auto bad = own.first()) {
        problems.add(bad->column, bad->what);
        return 0;
    }
    if (value && *value == 0) {
        problems.add(f.first_column,
                     fmt::format("{} is 0000: leave it blank for one pass (a peck of 0.001-9.999 "
                                 "in, or blank)",
                                 tap_field_label(f)));
        return 0;
    }
    return static_cast<Thousandths>(value.value_or(0));
}

} // namespace

void add_tap_fields(CardLayout& layout) {
    layout.tap_fields.push_back({FieldKind::tap_tool, std::nullopt, 2, 2});
    layout.tap_fields.push_back({FieldKind::tap_axis, std::nullopt, 4, 1});
    layout.tap_fields.push_back({FieldKind::tap_sense, std::nullopt, 5, 1});
    layout.tap_fields.push_back({FieldKind::tap_depth, std::nullopt, 6, 4});
    layout.tap_fields.push_back({FieldKind::tap_pitch, std::nullopt, 10, 5});
    layout.tap_fields.push_back({FieldKind::tap_rpm, std::nullopt, 15, 4});
    layout.tap_fields.push_back({FieldKind::tap_index, std::nullopt, 19, 1});
    layout.tap_fields.push_back({FieldKind::tap_retract, std::nullopt, 20, 1});
    layout.tap_fields.push_back({FieldKind::tap_peck, std::nullopt, 21, 4});
}

std::string tap_field_label(const LayoutField& field) {
    switch (field.kind) {
    case FieldKind::tap_tool:
        return "tap tool";
    case FieldKind::tap_axis:
        return "tap feed axis";
    case FieldKind::tap_sense:
        return "tap sense";
    case FieldKind::tap_depth:
        return "tap depth";
    case FieldKind::tap_pitch:
        return "tap pitch";
    case FieldKind::tap_rpm:
        return "tap speed";
    case FieldKind::tap_index:
        return "tap index wait";
    case FieldKind::tap_retract:
        return "tap retract multiple";
    case FieldKind::tap_peck:
        return "tap peck depth";
    default:
        return "tap field";
    }
}

std::string_view tap_field_short_label(FieldKind kind) {
    switch (kind) {
    case FieldKind::tap_tool:
        return "TOOL T";
    case FieldKind::tap_axis:
        return "AXIS";
    case FieldKind::tap_sense:
        return "SENSE";
    case FieldKind::tap_depth:
        return "DEPTH";
    case FieldKind::tap_pitch:
        return "PITCH";
    case FieldKind::tap_rpm:
        return "SPEED S";
    case FieldKind::tap_index:
        return "INDEX";
    case FieldKind::tap_retract:
        return "RETRACT";
    case FieldKind::tap_peck:
        return "PECK Q";
    default:
        return "";
    }
}

std::string tap_peck_text(const TapOrder& t) {
    if (t.peck == 0) {
        return "blank: one pass to the depth";
    }
    const int passes = tap_passes(t);
    return fmt::format("{} in a peck: {} pass{} in to {} in, out to the start between, the feed "
                       "on one helix (an addition)",
                       format_inches(t.peck), passes, passes == 1 ? "" : "es",
                       format_inches(t.depth));
}

DecodeResult decode_tap_card(const Card& card, const CardLayout& layout) {
    DecodeResult result;
    Problems problems;
    CardOrders& o = result.orders;
    o.kind = CardKind::tap;
    detail::find_strays(card, layout.tap_allowed_rows, layout, CardKind::tap, problems);
    o.number = detail::read_card_number(card, layout, problems);
    TapOrder& t = o.tap;
    t.tool = read_required(card, tap_field(layout, FieldKind::tap_tool),
                           "the tool to tap with, 01-99 (the head that holds it goes on)",
                           "tools are numbered 01-99", problems);
    t.axis = read_axis(card, tap_field(layout, FieldKind::tap_axis), problems);
    t.motion = read_sense(card, tap_field(layout, FieldKind::tap_sense), problems);
    t.depth = static_cast<Thousandths>(read_required(card, tap_field(layout, FieldKind::tap_depth),
                                                     "the depth of the hole, d.ddd in",
                                                     "a tap of depth 0 taps nothing", problems));
    t.pitch = read_required(card, tap_field(layout, FieldKind::tap_pitch),
                            "the pitch, 0.ddddd in per tool revolution",
                            "a pitch of 0 feeds nothing", problems);
    t.rpm = read_required(card, tap_field(layout, FieldKind::tap_rpm),
                          "spindle motor 27's speed S, 0001-9999 rev/min",
                          "the spindle must turn to tap (0001-9999 rev/min)", problems);
    t.index_wait = read_index_wait(card, tap_field(layout, FieldKind::tap_index), problems);
    t.retract = read_retract(card, tap_field(layout, FieldKind::tap_retract), problems);
    t.peck = read_peck(card, tap_field(layout, FieldKind::tap_peck), problems);
    result.bad_punch = problems.first();
    return result;
}

std::optional<std::string> tap_order_error(const TapOrder& t) {
    if (t.tool < 1 || t.tool > kMaxTapTool) {
        return fmt::format("tap tool {} is not 1..99", t.tool);
    }
    if (axis_index(t.axis) >= static_cast<std::size_t>(kAxisCount)) {
        return fmt::format("tap feed axis {} is none of the five axes",
                           static_cast<int>(axis_index(t.axis)));
    }
    if (t.motion != Motion::forward && t.motion != Motion::reverse) {
        return "tap sense is neither forward nor reverse";
    }
    if (t.depth < 1 || t.depth > kMaxThousandths) {
        return fmt::format("tap depth {} is not 0.001..9.999 in", t.depth);
    }
    if (t.pitch < 1 || t.pitch > kMaxPitch) {
        return fmt::format("tap pitch {} is not 1..99999 hundred-thousandths of an inch per tool "
                           "revolution",
                           t.pitch);
    }
    if (t.rpm < 1 || t.rpm > kMaxTapRpm) {
        return fmt::format("tap speed {} is not 1..9999 rev/min", t.rpm);
    }
    if (t.retract < 1 || t.retract > kMaxTapRetract) {
        return fmt::format("tap retract multiple {} is not 1..{}", t.retract, kMaxTapRetract);
    }
    if (t.peck > kMaxTapPeck) {
        return fmt::format("tap peck depth {} is not 0.001..9.999 in (or 0, one pass)", t.peck);
    }
    return std::nullopt;
}

std::optional<std::string> encode_tap_card(const TapOrder& t, const CardLayout& layout,
                                           Card& card) {
    if (layout.extension_column == 0) {
        return fmt::format("layout {} has no extension column for tap cards", layout.name);
    }
    if (auto error = tap_order_error(t)) {
        return error;
    }
    card.punch(layout.extension_column, Row::r3);
    std::optional<std::string> error;
    auto number = [&](FieldKind kind, int value) {
        if (auto e = detail::punch_number(card, tap_field(layout, kind), value); e && !error) {
            error = std::move(e);
        }
    };
    number(FieldKind::tap_tool, t.tool);
    number(FieldKind::tap_axis, static_cast<int>(axis_index(t.axis)) + 1);
    card.punch(tap_field(layout, FieldKind::tap_sense).first_column,
               t.motion == Motion::forward ? Row::r0 : Row::r1);
    number(FieldKind::tap_depth, t.depth);
    number(FieldKind::tap_pitch, t.pitch);
    number(FieldKind::tap_rpm, t.rpm);
    if (t.index_wait) {
        number(FieldKind::tap_index, 1);
    }
    if (t.retract > 1) {
        number(FieldKind::tap_retract, t.retract);
    }
    if (t.peck > 0) {
        number(FieldKind::tap_peck, t.peck);
    }
    return error;
}

EncodeResult tap_card(const TapOrder& order, int number, const CardLayout& layout) {
    CardOrders orders;
    orders.kind = CardKind::tap;
    orders.number = number;
    orders.tap = order;
    return encode(orders, layout);
}

} // namespace parsons::cardreader
