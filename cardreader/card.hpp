// The punched card: 80 columns of 12 punch positions (an IBM 5081-style card, Fig. 8 card 162).
//
// The real card is read column by column by the brushes of card reader 134; a hole lets a
// brush touch the contact roller. We represent a column by the 12-bit "Hollerith word" SIMH
// uses: row 12 in bit 11 down to row 9 in bit 0. The row order is written down here, once.
//
//     bit:  11  10   9   8   7   6   5   4   3   2   1   0
//     row:  12  11   0   1   2   3   4   5   6   7   8   9
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace parsons::cardreader {

inline constexpr int kColumns = 80;
inline constexpr int kRows = 12;

// One column's punches, rows 12 .. 9 in bits 11 .. 0.
using ColumnWord = std::uint16_t;
inline constexpr ColumnWord kAllRowsMask = 0x0FFF;

// The rows from the top edge of the card down.
enum class Row : std::uint8_t { r12, r11, r0, r1, r2, r3, r4, r5, r6, r7, r8, r9 };

inline constexpr std::array<Row, kRows> kRowsTopToBottom = {Row::r12, Row::r11, Row::r0, Row::r1,
                                                            Row::r2,  Row::r3,  Row::r4, Row::r5,
                                                            Row::r6,  Row::r7,  Row::r8, Row::r9};

constexpr ColumnWord row_bit(Row r) {
    return static_cast<ColumnWord>(0x800u >> static_cast<unsigned>(r));
}

// The digit row 0..9 (the rows printed on the card).
constexpr Row digit_row(int digit) {
    return static_cast<Row>(static_cast<int>(Row::r0) + digit);
}

// Row by its printed name: 12, 11, 0 .. 9. Precondition: name is one of those.
constexpr Row row_named(int name) {
    if (name == 12) {
        return Row::r12;
    }
    if (name == 11) {
        return Row::r11;
    }
    return digit_row(name);
}

// "12", "11", "0" .. "9".
std::string_view row_name(Row r);

// The punches of a column as a keypunch operator says them: "12-8-3", "0", or "blank".
std::string punches_text(ColumnWord word);

// Number of holes in a column.
int hole_count(ColumnWord word);

class Card {
public:
    Card() = default;
    // Every column at once, column 1 first, each word masked to the twelve rows (a reader's
    // whole card in one copy: no column number to check).
    explicit Card(const std::array<ColumnWord, kColumns>& columns) {
        for (std::size_t i = 0; i < columns.size(); ++i) {
            columns_[i] = columns[i] & kAllRowsMask;
        }
    }
    // Columns are numbered 1 .. 80 as printed on the card.
    ColumnWord column(int col) const { return columns_.at(static_cast<std::size_t>(col - 1)); }
    void set_column(int col, ColumnWord word) {
        columns_.at(static_cast<std::size_t>(col - 1)) = word & kAllRowsMask;
    }
    bool punched(int col, Row r) const { return (column(col) & row_bit(r)) != 0; }
    void punch(int col, Row r) { set_column(col, column(col) | row_bit(r)); }
    bool blank() const;

    // Every column at once, column 1 first (for loops over the whole card).
    const std::array<ColumnWord, kColumns>& columns() const { return columns_; }

    bool operator==(const Card&) const = default;

private:
    std::array<ColumnWord, kColumns> columns_{};
};

} // namespace parsons::cardreader
