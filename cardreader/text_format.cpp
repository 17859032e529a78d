#include "cardreader/text_format.hpp"

#include "cardreader/deck_error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <istream>
#include <optional>
#include <ostream>
#include <streambuf>

namespace parsons::cardreader {
namespace {

std::string describe_char(int ch) {
    if (ch >= 0x21 && ch < 0x7F) {
        return fmt::format("'{}'", static_cast<char>(ch));
    }
    return fmt::format("byte {:#04x}", ch);
}

// SIMH's end-of-record card, ~eor: rows 7, 8, 9 in column 1 alone (sim_card.c). Its ~eof
// (rows 6, 7, 9), ~eoi (rows 6, 7, 8, 9) and a lone ~ (the end-of-file flag) are marks for a
// monitor program, which the 1952 machine does not have: they are passed over and the reader
// reads on, as sim_card.c does (with a warning when cards follow), so they are never written.
constexpr ColumnWord kEndOfRecord = 07;
// The longest line read (a ~raw card is 324 characters): past it, no card image.
constexpr std::size_t kMaxTextLineBytes = 4096;

bool only_column_1(const Card& card, ColumnWord word) {
    if (card.column(1) != word) {
        return false;
    }
    for (int c = 2; c <= kColumns; ++c) {
        if (card.column(c) != 0) {
            return false;
        }
    }
    return true;
}

std::string lower(std::string_view text) {
    std::string out(text);
    for (char& c : out) {
        c = (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
    }
    return out;
}

class TextSource : public CardSource {
public:
    TextSource(std::istream& in, std::string file, KeypunchCode code,
               std::function<void(const std::string&)> warn)
        : buf_(*in.rdbuf()), file_(std::move(file)), code_(code), warn_(std::move(warn)) {}

    std::optional<Card> next() override {
        for (;;) {
            const std::optional<std::string> line = read_line();
            if (!line) {
                return std::nullopt; // a mark at the end closes the deck, as the hopper's end
            }
            std::optional<Card> card =
                !line->empty() && (*line)[0] == '~' ? control_line(*line) : characters(*line);
            if (card) {
                warn_of_mark();
                return card;
            }
        }
    }

private:
    // The next line without its end (LF, or CRLF); nothing at the end of the file.
    std::optional<std::string> read_line() {
        using traits = std::streambuf::traits_type;
        int ch = buf_.sbumpc();
        if (ch == traits::eof()) {
            return std::nullopt;
        }
        ++line_;
        std::string line;
        if (line_ == 1 && ch == 0xEF && buf_.sgetc() == 0xBB) {
            // A UTF-8 byte-order mark (an editor's "UTF-8 with BOM"): read past, as the
            // listing and the G-code reader read past one (docs/deck-formats.md).
            buf_.sbumpc();
            if (buf_.sgetc() != 0xBF) {
                throw DeckError::at_line_column(file_, line_, 1,
                                                "bytes 0xef 0xbb begin a byte-order mark that "
                                                "does not end (0xef 0xbb 0xbf)");
            }
            buf_.sbumpc();
            ch = buf_.sbumpc();
        }
        for (; ch != traits::eof() && ch != '\n'; ch = buf_.sbumpc()) {
            if (line.size() >= kMaxTextLineBytes) {
                throw DeckError::at_line(
                    file_, line_,
                    fmt::format("line is longer than {} bytes: no card image is (an endless line "
                                "or not a text deck)",
                                kMaxTextLineBytes));
            }
            if (ch == '\r') {
                const int after = buf_.sgetc();
                if (after == '\n' || after == traits::eof()) {
                    continue;
                }
                throw DeckError::at_line_column(file_, line_, column_of(line) + 1,
                                                "carriage return inside a line");
            }
            line += static_cast<char>(ch);
        }
        return line;
    }

    // The card column a character at the end of `line` would fall in (tabs expanded).
    static int column_of(const std::string& line) {
        int col = 0;
        for (char c : line) {
            col = c == '\t' ? (col | 7) + 1 : col + 1;
        }
        return col;
    }

    // SIMH's lines that begin with '~' (sim_card.c): "~raw" and 80 octal column words, the
    // control cards ~eor, ~eof, ~eoi, and a lone '~'. Nothing for an end-of-file mark.
    std::optional<Card> control_line(const std::string& line) {
        const std::string rest = line.substr(1);
        if (rest.find_first_not_of(" \t") == std::string::npos) {
            note_mark("a lone '~' is SIMH's end-of-file flag");
            return std::nullopt;
        }
        const std::string word = lower(rest.substr(0, 3));
        const std::string after = rest.substr(std::min<std::size_t>(3, rest.size()));
        const bool bare = after.find_first_not_of(" \t") == std::string::npos;
        if (word == "raw") {
            return raw_card(after);
        }
        if (bare && word == "eor") {
            Card card;
            card.set_column(1, kEndOfRecord);
            return card;
        }
        if (bare && (word == "eof" || word == "eoi")) {
            note_mark(word == "eof" ? "'~eof' is SIMH's end-of-file card (rows 6-7-9)"
                                    : "'~eoi' is SIMH's end-of-input card (rows 6-7-8-9)");
            return std::nullopt;
        }
        throw DeckError::at_line_column(
            file_, line_, 1,
            fmt::format("'{}' is no SIMH control line (~raw followed by octal column words, "
                        "~eor, ~eof, ~eoi, or a lone ~); '~' is no keypunch character",
                        line.substr(0, 12)));
    }

    // "~raw": four octal digits a column, rows 12 .. 9, as many columns as given (at most 80).
    Card raw_card(const std::string& digits) {
        Card card;
        int col = 0;
        int got = 0;
        ColumnWord word = 0;
        for (std::size_t i = 0; i < digits.size(); ++i) {
            const char c = digits[i];
            if (c < '0' || c > '7') {
                throw DeckError::at_line_column(
                    file_, line_, static_cast<int>(i) + 5,
                    fmt::format("{} in a ~raw card: each column is four octal digits 0-7 (rows "
                                "12-11-0 .. 7-8-9)",
                                describe_char(static_cast<unsigned char>(c))));
            }
            if (col >= kColumns) {
                throw DeckError::at_line_column(
                    file_, line_, static_cast<int>(i) + 5,
                    "a ~raw card has more than 80 columns (320 octal digits)");
            }
            word = static_cast<ColumnWord>(word << 3 | (c - '0'));
            if (++got == 4) { // four octal digits: 12 bits, every row and nothing more
                card.set_column(++col, word);
                word = 0;
                got = 0;
            }
        }
        if (got != 0) {
            throw DeckError::at_line_column(
                file_, line_, static_cast<int>(digits.size()) + 4,
                fmt::format("a ~raw card ends inside a column word ({} of its 4 octal digits)",
                            got));
        }
        return card;
    }

    Card characters(const std::string& line) {
        Card card;
        int col = 0; // columns filled so far
        for (char c : line) {
            const int ch = static_cast<unsigned char>(c);
            if (col >= kColumns) {
                past_column_80();
                break;
            }
            if (ch == '\t') {
                col = std::min((col | 7) + 1, kColumns);
                continue;
            }
            int folded = (ch >= 'a' && ch <= 'z') ? ch - 'a' + 'A' : ch;
            auto punches = punches_for(static_cast<char>(folded), code_);
            if (!punches) {
                throw DeckError::at_line_column(
                    file_, line_, col + 1,
                    fmt::format("{} is not a character of the IBM {} keypunch", describe_char(ch),
                                code_name(code_)));
            }
            card.set_column(col + 1, *punches);
            ++col;
        }
        return card;
    }

    // Text past column 80 is dropped, as SIMH's sim_card.c drops it; the first line that has
    // some is told (a card has 80 columns: a sequence number or a note beyond them).
    void past_column_80() {
        if (told_past_80_ || !warn_) {
            return;
        }
        told_past_80_ = true;
        warn_(fmt::format("{}:{}: text past column 80 dropped, as SIMH drops it (a card has 80 "
                          "columns); the same on any later line, not told again",
                          file_, line_));
    }

    // An end-of-file mark on this line: said when a card comes after it (not at the deck's end).
    void note_mark(const std::string& what) {
        if (!mark_) {
            mark_ = fmt::format("{}:{}: {}, for a monitor program the 1952 machine does not have: "
                                "it is passed over and the cards after it are read, as SIMH "
                                "reads on",
                                file_, line_, what);
        }
    }
    void warn_of_mark() {
        if (mark_ && warn_) {
            warn_(*mark_);
        }
        mark_.reset();
    }

    std::streambuf& buf_;
    std::string file_;
    KeypunchCode code_;
    std::function<void(const std::string&)> warn_;
    std::int64_t line_ = 0;
    std::optional<std::string> mark_; // the warning of a mark no card has followed yet
    bool told_past_80_ = false;
};

class TextSink : public CardSink {
public:
    TextSink(std::ostream& out, std::string file, KeypunchCode code)
        : out_(out), file_(std::move(file)), code_(code) {}

    void write(const Card& card) override {
        ++card_;
        if (only_column_1(card, kEndOfRecord)) {
            out_ << "~eor\n";
        } else if (auto line = as_characters(card)) {
            out_ << *line << '\n';
        } else {
            out_ << raw_line(card) << '\n';
        }
        if (!out_) {
            throw DeckError::in_file(file_, "write error");
        }
    }

    // The card as keypunch characters, trailing blanks trimmed; nothing when a column holds
    // holes no key makes, or when the line would read back as a SIMH control line.
    std::optional<std::string> as_characters(const Card& card) const {
        std::string line;
        for (int c = 1; c <= kColumns; ++c) {
            const CodeEntry* e = entry_for_punches(card.column(c), code_);
            if (!e) {
                return std::nullopt;
            }
            line += e->ascii;
        }
        line.erase(line.find_last_not_of(' ') + 1);
        if (!line.empty() && line[0] == '~') {
            return std::nullopt;
        }
        return line;
    }

    // As SIMH's punch writes a card that is not all characters: "~raw" and 80 four-digit
    // octal column words (an end-of-file or end-of-input card too, which as ~eof or ~eoi
    // would be passed over when read back).
    static std::string raw_line(const Card& card) {
        std::string line = "~raw";
        for (int c = 1; c <= kColumns; ++c) {
            line += fmt::format("{:04o}", card.column(c));
        }
        return line;
    }

private:
    std::ostream& out_;
    std::string file_;
    KeypunchCode code_;
    std::int64_t card_ = 0;
};

} // namespace

std::unique_ptr<CardSource> make_text_source(std::istream& in, std::string file, KeypunchCode code,
                                             std::function<void(const std::string&)> warn) {
    return std::make_unique<TextSource>(in, std::move(file), code, std::move(warn));
}

std::unique_ptr<CardSink> make_text_sink(std::ostream& out, std::string file, KeypunchCode code) {
    return std::make_unique<TextSink>(out, std::move(file), code);
}

} // namespace parsons::cardreader
