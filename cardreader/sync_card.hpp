// The sync card: an addition after EP 0436887 (Mitsubishi), not in the patent.
//
// The seed's Fig. 3 program puts its synchronisation commands in the block of the motion they
// govern: step 3 "G95 G101 R30 F10" (start when crank 21 reaches 30 degrees, travel 10 mm per
// pulse of detector 10), step 5 "G95 F20", and step 11 "M99" (the program goes back to its
// start). parsons punches them on a card of their own, standing before the motion card it
// synchronises, marked by row 2 of column 76 (row 1 marks a condition card), with the card
// number where every card has it (77-80):
//
//   column  2       position sync (G101): row 0
//   3 .. 5          the crank angle R, 000-359 degrees from top dead centre
//   column  6       loop (M99): row 0
//   7 .. 10         the card number the reader goes back to
//   11 .. 14        how many times, 0001-9999
//   column 15       register 14 reset (switch 16A, claim 5): row 0
//   16-20 table, 21-25 cross, 26-30 vertical, 31-35 swivel, 36-40 tilt
//                   speed sync (G95 F): the travel per detector pulse, five digits read
//                   0.ddddd in; blank = the axis is not speed-synchronised
//   column 76       row 2, the extension mark
//   every other column blank
//
// A loop card stands alone, as the seed's M99 is a block of its own: a card with the loop mark
// carries no synchronisation and no reset. The reset acts as the card is read (the crank's angle
// there becomes the reference R counts from); a card of the reset alone needs no motion card.
// decode and encode are pure, as for the motion card (layout.hpp). Emulation note: the seed's F is
// millimetres per pulse; the card holds inches, as every number of the 1952 machine does, to five
// decimals (a pulse is a fraction of a degree).
#pragma once

#include "cardreader/layout.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace parsons::cardreader {

inline constexpr int kMaxSyncAngle = 359; // degrees: the crank angle R, 000..359
inline constexpr int kMaxLoopCount = 9999;

// Adds the sync-card fields to a layout whose extension column is set.
void add_sync_fields(CardLayout& layout);
// "sync angle", "loop target", "table travel per pulse"
std::string sync_field_label(const LayoutField& field);
// Short labels for card pictures: "G101", "ANGLE R", "M99", "LOOP TO", "COUNT", "F / PULSE"
std::string_view sync_field_short_label(FieldKind kind);

DecodeResult decode_sync_card(const Card& card, const CardLayout& layout);
// Punches a sync card's orders and its mark (not the card number); the error says what the
// card cannot hold.
std::optional<std::string> encode_sync_card(const SyncOrder& order, const CardLayout& layout,
                                            Card& card);

// What is wrong with a sync card's orders that no card can hold (an angle over 359, a travel
// per pulse of 0, a loop with synchronisation, nothing at all), or nothing.
std::optional<std::string> sync_order_error(const SyncOrder& order);

} // namespace parsons::cardreader
