// Reading punched fields (field_reading.hpp): shared by the motion card, the condition card, the
// sync card and the tap card.
#include "cardreader/field_reading.hpp"

#include <fmt/format.h>

#include <array>
#include <cstdint>
#include <stdexcept>

namespace parsons::cardreader {

namespace detail {

std::string join_rows(ColumnWord word) {
    std::string text;
    for (Row r : kRowsTopToBottom) {
        if ((word & row_bit(r)) != 0) {
            text += text.empty() ? "" : " and ";
            text += row_name(r);
        }
    }
    return text;
}

namespace {

// What rows 0..9 of a column read as, for every way of punching them: the digit, kBlank or
// kDoublePunch: digit_of() for each, worked out when compiled, so that a number column costs a
// look-up.
constexpr std::int8_t kBlank = -1;
constexpr std::int8_t kDoublePunch = -2;
constexpr std::array<std::int8_t, kDigitRows + 1> kDigitRead = [] {
    std::array<std::int8_t, kDigitRows + 1> read{};
    for (unsigned rows = 0; rows <= kDigitRows; ++rows) {
        const int d = digit_of(static_cast<ColumnWord>(rows));
        read.at(rows) = rows == 0 ? kBlank : d < 0 ? kDoublePunch : static_cast<std::int8_t>(d);
    }
    return read;
}();

} // namespace

std::optional<int> read_number(const Card& card, const LayoutField& f, Problems& problems) {
    int value = 0;
    int blanks = 0;
    int first_blank = 0;
    bool bad = false;
    if (f.first_column < 1 || f.last_column() > kColumns) {
        throw std::out_of_range(fmt::format("{}: columns {}..{} are not on the card",
                                            field_label(f), f.first_column, f.last_column()));
    }
    const auto& columns = card.columns();
    for (int c = f.first_column; c <= f.last_column(); ++c) {
        const auto digits =
            static_cast<ColumnWord>(columns[static_cast<std::size_t>(c - 1)] & kDigitRows);
        const int d = kDigitRead[digits];
        if (d == kBlank) {
            blanks += 1;
            first_blank = first_blank == 0 ? c : first_blank;
            value *= 10;
            continue;
        }
        if (d == kDoublePunch) {
            problems.add(
                c, fmt::format("double punch (rows {}) in {}", join_rows(digits), field_label(f)));
            bad = true;
            continue;
        }
        value = value * 10 + d;
    }
    if (blanks == f.width) {
        return std::nullopt;
    }
    if (blanks > 0) {
        problems.add(first_blank,
                     fmt::format("blank digit inside the number in {}", field_label(f)));
        bad = true;
    }
    return bad ? 0 : value;
}

std::optional<std::string> punch_number(Card& card, const LayoutField& f, int value) {
    int max = 1;
    for (int i = 0; i < f.width; ++i) {
        max *= 10;
    }
    if (value < 0 || value >= max) {
        return fmt::format("{} value {} does not fit in {} digit columns", field_label(f), value,
                           f.width);
    }
    for (int c = f.last_column(); c >= f.first_column; --c) {
        card.punch(c, digit_row(value % 10));
        value /= 10;
    }
    return std::nullopt;
}

void find_strays(const Card& card, const std::array<ColumnWord, kColumns + 1>& allowed,
                 const CardLayout& layout, CardKind kind, Problems& problems) {
    // Looked for column by column only on a card that has any (a whole-card test first,
    // branch-free).
    ColumnWord strays = 0;
    for (std::size_t i = 0; i < static_cast<std::size_t>(kColumns); ++i) {
        strays |= static_cast<ColumnWord>(card.columns()[i] & ~allowed[i + 1]);
    }
    for (int c = 1; strays != 0 && c <= kColumns; ++c) {
        ColumnWord stray = card.column(c) &
                           static_cast<ColumnWord>(~allowed[static_cast<std::size_t>(c)]) &
                           kAllRowsMask;
        if (stray != 0) {
            const LayoutField* f = kind == CardKind::condition ? layout.condition_field_at(c)
                                   : kind == CardKind::sync    ? layout.sync_field_at(c)
                                   : kind == CardKind::tap     ? layout.tap_field_at(c)
                                   : kind == CardKind::segment ? layout.segment_field_at(c)
                                                               : layout.field_at(c);
            std::string where =
                f ? fmt::format("in {}", field_label(*f))
                  : fmt::format("in column {}, which layout {} leaves unused{}", c, layout.name,
                                kind == CardKind::condition ? " on a condition card"
                                : kind == CardKind::sync    ? " on a sync card"
                                : kind == CardKind::tap     ? " on a tap card"
                                : kind == CardKind::segment ? " on a segment card"
                                                            : "");
            problems.add(c, fmt::format("punch in {} {} where none belongs ({})",
                                        hole_count(stray) == 1 ? "row" : "rows", join_rows(stray),
                                        where));
        }
    }
}

int read_card_number(const Card& card, const CardLayout& layout, Problems& problems) {
    const LayoutField* f = layout.find(FieldKind::card_number);
    if (f == nullptr) {
        return 0;
    }
    const std::optional<int> number = read_number(card, *f, problems);
    if (!number) {
        problems.add(f->first_column, "card number is blank (it is always punched)");
    }
    return number.value_or(0);
}

} // namespace detail

} // namespace parsons::cardreader
