// The segment card: an addition after EP 0636958 (Black & Decker), not in the 1952 patent.
//
// The seed's machine moves a tool "along a pre-established path which comprises a plurality of
// path segments sequential to one another", each at "a pre-established nominal speed" (claim 1),
// its three Cartesian axes driven by stepper motors (claims 3, 11, 16). parsons punches one
// segment on a card of its own, marked by row 4 of column 76 (row 1 marks a condition card,
// row 2 a sync card, row 3 a tap card), with the card number where every card has it (77-80):
//
//   column  1       blank
//   2 .. 5          X: the end point on the table's axis, d.ddd in
//   6 .. 9          Y: the end point on the cross slide's axis, d.ddd in
//   10 .. 13        Z: the end point on the vertical slide's axis, d.ddd in
//   14 .. 16        F: the nominal speed along the segment, three digits dd.d in/min, 00.1-99.9
//   column 76       row 4, the extension mark
//   every other column blank
//
// The segment starts where the one before it ended (the first where the stepper axes stand,
// 0.000 0.000 0.000 at the start of a run). All three end points are always punched; a segment
// that goes nowhere (its end point the start) is the deck review's to refuse. decode and encode
// are pure, as for the motion card (layout.hpp).
#pragma once

#include "cardreader/layout.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace parsons::cardreader {

// Adds the segment-card fields to a layout whose extension column is set.
void add_segment_fields(CardLayout& layout);
// "segment X", "segment Y", "segment Z", "segment feed"
std::string segment_field_label(const LayoutField& field);
// Short labels for card pictures: "X", "Y", "Z", "FEED F"
std::string_view segment_field_short_label(FieldKind kind);

DecodeResult decode_segment_card(const Card& card, const CardLayout& layout);
// Punches a segment card's order and its mark (not the card number); the error says what the
// card cannot hold.
std::optional<std::string> encode_segment_card(const SegmentOrder& order, const CardLayout& layout,
                                               Card& card);

// What is wrong with a segment order that no card can hold (an end point outside 0..9.999 in, a
// feed outside 00.1..99.9 in/min), or nothing.
std::optional<std::string> segment_order_error(const SegmentOrder& order);

// The whole card a segment order is punched on, its number `number` (0..9999).
EncodeResult segment_card(const SegmentOrder& order, int number,
                          const CardLayout& layout = fig8_layout());

// The axis a segment coordinate drives: X the table, Y the cross slide, Z the vertical slide.
Axis segment_axis(int i);
// "X", "Y", "Z"
std::string_view segment_axis_letter(int i);

} // namespace parsons::cardreader
