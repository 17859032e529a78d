#include "cardreader/card.hpp"

#include <algorithm>
#include <bit>

namespace parsons::cardreader {

std::string_view row_name(Row r) {
    static constexpr std::array<std::string_view, kRows> names = {"12", "11", "0", "1", "2", "3",
                                                                  "4",  "5",  "6", "7", "8", "9"};
    return names.at(static_cast<std::size_t>(r));
}

std::string punches_text(ColumnWord word) {
    // IBM's charts name the zone (12, 11, 0) first, then the 8, then the digit: "12-8-3".
    static constexpr std::array<Row, kRows> spoken_order = {Row::r12, Row::r11, Row::r0, Row::r8,
                                                            Row::r1,  Row::r2,  Row::r3, Row::r4,
                                                            Row::r5,  Row::r6,  Row::r7, Row::r9};
    std::string text;
    for (Row r : spoken_order) {
        if ((word & row_bit(r)) != 0) {
            if (!text.empty()) {
                text += '-';
            }
            text += row_name(r);
        }
    }
    return text.empty() ? "blank" : text;
}

int hole_count(ColumnWord word) {
    return std::popcount(static_cast<unsigned>(word & kAllRowsMask));
}

bool Card::blank() const {
    return std::all_of(columns_.begin(), columns_.end(), [](ColumnWord w) { return w == 0; });
}

} // namespace parsons::cardreader
