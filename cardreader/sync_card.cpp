#include "cardreader/sync_card.hpp"

#include "cardreader/field_reading.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace parsons::cardreader {
namespace {

using detail::Problems;

using detail::r0;
constexpr int kTravelFirstColumn = 16;
constexpr int kTravelColumns = 5;

const LayoutField& sync_field(const CardLayout& layout, FieldKind kind,
                              std::optional<Axis> axis = std::nullopt) {
    if (const LayoutField* f = layout.find_sync(kind, axis)) {
        return *f;
    }
    throw std::logic_error("sync card field missing from the layout");
}

// A digit field read on its own: its value (none if blank) and whether it was sound, its
// faults added to `problems`.
struct Reading {
    std::optional<int> value;
    bool sound = true;
};

Reading read(const Card& card, const LayoutField& f, Problems& problems) {
    Problems own;
    Reading r;
    r.value = detail::read_number(card, f, own);
    if (const auto bad = own.first()) {
        problems.add(bad->column, bad->what);
        r.sound = false;
    }
    return r;
}

// G101 R: the mark in column 2 and the angle in 3-5, both or neither.
void read_position_sync(const Card& card, const CardLayout& layout, SyncOrder& s,
                        Problems& problems) {
    const LayoutField& mark = sync_field(layout, FieldKind::position_sync);
    const LayoutField& angle_field = sync_field(layout, FieldKind::sync_angle);
    const bool marked = (card.column(mark.first_column) & r0) != 0;
    const Reading angle = read(card, angle_field, problems);
    if (marked && !angle.value) {
        problems.add(angle_field.first_column,
                     fmt::format("sync angle is blank: position sync (column {}) needs the crank "
                                 "angle 000-359 in columns {}-{}",
                                 mark.first_column, angle_field.first_column,
                                 angle_field.last_column()));
    }
    if (!marked && angle.value) {
        problems.add(mark.first_column,
                     fmt::format("position sync (column {}, row 0) is blank, but a sync angle is "
                                 "punched in columns {}-{}",
                                 mark.first_column, angle_field.first_column,
                                 angle_field.last_column()));
    }
    if (angle.value && angle.sound && *angle.value > kMaxSyncAngle) {
        problems.add(angle_field.first_column,
                     fmt::format("sync angle {} outside 0-359 (whole degrees of crank 21 from top "
                                 "dead centre)",
                                 *angle.value));
    }
    s.position_sync = marked;
    s.angle_deg = marked && angle.sound && angle.value.value_or(0) <= kMaxSyncAngle
                      ? angle.value.value_or(0)
                      : 0;
}

// M99: the mark in column 6, the target in 7-10 and the count in 11-14, all or none.
void read_loop(const Card& card, const CardLayout& layout, SyncOrder& s, Problems& problems) {
    const LayoutField& mark = sync_field(layout, FieldKind::loop_mark);
    const LayoutField& target_field = sync_field(layout, FieldKind::loop_target);
    const LayoutField& count_field = sync_field(layout, FieldKind::loop_count);
    const bool marked = (card.column(mark.first_column) & r0) != 0;
    const Reading target = read(card, target_field, problems);
    const Reading count = read(card, count_field, problems);
    if (marked) {
        if (!target.value) {
            problems.add(target_field.first_column,
                         fmt::format("loop target is blank: the loop (column {}) goes back to the "
                                     "card number in columns {}-{}",
                                     mark.first_column, target_field.first_column,
                                     target_field.last_column()));
        }
        if (!count.value) {
            problems.add(count_field.first_column,
                         fmt::format("loop count is blank: the loop (column {}) needs how many "
                                     "times, 0001-9999, in columns {}-{}",
                                     mark.first_column, count_field.first_column,
                                     count_field.last_column()));
        } else if (count.sound && *count.value == 0) {
            problems.add(count_field.first_column,
                         "loop count 0000: a loop goes back 0001-9999 times");
        }
    } else if (target.value || count.value) {
        problems.add(mark.first_column,
                     fmt::format("loop mark (column {}, row 0) is blank, but a loop {} is punched "
                                 "in columns {}-{}",
                                 mark.first_column, target.value ? "target" : "count",
                                 target_field.first_column, count_field.last_column()));
    }
    s.loop = marked;
    s.loop_to = marked ? target.value.value_or(0) : 0;
    s.loop_count = marked ? count.value.value_or(0) : 0;
}

// G95 F: the travel per detector pulse of each axis, 0.ddddd in, blank = none.
void read_speed_sync(const Card& card, const CardLayout& layout, SyncOrder& s, Problems& problems) {
    for (Axis a : kAxes) {
        const LayoutField& f = sync_field(layout, FieldKind::travel_per_pulse, a);
        const Reading travel = read(card, f, problems);
        if (travel.value && travel.sound && *travel.value == 0) {
            problems.add(f.first_column,
                         fmt::format("{} is 00000: a travel per pulse of 0 (leave the field blank "
                                     "for an axis that is not speed-synchronised)",
                                     sync_field_label(f)));
        }
        if (travel.value && *travel.value > 0) {
            s.travel_per_pulse.at(axis_index(a)) = *travel.value;
        }
    }
}

} // namespace

void add_sync_fields(CardLayout& layout) {
    layout.sync_fields.push_back({FieldKind::position_sync, std::nullopt, 2, 1});
    layout.sync_fields.push_back({FieldKind::sync_angle, std::nullopt, 3, 3});
    layout.sync_fields.push_back({FieldKind::loop_mark, std::nullopt, 6, 1});
    layout.sync_fields.push_back({FieldKind::loop_target, std::nullopt, 7, 4});
    layout.sync_fields.push_back({FieldKind::loop_count, std::nullopt, 11, 4});
    layout.sync_fields.push_back({FieldKind::register_reset, std::nullopt, 15, 1});
    for (Axis a : kAxes) {
        const int first = kTravelFirstColumn + static_cast<int>(axis_index(a)) * kTravelColumns;
        layout.sync_fields.push_back({FieldKind::travel_per_pulse, a, first, kTravelColumns});
    }
}

std::string sync_field_label(const LayoutField& field) {
    switch (field.kind) {
    case FieldKind::position_sync:
        return "position sync";
    case FieldKind::sync_angle:
        return "sync angle";
    case FieldKind::loop_mark:
        return "loop mark";
    case FieldKind::loop_target:
        return "loop target";
    case FieldKind::loop_count:
        return "loop count";
    case FieldKind::register_reset:
        return "register 14 reset";
    case FieldKind::travel_per_pulse:
        return fmt::format("{} travel per pulse", axis_name(field.axis.value_or(Axis::table)));
    default:
        return "sync field";
    }
}

std::string_view sync_field_short_label(FieldKind kind) {
    switch (kind) {
    case FieldKind::position_sync:
        return "G101";
    case FieldKind::sync_angle:
        return "ANGLE R";
    case FieldKind::loop_mark:
        return "M99";
    case FieldKind::loop_target:
        return "LOOP TO";
    case FieldKind::loop_count:
        return "COUNT";
    case FieldKind::register_reset:
        return "16A";
    case FieldKind::travel_per_pulse:
        return "F/PULSE";
    default:
        return "";
    }
}

DecodeResult decode_sync_card(const Card& card, const CardLayout& layout) {
    DecodeResult result;
    Problems problems;
    CardOrders& o = result.orders;
    o.kind = CardKind::sync;
    detail::find_strays(card, layout.sync_allowed_rows, layout, CardKind::sync, problems);
    if (const LayoutField* f = layout.find(FieldKind::card_number)) {
        const Reading number = read(card, *f, problems);
        if (!number.value) {
            problems.add(f->first_column, "card number is blank (it is always punched)");
        }
        o.number = number.value.value_or(0);
    }
    SyncOrder& s = o.sync;
    read_position_sync(card, layout, s, problems);
    read_loop(card, layout, s, problems);
    read_speed_sync(card, layout, s, problems);
    const LayoutField& reset = sync_field(layout, FieldKind::register_reset);
    s.register_reset = (card.column(reset.first_column) & r0) != 0;
    const LayoutField& loop_mark = sync_field(layout, FieldKind::loop_mark);
    if (s.loop && (s.synchronises() || s.register_reset)) {
        problems.add(loop_mark.first_column,
                     fmt::format("a loop card (column {}) stands alone, but this one also carries "
                                 "{}: punch {} on a card of its own (the seed's M99 is a block of "
                                 "its own)",
                                 loop_mark.first_column,
                                 s.position_sync  ? "position sync"
                                 : s.speed_sync() ? "speed sync"
                                                  : "the reset of register 14 (switch 16A)",
                                 s.synchronises() ? "the synchronisation" : "the reset"));
    }
    bool anything = false;
    for (const LayoutField& f : layout.sync_fields) {
        for (int c = f.first_column; c <= f.last_column(); ++c) {
            anything = anything || card.column(c) != 0;
        }
    }
    if (!anything) {
        problems.add(layout.extension_column,
                     fmt::format("column {} marks a sync card (row 2), but no synchronisation, "
                                 "register reset or loop is punched in columns 1-75",
                                 layout.extension_column));
    }
    result.bad_punch = problems.first();
    return result;
}

std::optional<std::string> sync_order_error(const SyncOrder& s) {
    if (s.position_sync && (s.angle_deg < 0 || s.angle_deg > kMaxSyncAngle)) {
        return fmt::format("sync angle {} is not 0..359 degrees", s.angle_deg);
    }
    if (!s.position_sync && s.angle_deg != 0) {
        return fmt::format("a sync angle ({}) without position sync", s.angle_deg);
    }
    for (Axis a : kAxes) {
        const auto& f = s.travel_per_pulse.at(axis_index(a));
        if (f && (*f < 1 || *f > kMaxTravelPerPulse)) {
            return fmt::format("{} travel per pulse {}: {}", axis_name(a), *f,
                               *f == 0 ? "a travel per pulse of 0 (leave the axis out instead)"
                                       : "not 1..99999 hundred-thousandths of an inch");
        }
    }
    if (s.loop) {
        if (s.loop_to < 0 || s.loop_to > 9999) {
            return fmt::format("loop target {} is not a card number 0..9999", s.loop_to);
        }
        if (s.loop_count < 1 || s.loop_count > kMaxLoopCount) {
            return fmt::format("loop count {} is not 1..9999", s.loop_count);
        }
        if (s.synchronises() || s.register_reset) {
            return "a loop card stands alone: no position or speed sync or register reset on it";
        }
    } else if (s.loop_to != 0 || s.loop_count != 0) {
        return "a loop target or count without the loop";
    } else if (!s.synchronises() && !s.register_reset) {
        return "a sync card with nothing on it (no position sync, speed sync, register reset or "
               "loop)";
    }
    return std::nullopt;
}

std::optional<std::string> encode_sync_card(const SyncOrder& s, const CardLayout& layout,
                                            Card& card) {
    if (layout.extension_column == 0) {
        return fmt::format("layout {} has no extension column for sync cards", layout.name);
    }
    if (auto error = sync_order_error(s)) {
        return error;
    }
    card.punch(layout.extension_column, Row::r2);
    std::optional<std::string> error;
    auto number = [&](const LayoutField& f, int value) {
        if (auto e = detail::punch_number(card, f, value); e && !error) {
            error = std::move(e);
        }
    };
    if (s.position_sync) {
        card.punch(sync_field(layout, FieldKind::position_sync).first_column, Row::r0);
        number(sync_field(layout, FieldKind::sync_angle), s.angle_deg);
    }
    if (s.register_reset) {
        card.punch(sync_field(layout, FieldKind::register_reset).first_column, Row::r0);
    }
    if (s.loop) {
        card.punch(sync_field(layout, FieldKind::loop_mark).first_column, Row::r0);
        number(sync_field(layout, FieldKind::loop_target), s.loop_to);
        number(sync_field(layout, FieldKind::loop_count), s.loop_count);
    }
    for (Axis a : kAxes) {
        if (const auto& f = s.travel_per_pulse.at(axis_index(a))) {
            number(sync_field(layout, FieldKind::travel_per_pulse, a), *f);
        }
    }
    return error;
}

} // namespace parsons::cardreader
