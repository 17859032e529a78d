#include "cardreader/layout.hpp"

#include "cardreader/condition_card.hpp"
#include "cardreader/field_reading.hpp"
#include "cardreader/segment_card.hpp"
#include "cardreader/sync_card.hpp"
#include "cardreader/tap_card.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace parsons::cardreader {
namespace {

using detail::join_rows;
using detail::kDigitRows;
using detail::Problems;
using detail::r0;
using detail::r1;
using detail::read_number;
constexpr ColumnWord r2 = row_bit(Row::r2);
constexpr ColumnWord r3 = row_bit(Row::r3);
constexpr ColumnWord r4 = row_bit(Row::r4);
constexpr ColumnWord r12 = row_bit(Row::r12);

// The rows a field may punch in its columns (the 12-row cross marks are added separately).
ColumnWord rows_allowed(FieldKind k) {
    switch (k) {
    case FieldKind::spindle:
    case FieldKind::motion:
        return r0 | r1;
    case FieldKind::start_speed:
        return r0 | r1 | r2;
    case FieldKind::extension:
        return r1;
    case FieldKind::sense:
    case FieldKind::tap_sense:
        return r0 | r1;
    case FieldKind::position_sync:
    case FieldKind::loop_mark:
    case FieldKind::register_reset:
        return r0;
    default:
        return kDigitRows;
    }
}

CardLayout make_fig8() {
    CardLayout layout;
    layout.name = "fig8";
    layout.fields.push_back({FieldKind::spindle, std::nullopt, 1, 1});
    // Table (axis 1): two slow-downs, columns 2-19.
    layout.fields.push_back({FieldKind::motion, Axis::table, 2, 1});
    layout.fields.push_back({FieldKind::start_speed, Axis::table, 3, 1});
    layout.fields.push_back({FieldKind::slow_down_1, Axis::table, 4, 4});
    layout.fields.push_back({FieldKind::slow_down_2, Axis::table, 8, 4});
    layout.fields.push_back({FieldKind::stop, Axis::table, 12, 4});
    layout.fields.push_back({FieldKind::check, Axis::table, 16, 4});
    layout.sequence_first_column[axis_index(Axis::table)] = 2;
    // Cross, vertical, swivel, tilt: one slow-down each, 14 columns from 20, 34, 48, 62.
    int first = 20;
    for (Axis a : {Axis::cross, Axis::vertical, Axis::swivel, Axis::tilt}) {
        layout.fields.push_back({FieldKind::motion, a, first, 1});
        layout.fields.push_back({FieldKind::start_speed, a, first + 1, 1});
        layout.fields.push_back({FieldKind::slow_down_1, a, first + 2, 4});
        layout.fields.push_back({FieldKind::stop, a, first + 6, 4});
        layout.fields.push_back({FieldKind::check, a, first + 10, 4});
        layout.sequence_first_column[axis_index(a)] = first;
        first += 14;
    }
    // Column 76 is unused on a motion card; row 1 there marks a condition card (an addition).
    layout.fields.push_back({FieldKind::card_number, std::nullopt, 77, 4});
    layout.extension_column = 76;
    add_condition_fields(layout);
    add_sync_fields(layout);
    add_tap_fields(layout);
    add_segment_fields(layout);
    layout.index();
    return layout;
}

// More than one extension mark in column 76 (rows 1, 2 and 3 each mark a kind of card): a bad
// punch naming the rows and what each marks.
std::optional<BadPunch> two_marks(const Card& card, const CardLayout& layout) {
    if (layout.extension_column == 0) {
        return std::nullopt;
    }
    static constexpr std::array<std::pair<Row, std::string_view>, 4> kMarks = {
        std::pair{Row::r1, std::string_view("a condition card")},
        std::pair{Row::r2, std::string_view("a sync card")},
        std::pair{Row::r3, std::string_view("a tap card")},
        std::pair{Row::r4, std::string_view("a segment card")}};
    std::vector<std::string> rows;
    std::vector<std::string> meanings;
    for (const auto& [row, kind] : kMarks) {
        if (card.punched(layout.extension_column, row)) {
            rows.emplace_back(row_name(row));
            meanings.push_back(
                fmt::format("row {}{} {}", row_name(row), meanings.empty() ? " marks" : "", kind));
        }
    }
    if (rows.size() < 2) {
        return std::nullopt;
    }
    auto join = [](const std::vector<std::string>& words, std::string_view last) {
        std::string text;
        for (std::size_t i = 0; i < words.size(); ++i) {
            text += i == 0 ? "" : i + 1 == words.size() ? std::string(last) : ", ";
            text += words.at(i);
        }
        return text;
    };
    // "column 76 punched in rows 1 and 2: row 1 marks a condition card, row 2 a sync card, not
    // both"
    return BadPunch{layout.extension_column,
                    fmt::format("column {} punched in rows {}: {}, {}", layout.extension_column,
                                join(rows, " and "), join(meanings, ", "),
                                rows.size() == 2 ? "not both" : "only one of them")};
}

} // namespace

const LayoutField* CardLayout::find(FieldKind kind, std::optional<Axis> axis) const {
    auto it = std::find_if(fields.begin(), fields.end(),
                           [&](const LayoutField& f) { return f.kind == kind && f.axis == axis; });
    return it == fields.end() ? nullptr : &*it;
}

const LayoutField* CardLayout::condition_field_at(int column) const {
    auto it = std::find_if(condition_fields.begin(), condition_fields.end(),
                           [column](const LayoutField& f) {
                               return column >= f.first_column && column <= f.last_column();
                           });
    return it == condition_fields.end() ? nullptr : &*it;
}

const LayoutField* CardLayout::sync_field_at(int column) const {
    auto it = std::find_if(sync_fields.begin(), sync_fields.end(), [column](const LayoutField& f) {
        return column >= f.first_column && column <= f.last_column();
    });
    return it == sync_fields.end() ? nullptr : &*it;
}

const LayoutField* CardLayout::find_sync(FieldKind kind, std::optional<Axis> axis) const {
    auto it = std::find_if(sync_fields.begin(), sync_fields.end(),
                           [&](const LayoutField& f) { return f.kind == kind && f.axis == axis; });
    return it == sync_fields.end() ? nullptr : &*it;
}

const LayoutField* CardLayout::tap_field_at(int column) const {
    auto it = std::find_if(tap_fields.begin(), tap_fields.end(), [column](const LayoutField& f) {
        return column >= f.first_column && column <= f.last_column();
    });
    return it == tap_fields.end() ? nullptr : &*it;
}

const LayoutField* CardLayout::find_tap(FieldKind kind) const {
    auto it = std::find_if(tap_fields.begin(), tap_fields.end(),
                           [kind](const LayoutField& f) { return f.kind == kind; });
    return it == tap_fields.end() ? nullptr : &*it;
}

const LayoutField* CardLayout::segment_field_at(int column) const {
    auto it =
        std::find_if(segment_fields.begin(), segment_fields.end(), [column](const LayoutField& f) {
            return column >= f.first_column && column <= f.last_column();
        });
    return it == segment_fields.end() ? nullptr : &*it;
}

const LayoutField* CardLayout::find_segment(FieldKind kind, std::optional<Axis> axis) const {
    auto it = std::find_if(segment_fields.begin(), segment_fields.end(),
                           [&](const LayoutField& f) { return f.kind == kind && f.axis == axis; });
    return it == segment_fields.end() ? nullptr : &*it;
}

const LayoutField* CardLayout::field_at(int column) const {
    auto it = std::find_if(fields.begin(), fields.end(), [column](const LayoutField& f) {
        return column >= f.first_column && column <= f.last_column();
    });
    return it == fields.end() ? nullptr : &*it;
}

std::optional<std::pair<Axis, int>> CardLayout::sequence_at(int column) const {
    for (Axis a : kAxes) {
        int first = sequence_first_column.at(axis_index(a));
        if (column >= first && column < first + kSequencePositions) {
            return std::pair{a, column - first + 1};
        }
    }
    return std::nullopt;
}

std::string_view field_short_label(FieldKind kind) {
    switch (kind) {
    case FieldKind::spindle:
        return "SPINDLE";
    case FieldKind::motion:
        return "MOTION";
    case FieldKind::start_speed:
        return "SPEED";
    case FieldKind::slow_down_1:
        return "SLOW 1";
    case FieldKind::slow_down_2:
        return "SLOW 2";
    case FieldKind::stop:
        return "STOP";
    case FieldKind::check:
        return "CHECK";
    case FieldKind::card_number:
        return "CARD NO.";
    case FieldKind::extension:
        return "EXTENSION";
    case FieldKind::event:
        return "EVENT";
    case FieldKind::condition_axis:
        return "AXIS";
    case FieldKind::sense:
        return "SENSE";
    case FieldKind::position:
        return "POSITION";
    case FieldKind::action:
        return "ACTION";
    case FieldKind::parameter:
        return "PARAM.";
    case FieldKind::position_sync:
    case FieldKind::sync_angle:
    case FieldKind::loop_mark:
    case FieldKind::loop_target:
    case FieldKind::loop_count:
    case FieldKind::register_reset:
    case FieldKind::travel_per_pulse:
        return sync_field_short_label(kind);
    case FieldKind::tap_tool:
    case FieldKind::tap_axis:
    case FieldKind::tap_sense:
    case FieldKind::tap_depth:
    case FieldKind::tap_pitch:
    case FieldKind::tap_rpm:
    case FieldKind::tap_index:
    case FieldKind::tap_retract:
    case FieldKind::tap_peck:
        return tap_field_short_label(kind);
    case FieldKind::segment_end:
    case FieldKind::segment_feed:
        return segment_field_short_label(kind);
    }
    return "";
}

std::string field_label(const LayoutField& field) {
    std::string_view what;
    switch (field.kind) {
    case FieldKind::spindle:
        return "spindle";
    case FieldKind::card_number:
        return "card number";
    case FieldKind::extension:
        return "extension mark";
    case FieldKind::event:
    case FieldKind::condition_axis:
    case FieldKind::sense:
    case FieldKind::position:
    case FieldKind::action:
    case FieldKind::parameter:
        return fmt::format("condition {} {}", field.slot + 1, condition_field_word(field.kind));
    case FieldKind::position_sync:
    case FieldKind::sync_angle:
    case FieldKind::loop_mark:
    case FieldKind::loop_target:
    case FieldKind::loop_count:
    case FieldKind::register_reset:
    case FieldKind::travel_per_pulse:
        return sync_field_label(field);
    case FieldKind::tap_tool:
    case FieldKind::tap_axis:
    case FieldKind::tap_sense:
    case FieldKind::tap_depth:
    case FieldKind::tap_pitch:
    case FieldKind::tap_rpm:
    case FieldKind::tap_index:
    case FieldKind::tap_retract:
    case FieldKind::tap_peck:
        return tap_field_label(field);
    case FieldKind::segment_end:
    case FieldKind::segment_feed:
        return segment_field_label(field);
    case FieldKind::motion:
        what = "motion";
        break;
    case FieldKind::start_speed:
        what = "start speed";
        break;
    case FieldKind::slow_down_1:
        what = "first slow-down";
        break;
    case FieldKind::slow_down_2:
        what = "second slow-down";
        break;
    case FieldKind::stop:
        what = "stop";
        break;
    case FieldKind::check:
        what = "check";
        break;
    }
    return fmt::format("{} {}", axis_name(field.axis.value_or(Axis::table)), what);
}

void CardLayout::index() {
    for (int c = 1; c <= kColumns; ++c) {
        const LayoutField* f = field_at(c);
        ColumnWord allowed = f ? rows_allowed(f->kind) : 0;
        if (sequence_at(c)) {
            allowed |= r12;
        }
        if (c == extension_column) {
            allowed = rows_allowed(FieldKind::extension);
        }
        allowed_rows.at(static_cast<std::size_t>(c)) = allowed;
        const LayoutField* cf = condition_field_at(c);
        const bool number = f && f->kind == FieldKind::card_number;
        condition_allowed_rows.at(static_cast<std::size_t>(c)) =
            c == extension_column                   ? rows_allowed(FieldKind::extension)
            : cf                                    ? rows_allowed(cf->kind)
            : number || is_condition_mode_column(c) ? kDigitRows
                                                    : ColumnWord{0};
        const LayoutField* sf = sync_field_at(c);
        sync_allowed_rows.at(static_cast<std::size_t>(c)) = c == extension_column ? r2
                                                            : sf     ? rows_allowed(sf->kind)
                                                            : number ? kDigitRows
                                                                     : ColumnWord{0};
        const LayoutField* tf = tap_field_at(c);
        tap_allowed_rows.at(static_cast<std::size_t>(c)) = c == extension_column ? r3
                                                           : tf     ? rows_allowed(tf->kind)
                                                           : number ? kDigitRows
                                                                    : ColumnWord{0};
        const LayoutField* gf = segment_field_at(c);
        segment_allowed_rows.at(static_cast<std::size_t>(c)) = c == extension_column ? r4
                                                               : gf                  ? kDigitRows
                                                               : number              ? kDigitRows
                                                                        : ColumnWord{0};
    }
}

bool is_condition_card(const Card& card, const CardLayout& layout) {
    return layout.extension_column != 0 && card.punched(layout.extension_column, Row::r1);
}

bool is_sync_card(const Card& card, const CardLayout& layout) {
    return layout.extension_column != 0 && card.punched(layout.extension_column, Row::r2);
}

bool is_tap_card(const Card& card, const CardLayout& layout) {
    return layout.extension_column != 0 && card.punched(layout.extension_column, Row::r3);
}

bool is_segment_card(const Card& card, const CardLayout& layout) {
    return layout.extension_column != 0 && card.punched(layout.extension_column, Row::r4);
}

bool is_extension_card(const Card& card, const CardLayout& layout) {
    return is_condition_card(card, layout) || is_sync_card(card, layout) ||
           is_tap_card(card, layout) || is_segment_card(card, layout);
}

const CardLayout& fig8_layout() {
    static const CardLayout layout = make_fig8();
    return layout;
}

const CardLayout* layout_named(std::string_view name) {
    if (name == kLayoutNames[0]) {
        return &fig8_layout();
    }
    return nullptr;
}

DecodeResult decode(const Card& card, const CardLayout& layout) {
    DecodeResult result;
    Problems problems;

    if (auto both = two_marks(card, layout)) {
        result.bad_punch = std::move(both);
        return result;
    }
    if (is_condition_card(card, layout)) {
        return decode_condition_card(card, layout);
    }
    if (is_sync_card(card, layout)) {
        return decode_sync_card(card, layout);
    }
    if (is_tap_card(card, layout)) {
        return decode_tap_card(card, layout);
    }
    if (is_segment_card(card, layout)) {
        return decode_segment_card(card, layout);
    }
    detail::find_strays(card, layout.allowed_rows, layout, CardKind::motion, problems);

    CardOrders& o = result.orders;
    for (const LayoutField& f : layout.fields) {
        const int c = f.first_column;
        const ColumnWord word = card.column(c);
        AxisOrder* axis = f.axis ? &o.axis(*f.axis) : nullptr;
        switch (f.kind) {
        case FieldKind::spindle:
            if ((word & (r0 | r1)) == (r0 | r1)) {
                problems.add(c, "spindle punched both forward (row 0) and reverse (row 1)");
            }
            o.spindle = (word & r0)   ? Spindle::forward
                        : (word & r1) ? Spindle::reverse
                                      : Spindle::off;
            break;
        case FieldKind::motion:
            if ((word & (r0 | r1)) == (r0 | r1)) {
                problems.add(c, fmt::format("{} punched both forward (row 0) and reverse (row 1)",
                                            field_label(f)));
            } else if ((word & (r0 | r1)) == 0) {
                problems.add(c, fmt::format("missing {} (row 0 = forward, row 1 = reverse)",
                                            field_label(f)));
            }
            axis->motion = (word & r1) && !(word & r0) ? Motion::reverse : Motion::forward;
            break;
        case FieldKind::start_speed: {
            ColumnWord speed = word & (r0 | r1 | r2);
            if (speed == r0) {
                axis->start_speed = 1;
            } else if (speed == (r0 | r1)) {
                axis->start_speed = 2;
            } else if (speed == (r0 | r1 | r2)) {
                axis->start_speed = 3;
            } else if (speed == 0) {
                problems.add(c, fmt::format("missing {} (0, 0-1 or 0-1-2 for speed 1, 2 or 3)",
                                            field_label(f)));
            } else {
                problems.add(c, fmt::format("{} punched in rows {}: expected 0, 0-1 or 0-1-2",
                                            field_label(f), join_rows(speed)));
            }
            break;
        }
        default: {
            std::optional<int> value = read_number(card, f, problems);
            const bool required =
                f.kind != FieldKind::slow_down_1 && f.kind != FieldKind::slow_down_2;
            if (!value && required) {
                problems.add(c, fmt::format("{} is blank (it is always punched)", field_label(f)));
            }
            auto v = static_cast<Thousandths>(value.value_or(0));
            switch (f.kind) {
            case FieldKind::slow_down_1:
                axis->slow_down[0] = value ? std::optional<Thousandths>(v) : std::nullopt;
                break;
            case FieldKind::slow_down_2:
                axis->slow_down[1] = value ? std::optional<Thousandths>(v) : std::nullopt;
                break;
            case FieldKind::stop:
                axis->stop = v;
                break;
            case FieldKind::check:
                axis->check = v;
                break;
            case FieldKind::card_number:
                o.number = v;
                break;
            default:
                break;
            }
        }
        }
    }

    for (Axis a : kAxes) {
        int first = layout.sequence_first_column.at(axis_index(a));
        SequencePattern pattern = 0;
        for (int k = 0; k < kSequencePositions; ++k) {
            if (card.punched(first + k, Row::r12)) {
                pattern = static_cast<SequencePattern>(pattern | (1u << k));
            }
        }
        o.axis(a).sequence = pattern;
    }

    result.bad_punch = problems.first();
    return result;
}

EncodeResult encode(const CardOrders& orders, const CardLayout& layout) {
    EncodeResult result;
    Card& card = result.card;
    auto fail = [&](std::string what) {
        if (!result.error) {
            result.error = std::move(what);
        }
    };
    auto punch_number = [&](const LayoutField& f, int value) {
        if (auto error = detail::punch_number(card, f, value)) {
            fail(*error);
        }
    };

    if (orders.number < 0 || orders.number > 9999) {
        fail(fmt::format("card number {} is outside 0..9999", orders.number));
    }
    if (orders.kind == CardKind::condition) {
        if (const auto* f = layout.find(FieldKind::card_number)) {
            punch_number(*f, orders.number);
        }
        if (auto error = encode_condition_card(orders, layout, card)) {
            fail(*error);
        }
        return result;
    }
    if (orders.kind == CardKind::sync) {
        if (const auto* f = layout.find(FieldKind::card_number)) {
            punch_number(*f, orders.number);
        }
        if (auto error = encode_sync_card(orders.sync, layout, card)) {
            fail(*error);
        }
        return result;
    }
    if (orders.kind == CardKind::tap) {
        if (const auto* f = layout.find(FieldKind::card_number)) {
            punch_number(*f, orders.number);
        }
        if (auto error = encode_tap_card(orders.tap, layout, card)) {
            fail(*error);
        }
        return result;
    }
    if (orders.kind == CardKind::segment) {
        if (const auto* f = layout.find(FieldKind::card_number)) {
            punch_number(*f, orders.number);
        }
        if (auto error = encode_segment_card(orders.segment, layout, card)) {
            fail(*error);
        }
        return result;
    }
    for (Axis a : kAxes) {
        const AxisOrder& ax = orders.axis(a);
        if (ax.start_speed < 1 || ax.start_speed > 3) {
            fail(fmt::format("{} start speed {} is not 1, 2 or 3", axis_name(a), ax.start_speed));
        }
        for (int i = 0; i < 2; ++i) {
            FieldKind kind = i == 0 ? FieldKind::slow_down_1 : FieldKind::slow_down_2;
            if (ax.slow_down.at(static_cast<std::size_t>(i)) && !layout.find(kind, a)) {
                fail(fmt::format("layout {} has no {} slow-down field for the {} axis", layout.name,
                                 i == 0 ? "first" : "second", axis_name(a)));
            }
        }
        if (ax.sequence >= (1u << kSequencePositions)) {
            fail(fmt::format("{} sequence pattern has a position over 5", axis_name(a)));
        }
        int first = layout.sequence_first_column.at(axis_index(a));
        for (int k = 0; k < kSequencePositions; ++k) {
            if ((ax.sequence & (1u << k)) != 0) {
                card.punch(first + k, Row::r12);
            }
        }
    }

    for (const LayoutField& f : layout.fields) {
        const int c = f.first_column;
        if (f.kind == FieldKind::spindle) {
            if (orders.spindle != Spindle::off) {
                card.punch(c, orders.spindle == Spindle::forward ? Row::r0 : Row::r1);
            }
            continue;
        }
        if (f.kind == FieldKind::card_number) {
            punch_number(f, orders.number);
            continue;
        }
        const AxisOrder& ax = orders.axis(*f.axis);
        switch (f.kind) {
        case FieldKind::motion:
            card.punch(c, ax.motion == Motion::forward ? Row::r0 : Row::r1);
            break;
        case FieldKind::start_speed:
            for (int s = 0; s < ax.start_speed && s < 3; ++s) {
                card.punch(c, digit_row(s));
            }
            break;
        case FieldKind::slow_down_1:
        case FieldKind::slow_down_2: {
            auto& sd = ax.slow_down.at(f.kind == FieldKind::slow_down_1 ? 0 : 1);
            if (sd) {
                punch_number(f, *sd);
            }
            break;
        }
        case FieldKind::stop:
            punch_number(f, ax.stop);
            break;
        case FieldKind::check:
            punch_number(f, ax.check);
            break;
        default:
            break;
        }
    }
    return result;
}

} // namespace parsons::cardreader
