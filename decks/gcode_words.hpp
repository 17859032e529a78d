// The G words of RS-274 that parsons knows (decks/gcode_program.hpp; docs/gcode.md): each one's
// modal group, and why it is refused when it is.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace parsons::decks::gcode_words {

// Modal groups of the G words parsons reads; two words of one group on a line are refused.
enum class Group { motion, plane, units, distance, arc_distance, feed_mode, other };

struct GInfo {
    Group group;
    const char* refusal; // nullptr: read; else why it is refused
};

// What G`g` is, or nothing when parsons does not know it.
std::optional<GInfo> g_code(double g);

// A word of a line: its letter (upper case), its value and its text as written ("G41", "X1.5").
struct Word {
    char letter = 0;
    double value = 0;
    std::string text;
};

// A program number as the posts write it, O1234 or O<name>, first on its line (after an N
// word) with nothing after it but a comment: read into `words` and `i` moved past it. Any
// other O word is LinuxCNC's subroutines and loops (O100 sub, O<x> call): false, nothing read.
bool program_number(std::string_view l, std::size_t& i, std::vector<Word>& words);

// The word whose letter is l[i]: the letter upper-cased and the signed decimal number after it
// (blanks allowed within), its text without the blanks; `i` moved past it and `digits` the
// number's digits (0: a letter with no number). The value is left for the reader to judge.
Word scan_word(std::string_view l, std::size_t& i, int& digits);

} // namespace parsons::decks::gcode_words
