// Reading a G-code program (decks/gcode_program.hpp; docs/gcode.md).
#include "decks/gcode_program.hpp"

#include "cardreader/deck_error.hpp"
#include "decks/gcode_words.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <set>

namespace parsons::decks {
namespace {

using cardreader::DeckError;
using Eigen::Vector2d;
using Eigen::Vector3d;
using gcode_words::g_code;
using gcode_words::GInfo;
using gcode_words::Group;
using gcode_words::program_number;
using gcode_words::scan_word;
using gcode_words::Word;

constexpr double kMmPerInch = 25.4;
// An arc whose end lies further than this from the circle through its start is refused
// (inches): half a thousandth, the machine's own resolution.
constexpr double kArcMismatchIn = 0.0005;
// An arc of a larger radius is refused (inches): over the machine's 10 in its sagitta is under
// 0.00002 in (a G1 cuts it as well), and far beyond it a double no longer places its end on
// its circle to the mismatch above (the fuzzer's I22222267410415839 in millimetres).
constexpr double kLargestArcRadiusIn = 1e6;

class Reader {
public:
    Reader(std::string_view text, const std::string& file, bool strict,
           std::optional<double> retract_z = std::nullopt)
        : text_(text), strict_(strict), retract_z_(retract_z) {
        program_.file = file;
        if (text_.starts_with("\xEF\xBB\xBF")) {
            text_.remove_prefix(3); // a UTF-8 byte-order mark: read past (docs/gcode.md)
        }
    }

    // Whether the program holds a G53 retract to machine zero (read as the tool up: a rapid
    // to the highest Z the program reaches, known once the whole program is read).
    bool retracts() const { return retracted_; }

    GcodeProgram read() {
        std::size_t start = 0;
        while (start <= text_.size() && !ended_) {
            const std::size_t nl = text_.find('\n', start);
            const std::size_t end = nl == std::string_view::npos ? text_.size() : nl;
            ++line_;
            std::string_view l = text_.substr(start, end - start);
            if (!l.empty() && l.back() == '\r') {
                l.remove_suffix(1);
            }
            read_line(l);
            if (nl == std::string_view::npos) {
                break;
            }
            start = nl + 1;
        }
        program_.lines = line_;
        tell_ignored();
        return std::move(program_);
    }

private:
    [[noreturn]] void refuse(const std::string& word, const std::string& why) const {
        throw DeckError::at_line(program_.file, line_, word.empty() ? why : word + ": " + why);
    }

    // A word the 1952 machine has nothing for: told once a kind, at its first line, with the
    // number of later lines that hold one too (docs/gcode.md); under --strict, refused there.
    void ignore(const std::string& kind, const std::string& word, const std::string& why) {
        if (strict_) {
            refuse(word, why + " (refused under --strict, which ignores nothing)");
        }
        const auto [it, first] = ignored_.try_emplace(kind);
        Ignored& seen = it->second;
        if (first) {
            seen = {word, why, line_, line_, 0, order_++};
        } else if (seen.last_line != line_) {
            seen.last_line = line_;
            ++seen.later_lines;
        }
    }

    // The ignored words, in the order of their first lines: the program's list and the
    // warnings.
    void tell_ignored() {
        std::vector<std::pair<std::string, const Ignored*>> kinds;
        for (const auto& [kind, seen] : ignored_) {
            kinds.emplace_back(kind, &seen);
        }
        std::sort(kinds.begin(), kinds.end(),
                  [](const auto& a, const auto& b) { return a.second->order < b.second->order; });
        for (const auto& [kind, seen] : kinds) {
            program_.ignored.push_back(
                fmt::format("{} (first on line {}): {}", kind, seen->first_line, seen->why));
            program_.warnings.push_back(fmt::format(
                "{}:{}: {} ignored: {}{}", program_.file, seen->first_line, seen->word, seen->why,
                seen->later_lines == 0
                    ? ""
                    : fmt::format(" (the same on {} later line{}, not told again)",
                                  seen->later_lines, seen->later_lines == 1 ? "" : "s")));
        }
    }

    std::vector<Word> words_of(std::string_view l) {
        std::vector<Word> words;
        std::size_t i = 0;
        auto skip_blanks = [&] {
            while (i < l.size() && (l[i] == ' ' || l[i] == '\t')) {
                ++i;
            }
        };
        skip_blanks();
        if (i < l.size() && (l[i] == '$' || l[i] == '?')) {
            // grbl's own commands ($H home, $X unlock, $$ settings, $J= jog) and its status
            // query '?': sent to grbl, not moves of the program.
            ignore("$/?", std::string(l.substr(i, std::min<std::size_t>(12, l.size() - i))),
                   "a grbl command or status query ($H, $X, $$, $J=, ?), not a move of the "
                   "program: the line is skipped");
            return words;
        }
        if (i < l.size() && l[i] == '%') {
            ++i;
            skip_blanks();
            if (i < l.size() && l[i] != ';' && l[i] != '(') {
                refuse("%", "a '%' line marks the start or end of the program and holds nothing "
                            "else");
            }
        }
        if (i < l.size() && l[i] == '/') {
            refuse("/", "block delete: every line of the program is punched, or none");
        }
        while (true) {
            skip_blanks();
            if (i >= l.size() || l[i] == ';') {
                break;
            }
            const char c = l[i];
            if (c == '(') {
                const std::size_t close = l.find(')', i);
                if (close == std::string_view::npos) {
                    refuse("(", "a comment that is not closed on its line");
                }
                i = close + 1;
                continue;
            }
            if ((c == 'o' || c == 'O') && program_number(l, i, words)) {
                continue;
            }
            if (c == '#' || c == '[' || c == 'o' || c == 'O') {
                refuse(std::string(1, c), "parameters, expressions and subroutines: write the "
                                          "program out as plain moves");
            }
            if (std::isalpha(static_cast<unsigned char>(c)) == 0) {
                refuse(std::string(1, c), "not a G-code word (a letter and a number)");
            }
            int digits = 0;
            Word w = scan_word(l, i, digits);
            if (digits == 0) {
                refuse(w.text, "a letter with no number after it");
            }
            if (w.text.size() > 25) {
                refuse(w.text.substr(0, 12) + "...", "a number too long to be a coordinate");
            }
            w.value = std::stod(w.text.substr(1));
            words.push_back(w);
        }
        return words;
    }

    // The words of one line, sorted: the G-codes by modal group, the axis and arc words, the
    // spindle word, and whether the program ends on this line.
    struct LineWords {
        std::map<Group, Word> groups;
        std::map<char, Word> axis;
        std::optional<int> spindle;
        bool end_program = false;
        bool has_arc_word = false;
        std::optional<Word> tool;        // T
        bool tool_change = false;        // M6
        std::optional<Word> home;        // G28
        std::optional<Word> machine;     // G53
        std::optional<Word> tool_length; // G43, with its H
        std::optional<Word> blending;    // G64, with its P and Q
        std::vector<Word> h_p_q;         // H, P and Q: only with G43 and G64
    };

    void g_word(const Word& w, LineWords& line) const {
        const auto info = g_code(w.value);
        if (!info) {
            refuse(w.text, "not a G-code parsons reads (docs/gcode.md lists them)");
        }
        const long tenths = std::lround(w.value * 10);
        if (tenths == 530) {
            line.machine = w; // G53: read only as Fusion's retract, G53 G0 Z0 (read_retract)
            return;
        }
        if (info->refusal != nullptr) {
            refuse(w.text, info->refusal);
        }
        if (tenths == 280) {
            line.home = w;
        } else if (tenths == 430) {
            line.tool_length = w;
        } else if (tenths == 640) {
            line.blending = w;
        }
        if (info->group != Group::other) {
            if (const auto it = line.groups.find(info->group); it != line.groups.end()) {
                refuse(w.text, fmt::format("{} and {} on one line: two words of the same "
                                           "modal group",
                                           it->second.text, w.text));
            }
            line.groups[info->group] = w;
        }
    }

    void m_word(const Word& w, LineWords& line) {
        const int m = static_cast<int>(std::lround(w.value));
        if (std::abs(w.value - m) > 1e-9) {
            refuse(w.text, "not an M-code parsons reads");
        }
        if (m == 2 || m == 30) {
            line.end_program = true;
        } else if (m == 3 || m == 4 || m == 5) {
            if (line.spindle) {
                refuse(w.text, "two spindle words on one line");
            }
            line.spindle = m == 3 ? 1 : m == 4 ? 2 : 0;
        } else if (m == 7 || m == 8 || m == 9) {
            ignore("M7/M8/M9", w.text, "coolant: the 1952 card has no column for it");
        } else if (m == 6) {
            line.tool_change = true;
        } else if (m == 0 || m == 1) {
            refuse(w.text, "a program stop: the 1952 machine stops only at the end of "
                           "the deck or on a check");
        } else {
            refuse(w.text, "not an M-code parsons reads (docs/gcode.md lists them)");
        }
    }

    void sort_word(const Word& w, LineWords& line) {
        switch (w.letter) {
        case 'N':
            break;
        case 'G':
            g_word(w, line);
            break;
        case 'M':
            m_word(w, line);
            break;
        case 'X':
        case 'Y':
        case 'Z':
        case 'I':
        case 'J':
        case 'R':
            if (line.axis.count(w.letter) != 0) {
                refuse(w.text, fmt::format("{} given twice on one line", w.letter));
            }
            if (!std::isfinite(w.value)) {
                refuse(w.text, "not a finite number");
            }
            line.axis[w.letter] = w;
            line.has_arc_word =
                line.has_arc_word || w.letter == 'I' || w.letter == 'J' || w.letter == 'R';
            break;
        case 'F':
            if (!(w.value > 0)) {
                refuse(w.text, "a feed must be positive");
            }
            ignore("F", w.text,
                   "feeds: the deck's speeds are the speed switches', chosen by the "
                   "slow-down rule, not the program's");
            break;
        case 'S':
            if (w.value < 0) {
                refuse(w.text, "a spindle speed cannot be negative");
            }
            ignore("S", w.text,
                   "spindle speed: the 1952 spindle runs at the speed set on the machine");
            break;
        case 'T':
            if (w.value < 0 || w.value != std::floor(w.value) || line.tool) {
                refuse(w.text, "a tool number is one whole number, 0 or more");
            }
            line.tool = w;
            break;
        case 'O':
            ignore("O", w.text, "a program number: the deck is known by its file's name");
            break;
        case 'H':
        case 'P':
        case 'Q':
            line.h_p_q.push_back(w);
            break;
        case 'K':
            refuse(w.text, "K: arcs in the XY plane take I and J only");
        case 'A':
        case 'B':
        case 'C':
            refuse(w.text, "a rotary axis: the fixture's swivel and tilt stand where the "
                           "deck's own cards set them; the program moves X, Y and Z");
        default:
            refuse(w.text, "not a word parsons reads (docs/gcode.md lists them)");
        }
    }

    void read_line(std::string_view l) {
        const std::vector<Word> words = words_of(l);
        if (words.empty()) {
            return;
        }
        LineWords line;
        for (const Word& w : words) {
            sort_word(w, line);
        }
        read_setup_words(line);
        read_modes(line);
        if (line.machine) {
            read_retract(line);
            return;
        }
        if (line.home) {
            read_home(line);
            return;
        }
        read_move(line);
    }

    // The words a post writes to set up a machine with a tool changer and path blending:
    // T and M6, G43 H, G64 P Q. Each is ignored with its reason; H, P and Q on any other line
    // are refused as before.
    void read_setup_words(const LineWords& line) {
        for (const Word& w : line.h_p_q) {
            const bool with_g43 = w.letter == 'H' && line.tool_length;
            const bool with_g64 = w.letter != 'H' && line.blending;
            if (!with_g43 && !with_g64) {
                refuse(w.text, "not a word parsons reads (docs/gcode.md lists them)");
            }
        }
        auto with_values = [&line](const Word& g, char a, char b) {
            std::string text = g.text;
            for (const Word& w : line.h_p_q) {
                text += w.letter == a || w.letter == b ? " " + w.text : "";
            }
            return text;
        };
        if (line.tool) {
            const auto number = static_cast<std::int64_t>(line.tool->value);
            if (first_tool_ && *first_tool_ != number) {
                refuse(line.tool->text,
                       fmt::format("a second tool (the program began with T{}): a 1952 deck "
                                   "runs one cutter; split the program, one deck a tool "
                                   "(condition cards of parsons-extended change tools: gen "
                                   "two-tool)",
                                   *first_tool_));
            }
            first_tool_ = number;
        }
        if (line.tool || line.tool_change) {
            const std::string word = line.tool && line.tool_change ? line.tool->text + " M6"
                                     : line.tool                   ? line.tool->text
                                                                   : std::string("M6");
            ignore("T/M6", word,
                   fmt::format("the 1952 machine has no tool changer; the deck runs the one "
                               "cutter set in the spindle by hand{}",
                               !line.tool && first_tool_
                                   ? fmt::format(" (the program's T{})", *first_tool_)
                                   : std::string()));
        }
        if (line.tool_length) {
            ignore("G43", with_values(*line.tool_length, 'H', 'H'),
                   "tool length offset: the cutter is set by hand to the deck's zero, so the "
                   "program's Z is the cutter's tip");
        }
        if (line.blending) {
            ignore("G64", with_values(*line.blending, 'P', 'Q'),
                   "path blending: the 1952 machine stops every axis at the end of each card, "
                   "an exact stop whatever the program asks");
        }
    }

    // G28: a return home, read only after the last move (its X Y Z are the point it passes,
    // not a move): the deck ends where its last card stops. A move after it is refused there.
    void read_home(const LineWords& line) {
        if (line.has_arc_word) {
            refuse(line.home->text, "a return home takes no I, J or R");
        }
        ignore("G28", line.home->text,
               "a return home after the last move: the deck ends where its last card stops, "
               "and the operator brings the machine home");
        home_ = line_;
        if (line.end_program) {
            ended_ = true;
        }
    }

    // G53 G0 Z0: Fusion's retract to machine zero, the vertical slide at the top of its travel.
    // The deck knows only the program's frame, so it is read as the tool up: a rapid to the
    // highest Z the program reaches (retract_z_), with a warning. Any other G53 is refused.
    void read_retract(LineWords& line) {
        const Word& g53 = *line.machine;
        const auto z = line.axis.find('Z');
        const bool rapid = line.groups.count(Group::motion) != 0
                               ? std::lround(line.groups[Group::motion].value * 10) == 0
                               : motion_ == Mode::rapid;
        if (!rapid || line.axis.size() != 1 || z == line.axis.end() || z->second.value != 0 ||
            line.end_program) {
            refuse(g53.text, "machine coordinates: give the program's own and --work-zero (a "
                             "G53 is read only as the retract G53 G0 Z0, the tool up)");
        }
        if (incremental_) {
            refuse(g53.text, "a retract to machine zero under G91: give it under G90");
        }
        ignore("G53", g53.text + " G0 " + z->second.text,
               "a retract to machine zero: read as the tool up, a rapid to the highest Z the "
               "program reaches (the deck knows only the program's frame)");
        retracted_ = true;
        if (!retract_z_) {
            return; // the first reading: the highest Z is not known yet
        }
        const double saved = units_;
        units_ = 1.0;
        line.machine.reset();
        line.axis['Z'].value = *retract_z_;
        read_move(line);
        units_ = saved;
    }

    // In the order RS-274 applies them: units, plane, distance, spindle, then the move.
    void read_modes(LineWords& line) {
        if (const auto it = line.groups.find(Group::units); it != line.groups.end()) {
            units_ = it->second.value < 20.5 ? 1.0 : 1.0 / kMmPerInch;
            units_given_ = true;
            millimetres_ = it->second.value > 20.5;
        }
        if (const auto it = line.groups.find(Group::distance); it != line.groups.end()) {
            incremental_ = it->second.value > 90.5;
        }
        if (line.spindle) {
            spindle_ = *line.spindle;
        }
        const bool motion_word = line.groups.count(Group::motion) != 0;
        if (motion_word) {
            const double g = line.groups[Group::motion].value;
            motion_ = g < 0.5   ? Mode::rapid
                      : g < 1.5 ? Mode::linear
                      : g < 2.5 ? Mode::arc_cw
                      : g < 3.5 ? Mode::arc_ccw
                                : Mode::none; // G80
        }
    }

    void read_move(LineWords& line) {
        const bool has_axis =
            line.axis.count('X') + line.axis.count('Y') + line.axis.count('Z') != 0;
        if (line.has_arc_word && motion_ != Mode::arc_cw && motion_ != Mode::arc_ccw) {
            const char letter = line.axis.count('I') ? 'I' : line.axis.count('J') ? 'J' : 'R';
            refuse(line.axis[letter].text, "arc words with no arc: I, J and R go with G2 or G3");
        }
        if (!has_axis && !line.has_arc_word) {
            if (line.end_program) {
                ended_ = true;
            }
            return;
        }
        const Word& first = line.axis.begin()->second;
        if (home_) {
            throw DeckError::at_line(program_.file, *home_,
                                     fmt::format("G28: a return home with a move after it (line "
                                                 "{}): parsons cannot know where home is; write "
                                                 "the moves themselves",
                                                 line_));
        }
        if (motion_ == Mode::none) {
            refuse(first.text, "a move with no motion mode: give G0, G1, G2 or G3 first");
        }
        if (!units_given_) {
            refuse(first.text, "a move before the units are given: put G20 (inches) or G21 "
                               "(millimetres) before the first move");
        }
        if (program_.moves.empty()) {
            program_.millimetres = millimetres_;
        }
        Vector3d to = position_;
        const char names[3] = {'X', 'Y', 'Z'};
        for (int k = 0; k < 3; ++k) {
            if (const auto it = line.axis.find(names[k]); it != line.axis.end()) {
                const double v = it->second.value * units_;
                to[k] = incremental_ ? position_[k] + v : v;
            }
        }
        GcodeMove move;
        move.line = line_;
        move.from = position_;
        move.to = to;
        move.spindle = spindle_;
        if (motion_ == Mode::rapid || motion_ == Mode::linear) {
            move.motion = motion_ == Mode::rapid ? GcodeMotion::rapid : GcodeMotion::linear;
        } else {
            arc(move, line.axis);
        }
        if (move.motion == GcodeMotion::rapid || move.motion == GcodeMotion::linear) {
            if ((move.to - move.from).norm() == 0) {
                position_ = to;
                if (line.end_program) {
                    ended_ = true;
                }
                return;
            }
        }
        program_.moves.push_back(move);
        position_ = to;
        if (line.end_program) {
            ended_ = true;
        }
    }

    void arc(GcodeMove& move, std::map<char, Word>& axis) {
        const bool cw = motion_ == Mode::arc_cw;
        move.motion = cw ? GcodeMotion::arc_cw : GcodeMotion::arc_ccw;
        const Vector2d a = move.from.head<2>();
        const Vector2d b = move.to.head<2>();
        const bool has_r = axis.count('R') != 0;
        const bool has_ij = axis.count('I') + axis.count('J') != 0;
        const std::string word = cw ? "G2" : "G3";
        if (has_r && has_ij) {
            refuse(axis['R'].text, "an arc takes its centre from I and J or its radius from R, "
                                   "not both");
        }
        if (!has_r && !has_ij) {
            refuse(word, "an arc with neither I and J nor R");
        }
        Vector2d centre;
        if (has_r) {
            const double r = axis['R'].value * units_;
            const Vector2d chord = b - a;
            const double d = chord.norm();
            if (d < 1e-9) {
                refuse(axis['R'].text, "a full circle cannot be given by its radius: give I and J");
            }
            if (std::abs(r) < d / 2 - 1e-9) {
                refuse(axis['R'].text,
                       fmt::format("the radius {:.4f} in is less than half the distance {:.4f} "
                                   "in between the arc's ends",
                                   std::abs(r), d / 2));
            }
            const double h = std::sqrt(std::max(0.0, r * r - d * d / 4));
            const Vector2d left(-chord.y() / d, chord.x() / d);
            // A positive R is the shorter arc: its centre to the right of the chord going
            // clockwise, to the left going counter-clockwise; a negative R the other side.
            const double side = (cw ? -1.0 : 1.0) * (r > 0 ? 1.0 : -1.0);
            centre = (a + b) / 2 + side * h * left;
        } else {
            const double i = axis.count('I') ? axis['I'].value * units_ : 0;
            const double j = axis.count('J') ? axis['J'].value * units_ : 0;
            centre = a + Vector2d(i, j);
        }
        const double r0 = (a - centre).norm();
        const double r1 = (b - centre).norm();
        if (r0 < 1e-6) {
            refuse(word, "an arc of no radius: I and J are both 0");
        }
        if (!(r0 <= kLargestArcRadiusIn)) {
            refuse(word, fmt::format("an arc of radius {:.6g} in, over 1,000,000 in: over the "
                                     "machine's 10 in it is a straight line to 0.00002 in (give "
                                     "it as G1)",
                                     r0));
        }
        if (std::abs(r0 - r1) > kArcMismatchIn) {
            refuse(word, fmt::format("the arc's end is not on its circle: radius {:.5f} in at "
                                     "the start, {:.5f} in at the end",
                                     r0, r1));
        }
        const double a0 = std::atan2(a.y() - centre.y(), a.x() - centre.x());
        const double a1 = std::atan2(b.y() - centre.y(), b.x() - centre.x());
        double sweep = a1 - a0;
        if (cw) {
            while (sweep >= 0) {
                sweep -= 2 * std::numbers::pi;
            }
            if ((b - a).norm() < 1e-9) {
                sweep = -2 * std::numbers::pi;
            }
        } else {
            while (sweep <= 0) {
                sweep += 2 * std::numbers::pi;
            }
            if ((b - a).norm() < 1e-9) {
                sweep = 2 * std::numbers::pi;
            }
        }
        if (sweep <= -2 * std::numbers::pi - 1e-12 || sweep >= 2 * std::numbers::pi + 1e-12) {
            sweep = cw ? -2 * std::numbers::pi : 2 * std::numbers::pi;
        }
        move.centre = centre;
        move.sweep_rad = sweep;
    }

    enum class Mode { none, rapid, linear, arc_cw, arc_ccw };

    struct Ignored {
        std::string word; // the first, as written
        std::string why;
        std::int64_t first_line = 0;
        std::int64_t last_line = 0;
        std::int64_t later_lines = 0;
        int order = 0;
    };

    std::string_view text_;
    GcodeProgram program_;
    bool strict_ = false;
    std::map<std::string, Ignored> ignored_;
    int order_ = 0;
    std::optional<std::int64_t> first_tool_;
    std::optional<std::int64_t> home_; // the line of a G28
    std::optional<double> retract_z_;  // inches: where a G53 G0 Z0 takes the tool
    bool retracted_ = false;
    std::int64_t line_ = 0;
    bool ended_ = false;
    double units_ = 1.0;
    bool units_given_ = false;
    bool millimetres_ = false;
    bool incremental_ = false;
    int spindle_ = 0;
    Mode motion_ = Mode::none;
    Vector3d position_ = Vector3d::Zero();
};

} // namespace

GcodeProgram read_gcode(std::string_view text, const std::string& file, const GcodeReading& how) {
    Reader first(text, file, how.strict);
    GcodeProgram program = first.read();
    if (!first.retracts()) {
        return program;
    }
    // A G53 retract goes to the highest Z of the program (under G90 every Z is one the program
    // gives, so the second reading's highest Z is the first's).
    double top = 0;
    for (const GcodeMove& m : program.moves) {
        top = std::max({top, m.from.z(), m.to.z()});
    }
    return Reader(text, file, how.strict, top).read();
}

Vector3d point_on(const GcodeMove& move, double f) {
    if (move.motion == GcodeMotion::rapid || move.motion == GcodeMotion::linear) {
        return move.from + f * (move.to - move.from);
    }
    const Vector2d a = move.from.head<2>() - move.centre;
    const Vector2d b = move.to.head<2>() - move.centre;
    const double r = a.norm() + f * (b.norm() - a.norm());
    const double angle = std::atan2(a.y(), a.x()) + f * move.sweep_rad;
    return {move.centre.x() + r * std::cos(angle), move.centre.y() + r * std::sin(angle),
            move.from.z() + f * (move.to.z() - move.from.z())};
}

} // namespace parsons::decks
