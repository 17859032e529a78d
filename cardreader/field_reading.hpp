// Reading punched fields, shared by the motion card's decode (layout.cpp), the condition
// card's (condition_card.cpp), the sync card's (sync_card.cpp), the tap card's (tap_card.cpp) and
// the segment card's (segment_card.cpp): a digit column, a number of digit columns, and the
// collection of bad punches that reports the lowest column first.
#pragma once

#include "cardreader/card.hpp"
#include "cardreader/layout.hpp"

#include <bit>
#include <optional>
#include <string>

namespace parsons::cardreader::detail {

inline constexpr ColumnWord kDigitRows = 0x03FF; // rows 0 .. 9
inline constexpr ColumnWord r0 = row_bit(Row::r0);
inline constexpr ColumnWord r1 = row_bit(Row::r1);

// "0 and 1": the rows punched in a column word, top to bottom.
std::string join_rows(ColumnWord word);

// The digit of a column punched in one of rows 0..9, or -1 (blank or a double punch).
// Row d is bit 9 - d of the column word.
constexpr int digit_of(ColumnWord digits) {
    static_assert(row_bit(digit_row(0)) == 1U << 9 && row_bit(digit_row(9)) == 1U);
    if (digits == 0 || (digits & (digits - 1)) != 0) {
        return -1;
    }
    return 9 - std::countr_zero(static_cast<unsigned>(digits));
}

// Collects the bad punch with the lowest column: the one the operator finds first.
class Problems {
public:
    void add(int column, std::string what) {
        if (!first_ || column < first_->column) {
            first_ = BadPunch{column, std::move(what)};
        }
    }
    std::optional<BadPunch> first() const { return first_; }

private:
    std::optional<BadPunch> first_;
};

// Reads a digit field; nothing if every column is blank. A double punch or a blank inside the
// number is added to `problems` (and the value read as 0).
std::optional<int> read_number(const Card& card, const LayoutField& f, Problems& problems);

// The keypunch: `value` in the field's digit columns, or why it does not fit.
std::optional<std::string> punch_number(Card& card, const LayoutField& f, int value);

// The card number of columns 77-80 on a card of an addition's kind, always punched: its bad
// punch, or its being blank, added to `problems` (and 0 read).
int read_card_number(const Card& card, const CardLayout& layout, Problems& problems);

// Punches in columns where the table `allowed` (index 1..80) allows none, each named by the
// field of a card of this kind the column belongs to.
void find_strays(const Card& card, const std::array<ColumnWord, kColumns + 1>& allowed,
                 const CardLayout& layout, CardKind kind, Problems& problems);

} // namespace parsons::cardreader::detail
