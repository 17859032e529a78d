// Errors in deck files: every one names the file and where in it (line, card, column, byte).
//
// Readers throw DeckError; the CLI turns it into exit code 2 with the message as written here.
// The factories own the wording so that every reader says "where" the same way. No message
// carries a raw control byte to the terminal: every factory writes a byte below 0x20 (but the
// line end and the tab), DEL, and a byte that is no part of UTF-8 text as \xNN (visible_text).
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace parsons::cardreader {

// `text` with each control byte (below 0x20 but '\n' and '\t', DEL, a C1 control U+0080 ..
// U+009F) and each byte that is no part of valid UTF-8 written visibly as \xNN; the rest as is.
std::string visible_text(std::string_view text);

class DeckError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;

    // "deck.csv: empty file: no cards"
    static DeckError in_file(const std::string& file, const std::string& what);
    // "deck.csv:12: unknown axis 'table2'"
    static DeckError at_line(const std::string& file, std::int64_t line, const std::string& what);
    // "deck.txt:3:81: line is longer than 80 columns"
    static DeckError at_line_column(const std::string& file, std::int64_t line, int column,
                                    const std::string& what);
    // "deck.cbn: card 2, byte 161 (offset 0xa0): no card-start mark"
    static DeckError at_card_byte(const std::string& file, std::int64_t card,
                                  std::int64_t byte_offset, const std::string& what);
    // "deck.cbn: card 2, column 12: double punch (rows 3 and 5) in table stop"
    static DeckError at_card_column(const std::string& file, std::int64_t card, int column,
                                    const std::string& what);
};

} // namespace parsons::cardreader
