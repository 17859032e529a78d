// The G words parsons knows (decks/gcode_words.hpp).
#include "decks/gcode_words.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

namespace parsons::decks::gcode_words {

std::optional<GInfo> g_code(double g) {
    static const std::map<int, GInfo> codes = {
        {0, {Group::motion, nullptr}},
        {10, {Group::motion, nullptr}},
        {20, {Group::motion, nullptr}},
        {30, {Group::motion, nullptr}},
        {40,
         {Group::other, "dwell: the 1952 machine reads the next card as soon as every axis "
                        "has stopped; it cannot wait"}},
        {170, {Group::plane, nullptr}},
        {180, {Group::plane, "the XZ plane: parsons reads arcs in the XY plane only (G17)"}},
        {190, {Group::plane, "the YZ plane: parsons reads arcs in the XY plane only (G17)"}},
        {200, {Group::units, nullptr}},
        {210, {Group::units, nullptr}},
        {280, {Group::other, nullptr}}, // return home: ignored after the last move (home_)
        {300, {Group::other, "return to a second home: write the moves themselves"}},
        {382, {Group::motion, "probing: the 1952 machine has no probe"}},
        {400, {Group::other, nullptr}},
        {410,
         {Group::other, "cutter radius compensation: the deck generator offsets the cutter "
                        "itself (gen airfoil --cutter-radius); write the cutter-centre path"}},
        {420,
         {Group::other, "cutter radius compensation: the deck generator offsets the cutter "
                        "itself (gen airfoil --cutter-radius); write the cutter-centre path"}},
        {430, {Group::other, nullptr}}, // tool length offset: ignored (tool_length)
        {490, {Group::other, nullptr}},
        {530, {Group::other, "machine coordinates: give the program's own and --work-zero"}},
        {540, {Group::other, nullptr}},
        {550, {Group::other, "a second work offset: give --work-zero"}},
        {560, {Group::other, "a work offset: give --work-zero"}},
        {570, {Group::other, "a work offset: give --work-zero"}},
        {580, {Group::other, "a work offset: give --work-zero"}},
        {590, {Group::other, "a work offset: give --work-zero"}},
        {610, {Group::other, nullptr}},
        {640, {Group::other, nullptr}},
        {800, {Group::motion, nullptr}},
        {810, {Group::motion, "a drilling cycle: write its moves as G0 and G1 lines"}},
        {820, {Group::motion, "a drilling cycle: write its moves as G0 and G1 lines"}},
        {830, {Group::motion, "a drilling cycle: write its moves as G0 and G1 lines"}},
        {840,
         {Group::motion, "a tapping cycle: the tap card of parsons-extended does that "
                         "(gen tapping)"}},
        {900, {Group::distance, nullptr}},
        {901,
         {Group::arc_distance, "absolute arc centres: give I and J from the arc's start "
                               "(G91.1)"}},
        {910, {Group::distance, nullptr}},
        {911, {Group::arc_distance, nullptr}},
        {920, {Group::other, "setting the origin in the program: give --work-zero"}},
        {930,
         {Group::feed_mode, "inverse-time feed: the deck's speeds come from the slow-down "
                            "rule"}},
        {940, {Group::feed_mode, nullptr}},
        {950,
         {Group::feed_mode, "feed per revolution: the deck's speeds come from the slow-down "
                            "rule"}},
    };
    const double tenths = g * 10;
    if (std::abs(tenths - std::round(tenths)) > 1e-9) {
        return std::nullopt;
    }
    const auto it = codes.find(static_cast<int>(std::lround(tenths)));
    if (it == codes.end()) {
        if (g >= 81 && g <= 89 && g == std::floor(g)) {
            return GInfo{Group::motion, "a canned cycle: write its moves as G0 and G1 lines"};
        }
        return std::nullopt;
    }
    return it->second;
}

bool program_number(std::string_view l, std::size_t& i, std::vector<Word>& words) {
    const bool first =
        std::all_of(words.begin(), words.end(), [](const Word& w) { return w.letter == 'N'; });
    std::size_t end = i + 1;
    if (end < l.size() && l[end] == '<') {
        end = l.find('>', end);
        end = end == std::string_view::npos ? end : end + 1;
    } else {
        while (end < l.size() && std::isdigit(static_cast<unsigned char>(l[end])) != 0) {
            ++end;
        }
    }
    if (!first || end == std::string_view::npos || end <= i + 1 ||
        (end == i + 2 && l[i + 1] == '<')) {
        return false;
    }
    const std::size_t after = l.find_first_not_of(" \t", end);
    if (after != std::string_view::npos && l[after] != '(' && l[after] != ';') {
        return false;
    }
    Word w;
    w.letter = 'O';
    w.text = "O" + std::string(l.substr(i + 1, end - i - 1));
    words.push_back(w);
    i = end;
    return true;
}

Word scan_word(std::string_view l, std::size_t& i, int& digits) {
    auto skip_blanks = [&] {
        while (i < l.size() && (l[i] == ' ' || l[i] == '\t')) {
            ++i;
        }
    };
    Word w;
    w.letter = static_cast<char>(std::toupper(static_cast<unsigned char>(l[i])));
    ++i;
    skip_blanks();
    const std::size_t number_start = i;
    if (i < l.size() && (l[i] == '+' || l[i] == '-')) {
        ++i;
    }
    digits = 0;
    while (i < l.size() && (std::isdigit(static_cast<unsigned char>(l[i])) != 0)) {
        ++i;
        ++digits;
    }
    if (i < l.size() && l[i] == '.') {
        ++i;
        while (i < l.size() && (std::isdigit(static_cast<unsigned char>(l[i])) != 0)) {
            ++i;
            ++digits;
        }
    }
    std::string number(l.substr(number_start, i - number_start));
    std::erase(number, ' ');
    w.text = std::string(1, w.letter) + number;
    return w;
}

} // namespace parsons::decks::gcode_words
