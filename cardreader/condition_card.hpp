// The condition card: an addition after EP 0640901 (Siemens), not in the patent.
//
// The seed's part program puts condition records (its N50; N100-N120) before the motion record
// they watch (N60; N130): "if the axis passes this position, start this action". parsons punches
// them on a card of their own, marked by row 1 of column 76 (the column the 1952 layout leaves
// unused), with the card number where every card has it (77-80). Five condition slots of 15
// columns each fill columns 1-75:
//
//   slot k (k = 0..4) begins at column b = 1 + 15 k
//   b, b+1      event identifier 01..99, shared by the condition and its action (claim 3)
//   b+2         axis digit 1..5 (table, cross, vertical, swivel, tilt)
//   b+3         sense of passing: row 0 forward (counting up), row 1 reverse, rows 0 and 1 either
//   b+4 .. b+7  position d.ddd, compared with the axis's absolute counter
//   b+8         action digit 1..8 (orders.hpp ActionKind)
//   b+9 .. b+12 parameter, four digits, blank = 0 (tool number, held axis, lamp number)
//   b+13        mode (an addition beyond the seed's claims, after Siemens' WHENEVER/EVERY):
//               blank once (the seed's condition), 1 every (armed for every motion card until
//               a cancel or the deck's end), 2 cancel (ends the every-condition of the event in
//               b, b+1; every other column of the slot blank)
//   b+14        blank
//
// A slot whose columns are all blank is unused; the used slots must come first. decode and
// encode are pure, as for the motion card (layout.hpp).
#pragma once

#include "cardreader/layout.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace parsons::cardreader {

inline constexpr int kConditionSlotColumns = 15;
// The mode column's offset in its slot (column 14 of slot 1).
inline constexpr int kConditionModeOffset = 13;

// Column c (1..80) is a slot's mode column.
constexpr bool is_condition_mode_column(int c) {
    return c >= 1 && c <= kConditionsPerCard * kConditionSlotColumns &&
           (c - 1) % kConditionSlotColumns == kConditionModeOffset;
}

// Adds the condition-card fields to a layout whose extension column is set.
void add_condition_fields(CardLayout& layout);
// "event", "axis", "sense", "position", "action", "parameter"
std::string_view condition_field_word(FieldKind kind);

DecodeResult decode_condition_card(const Card& card, const CardLayout& layout);
// Punches a condition card's records and its mark; the error names the condition and field.
std::optional<std::string> encode_condition_card(const CardOrders& orders, const CardLayout& layout,
                                                 Card& card);

} // namespace parsons::cardreader
