#include "cardreader/text_format.hpp"

#include "cardreader/deck_error.hpp"

#include <fmt/format.h>

#include <istream>
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

class TextSource : public CardSource {
public:
    TextSource(std::istream& in, std::string file, KeypunchCode code)
        : buf_(*in.rdbuf()), file_(std::move(file)), code_(code) {}

    std::optional<Card> next() override {
        using traits = std::streambuf::traits_type;
        int ch = buf_.sbumpc();
        if (ch == traits::eof()) {
            return std::nullopt;
        }
        ++line_;
        Card card;
        int col = 0; // columns filled so far
        for (; ch != traits::eof() && ch != '\n'; ch = buf_.sbumpc()) {
            if (ch == '\r') {
                int after = buf_.sgetc();
                if (after == '\n' || after == traits::eof()) {
                    continue;
                }
                throw DeckError::at_line_column(file_, line_, col + 1,
                                                "carriage return inside a line");
            }
            if (ch == '\t') {
                col = (col | 7) + 1;
                if (col > kColumns) {
                    throw too_long();
                }
                continue;
            }
            if (col >= kColumns) {
                throw too_long();
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

private:
    DeckError too_long() const {
        return DeckError::at_line_column(
            file_, line_, kColumns + 1,
            "line is longer than 80 columns (a card has 80; nothing is cut off silently)");
    }

    std::streambuf& buf_;
    std::string file_;
    KeypunchCode code_;
    long line_ = 0;
};

class TextSink : public CardSink {
public:
    TextSink(std::ostream& out, std::string file, KeypunchCode code)
        : out_(out), file_(std::move(file)), code_(code) {}

    void write(const Card& card) override {
        ++card_;
        std::string line;
        for (int c = 1; c <= kColumns; ++c) {
            const CodeEntry* e = entry_for_punches(card.column(c), code_);
            if (!e) {
                throw DeckError::at_card_column(
                    file_, card_, c,
                    fmt::format("punches {} are no character of the IBM {} keypunch, so this card "
                                "cannot be written as a text card image (use .cbn or .bin)",
                                punches_text(card.column(c)), code_name(code_)));
            }
            line += e->ascii;
        }
        line.erase(line.find_last_not_of(' ') + 1);
        out_ << line << '\n';
        if (!out_) {
            throw DeckError::in_file(file_, "write error");
        }
    }

private:
    std::ostream& out_;
    std::string file_;
    KeypunchCode code_;
    long card_ = 0;
};

} // namespace

std::unique_ptr<CardSource> make_text_source(std::istream& in, std::string file,
                                             KeypunchCode code) {
    return std::make_unique<TextSource>(in, std::move(file), code);
}

std::unique_ptr<CardSink> make_text_sink(std::ostream& out, std::string file, KeypunchCode code) {
    return std::make_unique<TextSink>(out, std::move(file), code);
}

} // namespace parsons::cardreader
