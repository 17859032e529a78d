#include "cardreader/deck_error.hpp"

#include <fmt/format.h>

namespace parsons::cardreader {

DeckError DeckError::in_file(const std::string& file, const std::string& what) {
    return DeckError(fmt::format("{}: {}", file, what));
}

DeckError DeckError::at_line(const std::string& file, std::int64_t line, const std::string& what) {
    return DeckError(fmt::format("{}:{}: {}", file, line, what));
}

DeckError DeckError::at_line_column(const std::string& file, std::int64_t line, int column,
                                    const std::string& what) {
    return DeckError(fmt::format("{}:{}:{}: {}", file, line, column, what));
}

DeckError DeckError::at_card_byte(const std::string& file, std::int64_t card,
                                  std::int64_t byte_offset, const std::string& what) {
    return DeckError(fmt::format("{}: card {}, byte {} (offset {:#x}): {}", file, card,
                                 byte_offset + 1, byte_offset, what));
}

DeckError DeckError::at_card_column(const std::string& file, std::int64_t card, int column,
                                    const std::string& what) {
    return DeckError(fmt::format("{}: card {}, column {}: {}", file, card, column, what));
}

} // namespace parsons::cardreader
