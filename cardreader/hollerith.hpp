// Hollerith card codes: which holes a keypunch makes for each key, as data.
//
// The IBM 029 keypunch (1964) punches the 64-character EBCDIC card code; the IBM 026 (1949),
// the keypunch Parsons' deck would really have been made on, punches the 48-character BCD
// code, here in its FORTRAN ("H") arrangement. Text card images are ASCII, so the two 029
// characters ASCII lacks stand in as '[' for the cent sign (12-8-2) and '^' for the logical
// not (11-8-7); the printed glyph keeps the real character for card pictures.
#pragma once

#include "cardreader/card.hpp"

#include <array>
#include <optional>
#include <span>
#include <string_view>

namespace parsons::cardreader {

enum class KeypunchCode : std::uint8_t { ibm029, ibm026 };

struct CodeEntry {
    char ascii;               // the character in a text card image (upper case)
    ColumnWord punches;       // the holes the keypunch makes
    std::string_view printed; // what the keypunch prints along the top edge (UTF-8)
};

// The whole table of a keypunch, one entry per key.
std::span<const CodeEntry> code_table(KeypunchCode code);

// The holes for a character, or nothing if the keypunch has no such key. Lower case is not
// folded here; the text reader folds it as SIMH does.
std::optional<ColumnWord> punches_for(char ascii, KeypunchCode code);

// The table entry for a column's holes, or nothing if no key makes exactly these holes.
const CodeEntry* entry_for_punches(ColumnWord punches, KeypunchCode code);

inline constexpr std::array<KeypunchCode, 2> kKeypunchCodes = {KeypunchCode::ibm029,
                                                               KeypunchCode::ibm026};
std::string_view code_name(KeypunchCode code);
std::optional<KeypunchCode> code_named(std::string_view name);

} // namespace parsons::cardreader
