// A tap card (an addition after EP 0360190, Mitsubishi; tap_card.hpp) in the listing: one row,
// with the word `tap` where a motion row has its spindle (docs/deck-formats.md):
//
//   card,tap,TOOL,AXIS,SENSE,DEPTH,PITCH,RPM
//   12,tap,1,vertical,reverse,0.600,0.05000,240
//
// TOOL 1..99; AXIS table .. tilt; SENSE forward or reverse (the sense into the work, as the
// axis's counters count); DEPTH d.ddd in, over 0; PITCH 0.ddddd in per tool revolution, over 0;
// RPM spindle motor 27's speed S, 1..9999 rev/min. Then the rigid-tapping additions, each a
// word, each at most once, written only when ordered: `index` (the feed waits for encoder 32's
// index; column 19 punched 1), `retract=K` (K 1..4: the return stroke at K x S; column 20,
// written only for K over 1), `peck=D.DDD` (the peck depth Q, 0.001..9.999 in: in to Q, out,
// in to 2Q, ... to the depth; columns 21-24, written only when punched).
#pragma once

#include "cardreader/orders.hpp"

#include <string>
#include <string_view>
#include <utility>

namespace parsons::cardreader {

// Is this listing line a tap row (its second field the word `tap`)?
bool is_tap_row(std::string_view text);

// Reads one tap row: its card number and its order. Throws DeckError naming file and line for
// a bad row.
std::pair<int, TapOrder> read_tap_row(std::string_view text, const std::string& file,
                                      std::int64_t line);

// The listing row of a tap card, without a newline.
std::string tap_row(const CardOrders& orders);

} // namespace parsons::cardreader
