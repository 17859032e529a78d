// The tap card: an addition after EP 0360190 (Mitsubishi), not in the patent.
//
// Claim 1 of the seed: gear ratio data memory 12a holds the ratio of gear means 30, through which
// spindle motor 27 drives the spindle head 31 that holds tool 16, selected by the tool number the
// machining program specifies; the synchronous operation control means works out the tool's
// real speed from that ratio and the motor's feedback (S x A, Fig. 7 step S34) and runs the tool
// and a feed shaft in step. The seed's program gives the tool number T and the speed S; parsons
// punches them, with the feed axis, its sense, the depth and the pitch of the hole, on a card of
// their own, marked by row 3 of column 76 (row 1 marks a condition card, row 2 a sync card), with
// the card number where every card has it (77-80):
//
//   column  1       blank
//   2 .. 3          tool T, 01-99: the spindle head that holds it (PC 130 puts it on)
//   column  4       feed axis: one digit 1-5 (table, cross, vertical, swivel, tilt)
//   column  5       sense into the work: row 0 forward (counters count up), row 1 reverse
//   6 .. 9          depth d.ddd in, 0.001-9.999
//   10 .. 14        pitch: five digits read 0.ddddd in per tool revolution, 00001-99999
//   15 .. 18        spindle motor 27's speed S, 0001-9999 rev/min
//   column 19       index wait (rigid tapping, an addition): blank none, 1 the feed waits for
//                   encoder 32's index (docs/tapping.md, "Rigid tapping")
//   column 20       retract multiple k (rigid tapping, an addition): blank or 1, out at S; 2-4,
//                   motor 27 reverses to k x S (the feed follows, the pitch held)
//   21 .. 24        peck depth Q (rigid peck tapping, an addition): blank, one pass; d.ddd in,
//                   0001-9999, in to Q, out, in to 2Q, ... the feed on one helix throughout
//   column 76       row 3, the extension mark
//   every other column blank
//
// A tap card stands alone: it taps one hole (in to the depth, back out as the spindle reverses)
// and no axis moves by the 1952 columns on it. Whether the machine can tap it (the profile has
// spindle synchronisation, a head holds the tool, the motor reaches S, the drive follows the
// feed) is the deck review's (tap_review.hpp). decode and encode are pure, as for the motion card
// (layout.hpp).
// Emulation note: the seed's program is metric and its tapping block is its own; the card holds
// inches, as every number of the 1952 machine does, the pitch to five decimals.
#pragma once

#include "cardreader/layout.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace parsons::cardreader {

// Adds the tap-card fields to a layout whose extension column is set.
void add_tap_fields(CardLayout& layout);
// "tap tool", "tap feed axis", "tap sense", "tap depth", "tap pitch", "tap speed",
// "tap index wait", "tap retract multiple", "tap peck depth"
std::string tap_field_label(const LayoutField& field);
// Short labels for card pictures: "TOOL T", "AXIS", "SENSE", "DEPTH", "PITCH", "SPEED S", "INDEX",
// "RETRACT", "PECK Q"
std::string_view tap_field_short_label(FieldKind kind);
// What columns 21-24 order, for `parsons show`: "0.100 in a peck: 3 passes in to 0.300 in, ..."
// or "blank: one pass to the depth".
std::string tap_peck_text(const TapOrder& t);

DecodeResult decode_tap_card(const Card& card, const CardLayout& layout);
// Punches a tap card's order and its mark (not the card number); the error says what the card
// cannot hold.
std::optional<std::string> encode_tap_card(const TapOrder& order, const CardLayout& layout,
                                           Card& card);

// What is wrong with a tap order that no card can hold (a tool outside 1..99, a depth of 0,
// a pitch or speed of 0 or too many digits, an axis that is none of the five), or nothing.
std::optional<std::string> tap_order_error(const TapOrder& order);

// The whole card a tap order is punched on, its number `number` (0..9999): what the job
// generator and the cabinet's tests use. The error says what the card cannot hold.
EncodeResult tap_card(const TapOrder& order, int number, const CardLayout& layout = fig8_layout());

} // namespace parsons::cardreader
