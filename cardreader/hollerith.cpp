#include "cardreader/hollerith.hpp"

#include <algorithm>
#include <array>
#include <initializer_list>

namespace parsons::cardreader {
namespace {

// Holes by the row names a keypunch chart uses: H({12, 8, 3}) is "12-8-3".
constexpr ColumnWord H(std::initializer_list<int> rows) {
    ColumnWord word = 0;
    for (int r : rows) {
        word = static_cast<ColumnWord>(word | row_bit(row_named(r)));
    }
    return word;
}

// IBM 029 card code (EBCDIC card code, IBM 29 Card Punch reference manual, "Card Code").
constexpr std::array<CodeEntry, 63> kIbm029 = {{
    {' ', H({}), " "},
    {'0', H({0}), "0"},
    {'1', H({1}), "1"},
    {'2', H({2}), "2"},
    {'3', H({3}), "3"},
    {'4', H({4}), "4"},
    {'5', H({5}), "5"},
    {'6', H({6}), "6"},
    {'7', H({7}), "7"},
    {'8', H({8}), "8"},
    {'9', H({9}), "9"},
    {'A', H({12, 1}), "A"},
    {'B', H({12, 2}), "B"},
    {'C', H({12, 3}), "C"},
    {'D', H({12, 4}), "D"},
    {'E', H({12, 5}), "E"},
    {'F', H({12, 6}), "F"},
    {'G', H({12, 7}), "G"},
    {'H', H({12, 8}), "H"},
    {'I', H({12, 9}), "I"},
    {'J', H({11, 1}), "J"},
    {'K', H({11, 2}), "K"},
    {'L', H({11, 3}), "L"},
    {'M', H({11, 4}), "M"},
    {'N', H({11, 5}), "N"},
    {'O', H({11, 6}), "O"},
    {'P', H({11, 7}), "P"},
    {'Q', H({11, 8}), "Q"},
    {'R', H({11, 9}), "R"},
    {'S', H({0, 2}), "S"},
    {'T', H({0, 3}), "T"},
    {'U', H({0, 4}), "U"},
    {'V', H({0, 5}), "V"},
    {'W', H({0, 6}), "W"},
    {'X', H({0, 7}), "X"},
    {'Y', H({0, 8}), "Y"},
    {'Z', H({0, 9}), "Z"},
    {'&', H({12}), "&"},
    {'-', H({11}), "-"},
    {'/', H({0, 1}), "/"},
    {'[', H({12, 8, 2}), "\u00a2"}, // cent sign
    {'.', H({12, 8, 3}), "."},
    {'<', H({12, 8, 4}), "<"},
    {'(', H({12, 8, 5}), "("},
    {'+', H({12, 8, 6}), "+"},
    {'|', H({12, 8, 7}), "|"},
    {'!', H({11, 8, 2}), "!"},
    {'$', H({11, 8, 3}), "$"},
    {'*', H({11, 8, 4}), "*"},
    {')', H({11, 8, 5}), ")"},
    {';', H({11, 8, 6}), ";"},
    {'^', H({11, 8, 7}), "\u00ac"}, // logical not
    {',', H({0, 8, 3}), ","},
    {'%', H({0, 8, 4}), "%"},
    {'_', H({0, 8, 5}), "_"},
    {'>', H({0, 8, 6}), ">"},
    {'?', H({0, 8, 7}), "?"},
    {':', H({8, 2}), ":"},
    {'#', H({8, 3}), "#"},
    {'@', H({8, 4}), "@"},
    {'\'', H({8, 5}), "'"},
    {'=', H({8, 6}), "="},
    {'"', H({8, 7}), "\""},
}};

// IBM 026 card code, FORTRAN arrangement (BCD "H" set).
constexpr std::array<CodeEntry, 48> kIbm026 = {{
    {' ', H({}), " "},         {'0', H({0}), "0"},        {'1', H({1}), "1"},
    {'2', H({2}), "2"},        {'3', H({3}), "3"},        {'4', H({4}), "4"},
    {'5', H({5}), "5"},        {'6', H({6}), "6"},        {'7', H({7}), "7"},
    {'8', H({8}), "8"},        {'9', H({9}), "9"},        {'A', H({12, 1}), "A"},
    {'B', H({12, 2}), "B"},    {'C', H({12, 3}), "C"},    {'D', H({12, 4}), "D"},
    {'E', H({12, 5}), "E"},    {'F', H({12, 6}), "F"},    {'G', H({12, 7}), "G"},
    {'H', H({12, 8}), "H"},    {'I', H({12, 9}), "I"},    {'J', H({11, 1}), "J"},
    {'K', H({11, 2}), "K"},    {'L', H({11, 3}), "L"},    {'M', H({11, 4}), "M"},
    {'N', H({11, 5}), "N"},    {'O', H({11, 6}), "O"},    {'P', H({11, 7}), "P"},
    {'Q', H({11, 8}), "Q"},    {'R', H({11, 9}), "R"},    {'S', H({0, 2}), "S"},
    {'T', H({0, 3}), "T"},     {'U', H({0, 4}), "U"},     {'V', H({0, 5}), "V"},
    {'W', H({0, 6}), "W"},     {'X', H({0, 7}), "X"},     {'Y', H({0, 8}), "Y"},
    {'Z', H({0, 9}), "Z"},     {'+', H({12}), "+"},       {'-', H({11}), "-"},
    {'/', H({0, 1}), "/"},     {'.', H({12, 8, 3}), "."}, {')', H({12, 8, 4}), ")"},
    {'$', H({11, 8, 3}), "$"}, {'*', H({11, 8, 4}), "*"}, {',', H({0, 8, 3}), ","},
    {'(', H({0, 8, 4}), "("},  {'=', H({8, 3}), "="},     {'\'', H({8, 4}), "'"},
}};

} // namespace

std::span<const CodeEntry> code_table(KeypunchCode code) {
    if (code == KeypunchCode::ibm026) {
        return kIbm026;
    }
    return kIbm029;
}

std::optional<ColumnWord> punches_for(char ascii, KeypunchCode code) {
    for (const CodeEntry& e : code_table(code)) {
        if (e.ascii == ascii) {
            return e.punches;
        }
    }
    return std::nullopt;
}

const CodeEntry* entry_for_punches(ColumnWord punches, KeypunchCode code) {
    auto table = code_table(code);
    auto it = std::find_if(table.begin(), table.end(),
                           [punches](const CodeEntry& e) { return e.punches == punches; });
    return it == table.end() ? nullptr : &*it;
}

std::string_view code_name(KeypunchCode code) {
    return code == KeypunchCode::ibm026 ? "026" : "029";
}

std::optional<KeypunchCode> code_named(std::string_view name) {
    for (KeypunchCode code : kKeypunchCodes) {
        if (code_name(code) == name) {
            return code;
        }
    }
    return std::nullopt;
}

} // namespace parsons::cardreader
