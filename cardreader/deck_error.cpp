#include "cardreader/deck_error.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace parsons::cardreader {

namespace {

// The length of the valid UTF-8 sequence at text[i] (1 for ASCII), or 0 when it is none.
std::size_t utf8_length(std::string_view text, std::size_t i) {
    const auto b = static_cast<unsigned char>(text[i]);
    const std::size_t n = b < 0x80             ? 1
                          : (b & 0xE0) == 0xC0 ? 2
                          : (b & 0xF0) == 0xE0 ? 3
                          : (b & 0xF8) == 0xF0 ? 4
                                               : 0;
    if (n == 0 || (n == 2 && b < 0xC2) || i + n > text.size()) {
        return 0;
    }
    for (std::size_t k = 1; k < n; ++k) {
        if ((static_cast<unsigned char>(text[i + k]) & 0xC0) != 0x80) {
            return 0;
        }
    }
    return n;
}

} // namespace

std::string visible_text(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const auto b = static_cast<unsigned char>(text[i]);
        const std::size_t n = utf8_length(text, i);
        const bool control =
            (b < 0x20 && b != '\n' && b != '\t') || b == 0x7F ||
            (n == 2 && b == 0xC2 && static_cast<unsigned char>(text[i + 1]) < 0xA0);
        if (n == 0 || control) {
            for (std::size_t k = 0; k < std::max<std::size_t>(n, 1); ++k) {
                out += fmt::format("\\x{:02x}", static_cast<unsigned char>(text[i + k]));
            }
            i += std::max<std::size_t>(n, 1);
            continue;
        }
        out.append(text.substr(i, n));
        i += n;
    }
    return out;
}

DeckError DeckError::in_file(const std::string& file, const std::string& what) {
    return DeckError(visible_text(fmt::format("{}: {}", file, what)));
}

DeckError DeckError::at_line(const std::string& file, std::int64_t line, const std::string& what) {
    return DeckError(visible_text(fmt::format("{}:{}: {}", file, line, what)));
}

DeckError DeckError::at_line_column(const std::string& file, std::int64_t line, int column,
                                    const std::string& what) {
    return DeckError(visible_text(fmt::format("{}:{}:{}: {}", file, line, column, what)));
}

DeckError DeckError::at_card_byte(const std::string& file, std::int64_t card,
                                  std::int64_t byte_offset, const std::string& what) {
    return DeckError(visible_text(fmt::format("{}: card {}, byte {} (offset {:#x}): {}", file, card,
                                              byte_offset + 1, byte_offset, what)));
}

DeckError DeckError::at_card_column(const std::string& file, std::int64_t card, int column,
                                    const std::string& what) {
    return DeckError(
        visible_text(fmt::format("{}: card {}, column {}: {}", file, card, column, what)));
}

} // namespace parsons::cardreader
