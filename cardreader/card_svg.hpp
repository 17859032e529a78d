// A picture of card 162 as it would lie on the desk: cream 5081-style stock with its clipped
// corner, the digits 0-9 printed in every column, column numbers under rows 0 and 9, the
// keypunch's interpretation printed along the top edge, the layout's field names and rules
// printed over the column groups (heavy rules 164 between the axis sections, as in Fig. 8),
// the row of cross marks of each sequence pattern 222, and rectangular holes.
//
// Dimensions are the real card's, in hundredths of an inch: 7.375 x 3.25 in, column pitch
// 0.087 in, row pitch 0.25 in, holes 0.055 x 0.125 in.
#pragma once

#include "cardreader/card.hpp"
#include "cardreader/hollerith.hpp"
#include "cardreader/layout.hpp"

#include <optional>
#include <string>

namespace parsons::cardreader {

struct CardPictureNotes {
    std::string caption;               // printed under the card ("sample.cbn, card 1 ...")
    std::optional<BadPunch> bad_punch; // outlined in red, and named under the card
};

// Text made safe for SVG/XML character data and attribute values.
std::string xml_escape(std::string_view text);

std::string card_svg(const Card& card, const CardLayout& layout, const CardPictureNotes& notes,
                     KeypunchCode code = KeypunchCode::ibm029);

} // namespace parsons::cardreader
