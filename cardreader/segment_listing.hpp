// A segment card (an addition after EP 0636958, Black & Decker; segment_card.hpp) in the
// listing: one row, with the word `segment` where a motion row has its spindle
// (docs/deck-formats.md):
//
//   card,segment,X,Y,Z,F
//   3,segment,2.000,0.500,0.000,20.0
//
// X, Y, Z the end point, d.ddd in (0.000 .. 9.999); F the nominal speed along the segment,
// dd.d in/min (0.1 .. 99.9).
#pragma once

#include "cardreader/orders.hpp"

#include <string>
#include <string_view>
#include <utility>

namespace parsons::cardreader {

// Is this listing line a segment row (its second field the word `segment`)?
bool is_segment_row(std::string_view text);

// Reads one segment row: its card number and its order. Throws DeckError naming file and line
// for a bad row.
std::pair<int, SegmentOrder> read_segment_row(std::string_view text, const std::string& file,
                                              std::int64_t line);

// The listing row of a segment card, without a newline.
std::string segment_row(const CardOrders& orders);

} // namespace parsons::cardreader
