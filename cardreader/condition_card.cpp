#include "cardreader/condition_card.hpp"

#include "cardreader/field_reading.hpp"

#include <fmt/format.h>

namespace parsons::cardreader {
namespace {

using detail::kDigitRows;
using detail::Problems;
using detail::read_card_number;
using detail::read_number;

using detail::r0;
using detail::r1;

// The fields of one slot, in the order of the table above.
const LayoutField& slot_field(const CardLayout& layout, int slot, FieldKind kind) {
    for (const LayoutField& f : layout.condition_fields) {
        if (f.slot == slot && f.kind == kind) {
            return f;
        }
    }
    throw std::logic_error("condition slot field missing from the layout");
}

bool slot_blank(const Card& card, int first_column) {
    for (int c = first_column; c < first_column + kConditionSlotColumns; ++c) {
        if (card.column(c) != 0) {
            return false;
        }
    }
    return true;
}

// The mode column (an addition beyond the seed's claims): blank once, 1 every, 2 cancel.
std::optional<ConditionMode> read_mode(const Card& card, int slot, Problems& problems) {
    const int column = 1 + slot * kConditionSlotColumns + kConditionModeOffset;
    const ColumnWord w = card.column(column) & kDigitRows;
    if (w == 0) {
        return ConditionMode::once;
    }
    const int digit = detail::digit_of(w);
    if (digit == 1 || digit == 2) {
        return digit == 1 ? ConditionMode::every : ConditionMode::cancel;
    }
    problems.add(column,
                 fmt::format("condition {} mode is {}: expected blank (once), 1 (every) or "
                             "2 (cancel)",
                             slot + 1,
                             digit < 0 ? fmt::format("punched in rows {}", detail::join_rows(w))
                                       : std::to_string(digit)));
    return std::nullopt;
}

// A cancel names its event and nothing else: every other column of the slot stays blank.
void read_cancel(const Card& card, const CardLayout& layout, int slot, ConditionOrder& cond,
                 Problems& problems) {
    const LayoutField& event = slot_field(layout, slot, FieldKind::event);
    const std::optional<int> value = read_number(card, event, problems);
    if (!value || *value == 0) {
        problems.add(event.first_column,
                     fmt::format("{} is {}: a cancel names the every-condition it ends (01..99)",
                                 field_label(event), value ? "00" : "blank"));
    }
    cond.event = value.value_or(0);
    cond.mode = ConditionMode::cancel;
    const int b = 1 + slot * kConditionSlotColumns;
    for (int c = b + 2; c < b + kConditionModeOffset; ++c) {
        if (card.column(c) != 0) {
            problems.add(c, fmt::format("condition {} is a cancel (column {} row 2): only its "
                                        "event is punched, column {} must be blank",
                                        slot + 1, b + kConditionModeOffset, c));
            return;
        }
    }
}

void read_slot(const Card& card, const CardLayout& layout, int slot, ConditionOrder& cond,
               Problems& problems) {
    const std::optional<ConditionMode> mode = read_mode(card, slot, problems);
    if (mode == ConditionMode::cancel) {
        read_cancel(card, layout, slot, cond, problems);
        return;
    }
    cond.mode = mode.value_or(ConditionMode::once);
    auto field = [&](FieldKind k) -> const LayoutField& { return slot_field(layout, slot, k); };
    auto required = [&](FieldKind k) {
        const LayoutField& f = field(k);
        std::optional<int> value = read_number(card, f, problems);
        if (!value) {
            problems.add(f.first_column, fmt::format("{} is blank", field_label(f)));
        }
        return value.value_or(0);
    };
    const LayoutField& event = field(FieldKind::event);
    cond.event = required(FieldKind::event);
    if (cond.event == 0 && read_number(card, event, problems)) {
        problems.add(event.first_column,
                     fmt::format("{} is 00 (identifiers are 01..99)", field_label(event)));
    }
    const LayoutField& axis = field(FieldKind::condition_axis);
    const int axis_digit = required(FieldKind::condition_axis);
    if (axis_digit < 1 || axis_digit > kAxisCount) {
        if (read_number(card, axis, problems)) {
            problems.add(axis.first_column,
                         fmt::format("{} is {}: expected 1..5 (table, cross, vertical, swivel, "
                                     "tilt)",
                                     field_label(axis), axis_digit));
        }
    } else {
        cond.axis = kAxes.at(static_cast<std::size_t>(axis_digit - 1));
    }
    const LayoutField& sense = field(FieldKind::sense);
    const ColumnWord s = card.column(sense.first_column) & (r0 | r1);
    if (s == 0) {
        problems.add(sense.first_column,
                     fmt::format("{} is blank (row 0 forward, row 1 reverse, rows 0 and 1 "
                                 "either)",
                                 field_label(sense)));
    }
    cond.sense = s == (r0 | r1) ? PassingSense::either
                 : s == r1      ? PassingSense::reverse
                                : PassingSense::forward;
    cond.position = static_cast<Thousandths>(required(FieldKind::position));
    const LayoutField& action = field(FieldKind::action);
    const int action_digit = required(FieldKind::action);
    if (action_digit >= 1 && action_digit <= kActionKinds) {
        cond.action = static_cast<ActionKind>(action_digit);
    } else if (read_number(card, action, problems)) {
        problems.add(action.first_column,
                     fmt::format("{} is {}: expected 1..8 (docs/card-layout.md)",
                                 field_label(action), action_digit));
    }
    const LayoutField& parameter = field(FieldKind::parameter);
    cond.parameter = read_number(card, parameter, problems).value_or(0);
    if (action_digit >= 1 && action_digit <= kActionKinds) {
        if (auto error = parameter_error(cond.action, cond.parameter)) {
            problems.add(parameter.first_column,
                         fmt::format("{}: {}", field_label(parameter), *error));
        }
    }
}

} // namespace

void add_condition_fields(CardLayout& layout) {
    for (int slot = 0; slot < kConditionsPerCard; ++slot) {
        const int b = 1 + slot * kConditionSlotColumns;
        layout.condition_fields.push_back({FieldKind::event, std::nullopt, b, 2, slot});
        layout.condition_fields.push_back(
            {FieldKind::condition_axis, std::nullopt, b + 2, 1, slot});
        layout.condition_fields.push_back({FieldKind::sense, std::nullopt, b + 3, 1, slot});
        layout.condition_fields.push_back({FieldKind::position, std::nullopt, b + 4, 4, slot});
        layout.condition_fields.push_back({FieldKind::action, std::nullopt, b + 8, 1, slot});
        layout.condition_fields.push_back({FieldKind::parameter, std::nullopt, b + 9, 4, slot});
    }
}

std::string_view condition_field_word(FieldKind kind) {
    switch (kind) {
    case FieldKind::event:
        return "event";
    case FieldKind::condition_axis:
        return "axis";
    case FieldKind::sense:
        return "sense";
    case FieldKind::position:
        return "position";
    case FieldKind::action:
        return "action";
    case FieldKind::parameter:
        return "parameter";
    default:
        return "field";
    }
}

DecodeResult decode_condition_card(const Card& card, const CardLayout& layout) {
    DecodeResult result;
    Problems problems;
    CardOrders& o = result.orders;
    o.kind = CardKind::condition;
    detail::find_strays(card, layout.condition_allowed_rows, layout, CardKind::condition, problems);
    o.number = read_card_number(card, layout, problems);
    int first_blank_slot = -1;
    for (int slot = 0; slot < kConditionsPerCard; ++slot) {
        const int b = 1 + slot * kConditionSlotColumns;
        if (slot_blank(card, b)) {
            first_blank_slot = first_blank_slot < 0 ? slot : first_blank_slot;
            continue;
        }
        if (first_blank_slot >= 0) {
            problems.add(b, fmt::format("condition {} is punched but condition {} before it is "
                                        "blank (the conditions of a card come first)",
                                        slot + 1, first_blank_slot + 1));
        }
        read_slot(card, layout, slot, o.conditions.at(static_cast<std::size_t>(o.condition_count)),
                  problems);
        ++o.condition_count;
    }
    if (o.condition_count == 0) {
        problems.add(layout.extension_column,
                     fmt::format("column {} marks a condition card (row 1), but no condition is "
                                 "punched in columns 1-75",
                                 layout.extension_column));
    }
    result.bad_punch = problems.first();
    return result;
}

std::optional<std::string> encode_condition_card(const CardOrders& orders, const CardLayout& layout,
                                                 Card& card) {
    if (layout.extension_column == 0) {
        return fmt::format("layout {} has no extension column for condition cards", layout.name);
    }
    if (orders.condition_count < 1 || orders.condition_count > kConditionsPerCard) {
        return fmt::format("a condition card holds 1..{} conditions, not {}", kConditionsPerCard,
                           orders.condition_count);
    }
    auto punch_number = [&](const LayoutField& f, int value) {
        return detail::punch_number(card, f, value);
    };
    card.punch(layout.extension_column, Row::r1);
    for (int slot = 0; slot < orders.condition_count; ++slot) {
        const ConditionOrder& c = orders.conditions.at(static_cast<std::size_t>(slot));
        auto field = [&](FieldKind k) -> const LayoutField& { return slot_field(layout, slot, k); };
        if (c.event < 1 || c.event > 99) {
            return fmt::format("condition {}: event {} is not 1..99", slot + 1, c.event);
        }
        const int mode_column = 1 + slot * kConditionSlotColumns + kConditionModeOffset;
        if (c.mode == ConditionMode::cancel) {
            card.punch(mode_column, Row::r2);
            if (auto error = punch_number(field(FieldKind::event), c.event)) {
                return error;
            }
            continue;
        }
        if (c.mode == ConditionMode::every) {
            card.punch(mode_column, Row::r1);
        }
        if (auto error = parameter_error(c.action, c.parameter)) {
            return fmt::format("condition {}: {}", slot + 1, *error);
        }
        for (auto error : {punch_number(field(FieldKind::event), c.event),
                           punch_number(field(FieldKind::condition_axis),
                                        static_cast<int>(axis_index(c.axis)) + 1),
                           punch_number(field(FieldKind::position), c.position),
                           punch_number(field(FieldKind::action), static_cast<int>(c.action))}) {
            if (error) {
                return error;
            }
        }
        if (c.parameter != 0) {
            if (auto error = punch_number(field(FieldKind::parameter), c.parameter)) {
                return error;
            }
        }
        const int sense = field(FieldKind::sense).first_column;
        if (c.sense != PassingSense::reverse) {
            card.punch(sense, Row::r0);
        }
        if (c.sense != PassingSense::forward) {
            card.punch(sense, Row::r1);
        }
    }
    return std::nullopt;
}

} // namespace parsons::cardreader
