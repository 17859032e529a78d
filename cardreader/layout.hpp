// The card layout: which columns of card 162 (Fig. 8) hold which field, as a table of fields.
//
// The reader's brushes are wired to columns by a plugboard; a layout is that plugboard.
// Figure 8 itself is not legible in the patent text we have, so the default "fig8" layout is
// the reconstruction told in docs/card-layout.md (docs/design-rules.md, The card layout).
// Other layouts are other tables.
//
// decode() is pure: a card and a layout in, the orders or the first bad punch out (naming the
// column and what is wrong). encode() is the keypunch: orders in, the holes out.
#pragma once

#include "cardreader/card.hpp"
#include "cardreader/orders.hpp"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace parsons::cardreader {

enum class FieldKind : std::uint8_t {
    spindle,     // one column: row 0 forward, row 1 reverse, blank off
    motion,      // one column: row 0 forward, row 1 reverse
    start_speed, // one column: 0 / 0-1 / 0-1-2 = speed 1 / 2 / 3
    slow_down_1, // digit columns d.ddd, blank = no slow-down
    slow_down_2, // digit columns d.ddd, blank = no slow-down
    stop,        // digit columns d.ddd, always punched
    check,       // digit columns d.ddd, always punched
    card_number, // digit columns, always punched
    // Column 76, the extension mark (an addition): row 1 = a condition card.
    extension,
    // The fields of a condition card (an addition after EP 0640901; docs/card-layout.md), one
    // set per condition slot: the event identifier, the axis (1..5), the sense of passing
    // (row 0 forward, row 1 reverse, both either), the position d.ddd, the action (1..8) and
    // its parameter (blank = 0).
    event,
    condition_axis,
    sense,
    position,
    action,
    parameter,
    // The fields of a sync card (an addition after EP 0436887; docs/card-layout.md): the
    // position-sync mark (G101, row 0), the crank angle R (three digits, degrees), the loop
    // mark (M99, row 0), the card number the loop goes back to, how many times, the reset of
    // register 14 (switch 16A, row 0), and per axis the travel per detector pulse (G95 F, five
    // digits read 0.ddddd in; blank = none).
    position_sync,
    sync_angle,
    loop_mark,
    loop_target,
    loop_count,
    register_reset,
    travel_per_pulse,
    // The fields of a tap card (an addition after EP 0360190; docs/card-layout.md): the tool T
    // (two digits, 01-99), the feed axis (one digit 1-5), the sense into the work (row 0
    // forward, row 1 reverse), the depth (d.ddd in), the pitch (five digits read 0.ddddd in per
    // tool revolution) and spindle motor 27's speed S (four digits, rev/min); the rigid-tapping
    // additions: the index wait (one digit, blank or 1), the retract multiple k (one digit, blank
    // or 1-4), the peck depth Q (four digits, d.ddd in, blank for one pass).
    tap_tool,
    tap_axis,
    tap_sense,
    tap_depth,
    tap_pitch,
    tap_rpm,
    tap_index,
    tap_retract,
    tap_peck,
    // The fields of a segment card (an addition after EP 0636958; docs/card-layout.md): the end
    // point in X, Y and Z (d.ddd in each, axis table, cross, vertical) and the feed F (three
    // digits, tenths of an inch a minute).
    segment_end,
    segment_feed,
};

struct LayoutField {
    FieldKind kind;
    std::optional<Axis> axis; // none for spindle and card number
    int first_column;         // 1 .. 80
    int width;                // columns
    int slot = -1;            // condition slot 0..4 (condition-card fields), else -1

    int last_column() const { return first_column + width - 1; }
};

struct CardLayout {
    std::string name;
    std::vector<LayoutField> fields;
    // Sequence pattern 222 of each axis: row 12 of five consecutive columns starting here.
    std::array<int, kAxisCount> sequence_first_column{};

    const LayoutField* find(FieldKind kind, std::optional<Axis> axis = std::nullopt) const;
    const LayoutField* field_at(int column) const;
    // The sequence position (1..5) and axis whose cross mark sits in row 12 of this column.
    std::optional<std::pair<Axis, int>> sequence_at(int column) const;

    // The condition card (an addition): the extension mark's column (0 = the layout has
    // none, so no condition cards) and the fields of a card marked there in row 1. The card
    // number stays where the motion card has it.
    int extension_column = 0;
    std::vector<LayoutField> condition_fields;
    const LayoutField* condition_field_at(int column) const;

    // The sync card (an addition): the fields of a card marked in row 2 of the extension
    // column; the card number stays where the motion card has it.
    std::vector<LayoutField> sync_fields;
    const LayoutField* sync_field_at(int column) const;
    const LayoutField* find_sync(FieldKind kind, std::optional<Axis> axis = std::nullopt) const;

    // The tap card (an addition): the fields of a card marked in row 3 of the extension column;
    // the card number stays where the motion card has it.
    std::vector<LayoutField> tap_fields;
    const LayoutField* tap_field_at(int column) const;
    const LayoutField* find_tap(FieldKind kind) const;

    // The segment card (an addition): the fields of a card marked in row 4 of the extension
    // column; the card number stays where the motion card has it.
    std::vector<LayoutField> segment_fields;
    const LayoutField* segment_field_at(int column) const;
    const LayoutField* find_segment(FieldKind kind, std::optional<Axis> axis = std::nullopt) const;

    // The rows each column may be punched in (index 1..80), worked out once by index(): on a
    // motion card, on a condition card, on a sync card and on a tap card.
    std::array<ColumnWord, kColumns + 1> allowed_rows{};
    std::array<ColumnWord, kColumns + 1> condition_allowed_rows{};
    std::array<ColumnWord, kColumns + 1> sync_allowed_rows{};
    std::array<ColumnWord, kColumns + 1> tap_allowed_rows{};
    std::array<ColumnWord, kColumns + 1> segment_allowed_rows{};
    void index();
};

// Is this card marked as a condition card (row 1 of the layout's extension column)?
bool is_condition_card(const Card& card, const CardLayout& layout);
// Is this card marked as a sync card (row 2 of the layout's extension column)?
bool is_sync_card(const Card& card, const CardLayout& layout);
// Is this card marked as a tap card (row 3 of the layout's extension column)?
bool is_tap_card(const Card& card, const CardLayout& layout);
// Is this card marked as a segment card (row 4 of the layout's extension column)?
bool is_segment_card(const Card& card, const CardLayout& layout);
// Is it any of them (an extension card: an addition, whose double punches are bad punches in
// every profile)?
bool is_extension_card(const Card& card, const CardLayout& layout);

// "table stop", "spindle", "card number", "condition 2 position", "sync angle",
// "table travel per pulse", "tap pitch"
std::string field_label(const LayoutField& field);
// Short label for card pictures: "STOP", "SLOW 1", "CHECK"
std::string_view field_short_label(FieldKind kind);

const CardLayout& fig8_layout();
// The layouts a card reader can be plugged for, by name ("fig8"), and the one of a name.
inline constexpr std::array<std::string_view, 1> kLayoutNames = {"fig8"};
const CardLayout* layout_named(std::string_view name);

// A punch the layout cannot read; the reader stops the machine and names the column.
struct BadPunch {
    int column;
    std::string what;
};

struct DecodeResult {
    CardOrders orders;
    std::optional<BadPunch> bad_punch;
    explicit operator bool() const { return !bad_punch; }
};

DecodeResult decode(const Card& card, const CardLayout& layout);

// Orders a layout cannot hold (a second slow-down for an axis with no such field, a number
// over 9.999): the message names the axis and field.
struct EncodeResult {
    Card card;
    std::optional<std::string> error;
    explicit operator bool() const { return !error; }
};

EncodeResult encode(const CardOrders& orders, const CardLayout& layout);

} // namespace parsons::cardreader
