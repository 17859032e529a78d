#include "cardreader/deck_io.hpp"

#include "cardreader/bin_format.hpp"
#include "cardreader/cbn_format.hpp"
#include "cardreader/deck_error.hpp"
#include "cardreader/five_card_format.hpp"
#include "cardreader/listing_fields.hpp"
#include "cardreader/listing_format.hpp"
#include "cardreader/tape_format.hpp"
#include "cardreader/text_format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <istream>
#include <vector>

namespace parsons::cardreader {
namespace {

// Refuses a deck with no cards at all (an empty file is a mistake, not an empty job) and the
// card past kMaxDeckCards (five cards a step: the step, whose five cards share one number).
class BoundedSource : public CardSource {
public:
    BoundedSource(std::unique_ptr<CardSource> inner, std::string file, bool empty_file,
                  std::int64_t max_cards)
        : inner_(std::move(inner)), file_(std::move(file)), empty_file_(empty_file),
          max_cards_(max_cards) {}

    std::optional<Card> next() override {
        auto card = inner_->next();
        if (!card && !any_) {
            throw DeckError::in_file(file_, empty_file_
                                                ? "empty file: the deck has no cards"
                                                : "no cards: the file holds nothing but a "
                                                  "header, comments, blank lines or blank tape");
        }
        any_ = true;
        if (card && ++read_ > max_cards_) {
            const std::int64_t step = inner_->cards_a_step();
            const std::string which = step == 1 ? fmt::format("card {}", read_)
                                                : fmt::format("step {} (cards {}-{})", read_,
                                                              (read_ - 1) * step + 1, read_ * step);
            throw DeckError::in_file(
                file_, fmt::format("{}: a deck holds at most 9,999 {} (a card's number is four "
                                   "digits, columns 77-80: a longer deck would repeat card "
                                   "numbers); cut the deck in two",
                                   which, step == 1 ? "cards" : "steps"));
        }
        return card;
    }
    int cards_a_step() const override { return inner_->cards_a_step(); }

private:
    std::unique_ptr<CardSource> inner_;
    std::string file_;
    bool empty_file_ = false;
    bool any_ = false;
    std::int64_t read_ = 0;
    std::int64_t max_cards_ = kMaxDeckCards;
};

} // namespace

void DeckFingerprint::add(const Card& card) {
    for (int c = 1; c <= kColumns; ++c) {
        const ColumnWord w = card.column(c);
        for (const unsigned byte : {w & 0xFFu, (w >> 8) & 0xFFu}) {
            hash_ = (hash_ ^ byte) * 0x100000001b3ULL;
        }
    }
    ++cards_;
}

std::string DeckFingerprint::hex() const {
    return fmt::format("{:016x}", hash_);
}

std::string_view format_name(DeckFormat f) {
    switch (f) {
    case DeckFormat::cbn:
        return "cbn";
    case DeckFormat::bin:
        return "bin";
    case DeckFormat::text:
        return "text";
    case DeckFormat::listing:
        return "listing";
    case DeckFormat::tape:
        return "tape";
    case DeckFormat::five:
        return "five";
    }
    return "cbn";
}

bool format_is_continuous(DeckFormat f) {
    return f == DeckFormat::tape;
}

std::optional<DeckFormat> format_named(std::string_view name) {
    for (DeckFormat f : kDeckFormats) {
        if (format_name(f) == name) {
            return f;
        }
    }
    return std::nullopt;
}

std::span<const std::string_view> format_extensions(DeckFormat f) {
    static constexpr std::array<std::string_view, 1> cbn = {"cbn"};
    static constexpr std::array<std::string_view, 1> bin = {"bin"};
    static constexpr std::array<std::string_view, 4> text = {"txt", "crd", "card", "cards"};
    static constexpr std::array<std::string_view, 2> listing = {"csv", "lst"};
    static constexpr std::array<std::string_view, 2> tape = {"tape", "ptp"};
    static constexpr std::array<std::string_view, 1> five = {"five"};
    switch (f) {
    case DeckFormat::cbn:
        return cbn;
    case DeckFormat::bin:
        return bin;
    case DeckFormat::text:
        return text;
    case DeckFormat::listing:
        return listing;
    case DeckFormat::tape:
        return tape;
    case DeckFormat::five:
        return five;
    }
    return {};
}

std::optional<DeckFormat> format_for_path(std::string_view path) {
    const auto dot = path.rfind('.');
    const auto slash = path.find_last_of("/\\");
    if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash)) {
        return std::nullopt;
    }
    std::string ext(path.substr(dot + 1));
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (DeckFormat f : kDeckFormats) {
        const auto known = format_extensions(f);
        if (std::find(known.begin(), known.end(), ext) != known.end()) {
            return f;
        }
    }
    return std::nullopt;
}

namespace {

// Every first byte of a column's pair has its low four bits clear (the .bin layout).
bool bin_words(std::string_view bytes) {
    if (bytes.size() % 2 != 0) {
        return false;
    }
    for (std::size_t i = 0; i < bytes.size(); i += 2) {
        if ((static_cast<unsigned char>(bytes[i]) & 0x0F) != 0) {
            return false;
        }
    }
    return true;
}

// Bytes 2..160 without the card-start mark, every byte (bits 6..0) of odd parity.
bool cbn_card(std::string_view bytes) {
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        const auto b = static_cast<unsigned char>(bytes[i]);
        if ((i > 0 && (b & 0x80) != 0) || std::popcount(static_cast<unsigned>(b & 0x7F)) % 2 != 1) {
            return false;
        }
    }
    return true;
}

} // namespace

std::optional<DeckFormat> sniff_format(std::string_view head) {
    if (head.empty()) {
        return std::nullopt;
    }
    std::string_view text = head;
    if (text.starts_with("\xEF\xBB\xBF")) {
        text.remove_prefix(3); // a spreadsheet's UTF-8 byte-order mark: a listing
    }
    std::string start(text.substr(0, 5));
    std::transform(start.begin(), start.end(), start.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (start.starts_with("#") || start == "card,") {
        return DeckFormat::listing;
    }
    // As sim_card.c tells them: a first card whose every byte has odd parity and whose first
    // alone has the card-start mark is column binary; else a whole first card of .bin words is
    // binary; else a card-start mark still says column binary (a damaged card: its reader
    // names the fault); anything else is text.
    const bool mark = (static_cast<unsigned char>(head[0]) & 0x80) != 0;
    if (mark && head.size() >= 160 && cbn_card(head.substr(0, 160))) {
        return DeckFormat::cbn;
    }
    if (head.size() >= 160 && bin_words(head.substr(0, 160))) {
        return DeckFormat::bin;
    }
    if (mark) {
        return DeckFormat::cbn;
    }
    const bool printable = std::all_of(text.begin(), text.end(), [](char c) {
        const auto u = static_cast<unsigned char>(c);
        return (u >= 0x20 && u < 0x7F) || c == '\n' || c == '\r' || c == '\t';
    });
    if (printable) {
        return DeckFormat::text;
    }
    if (bin_words(head)) {
        return DeckFormat::bin; // a short one: its reader says where it ends
    }
    return std::nullopt;
}

namespace {

constexpr std::size_t kSignatureCardBytes = 160; // a card of .cbn and .bin alike

// Every byte printable ASCII, a tab or a line end (after a UTF-8 byte-order mark), and at
// least one: what text card images and a listing are made of.
bool printable_text(std::string_view head) {
    if (head.starts_with("\xEF\xBB\xBF")) {
        head.remove_prefix(3);
    }
    return !head.empty() && std::all_of(head.begin(), head.end(), [](char c) {
        const auto u = static_cast<unsigned char>(c);
        return (u >= 0x20 && u < 0x7F) || c == '\n' || c == '\r' || c == '\t';
    });
}

// Printable text whose every line fits a card: 80 columns at most (a tab to the next multiple
// of eight), or a SIMH line that begins with '~' (~raw holds 320 octal digits). The last line
// of a head as long as kDeckHeadBytes may be cut short, so it is not measured.
bool text_card_lines(std::string_view head) {
    if (!printable_text(head)) {
        return false;
    }
    const bool whole_file = head.size() < kDeckHeadBytes;
    std::size_t start = 0;
    while (start < head.size()) {
        const std::size_t nl = head.find('\n', start);
        if (nl == std::string_view::npos && !whole_file) {
            break;
        }
        const std::string_view line = head.substr(start, std::min(nl, head.size()) - start);
        int columns = 0;
        for (const char c : line) {
            columns = c == '\t' ? (columns | 7) + 1 : c == '\r' ? columns : columns + 1;
        }
        if (columns > kColumns && !line.starts_with('~')) {
            return false;
        }
        start = nl == std::string_view::npos ? head.size() : nl + 1;
    }
    return true;
}

// The number of whole 160-byte cards at the head, each a column-binary card (0 when not all).
std::size_t cbn_cards_at(std::string_view head) {
    const std::size_t n = head.size() / kSignatureCardBytes;
    for (std::size_t k = 0; k < n; ++k) {
        const auto card = head.substr(k * kSignatureCardBytes, kSignatureCardBytes);
        if ((static_cast<unsigned char>(card[0]) & 0x80) == 0 || !cbn_card(card)) {
            return 0;
        }
    }
    return n;
}

// Every byte of the whole cards, bits 6..0, of odd parity: column binary, or column binary
// whose card-start marks are missing (a damaged .cbn, which its reader names).
bool odd_parity_cards(std::string_view head) {
    const auto bytes = head.substr(0, head.size() / kSignatureCardBytes * kSignatureCardBytes);
    return !bytes.empty() && std::all_of(bytes.begin(), bytes.end(), [](char c) {
        return std::popcount(static_cast<unsigned>(static_cast<unsigned char>(c) & 0x7F)) % 2 == 1;
    });
}

// The number of whole cards at the head whose words are all .bin words (0 when not all).
std::size_t bin_cards_at(std::string_view head) {
    const std::size_t n = head.size() / kSignatureCardBytes;
    return bin_words(head.substr(0, n * kSignatureCardBytes)) ? n : 0;
}

// A whole tape card at the head: the blank leader frames before it, or nothing.
std::optional<std::size_t> tape_card_at(std::string_view head) {
    const std::size_t leader = std::min(head.find_first_not_of('\0'), head.size());
    if (head.size() < leader + kTapeDataFrames + 1) {
        return std::nullopt;
    }
    for (std::size_t i = leader; i < leader + kTapeDataFrames; ++i) {
        const auto f = static_cast<unsigned char>(head[i]);
        if ((f & kTapeEndOfCard) != 0 || std::popcount(static_cast<unsigned>(f)) % 2 == 0) {
            return std::nullopt;
        }
    }
    if (static_cast<unsigned char>(head[leader + kTapeDataFrames]) != kTapeEndOfCard) {
        return std::nullopt;
    }
    return leader;
}

// The line (1-based) of the listing's header, when it is the first line of printable text
// that is not blank or a comment, as the listing reader wants it; else nothing.
std::optional<int> listing_header_line(std::string_view head) {
    if (!printable_text(head)) {
        return std::nullopt;
    }
    if (head.starts_with("\xEF\xBB\xBF")) {
        head.remove_prefix(3);
    }
    int line = 0;
    std::size_t start = 0;
    while (start < head.size()) {
        const std::size_t nl = std::min(head.find('\n', start), head.size());
        ++line;
        const std::string_view whole = head.substr(start, nl - start);
        const std::string_view data = detail::trim(whole.substr(0, whole.find('#')));
        const std::string_view text = data.ends_with('\r') ? data.substr(0, data.size() - 1) : data;
        if (!detail::trim(text).empty()) {
            return detail::split_fields(detail::trim(text)) == detail::split_fields(kListingHeader)
                       ? std::optional<int>(line)
                       : std::nullopt;
        }
        start = nl + 1;
    }
    return std::nullopt;
}

std::string cards_said(std::size_t n, std::string_view what) {
    return fmt::format("its first {} bytes are {} whole {} card{}", n * kSignatureCardBytes, n,
                       what, n == 1 ? "" : "s");
}

} // namespace

std::optional<ContentFormat> content_outranks(DeckFormat extension, std::string_view head) {
    const bool text = printable_text(head);
    const auto header = listing_header_line(head);
    const std::size_t cbn = cbn_cards_at(head);
    const std::size_t bin = bin_cards_at(head);
    const auto tape = tape_card_at(head);
    const bool comma = head.find(',') != std::string_view::npos;
    bool fits = false;
    switch (extension) {
    case DeckFormat::cbn:
    case DeckFormat::five: // the same bytes: five cards a step are told by no byte
        fits = cbn > 0;
        break;
    case DeckFormat::bin:
        fits = bin > 0;
        break;
    case DeckFormat::tape:
        fits = tape.has_value();
        break;
    case DeckFormat::listing:
        fits = text && (header || comma);
        break;
    case DeckFormat::text:
        fits = text && !header;
        break;
    }
    if (fits) {
        return std::nullopt;
    }
    std::vector<ContentFormat> found;
    if (cbn > 0) {
        found.push_back(
            {DeckFormat::cbn, cards_said(cbn, "column-binary") +
                                  ": a card-start mark (bit 7) on each card's first byte alone and "
                                  "every byte of odd parity"});
    }
    if (bin > 0 && !text && !odd_parity_cards(head)) {
        found.push_back(
            {DeckFormat::bin, cards_said(bin, "IBM 1130 binary") +
                                  ": bits 3..0 of every column's first byte clear, and neither "
                                  "printable text nor every byte of odd parity as column binary"});
    }
    if (tape) {
        found.push_back({DeckFormat::tape,
                         fmt::format("{}160 frames with channel 8 clear and odd parity, then an "
                                     "end-of-card frame (channel 8 alone)",
                                     *tape == 0 ? std::string()
                                                : fmt::format("after {} blank leader frame{}, ",
                                                              *tape, *tape == 1 ? "" : "s"))});
    }
    if (header) {
        found.push_back({DeckFormat::listing, fmt::format("line {} is the listing's header '{}'",
                                                          *header, kListingHeader)});
    }
    if (text && !header && text_card_lines(head)) {
        found.push_back(
            {DeckFormat::text,
             fmt::format("its first {} bytes are printable ASCII in lines of a card each{}",
                         head.size(),
                         extension == DeckFormat::listing
                             ? ", and none holds a comma, as every listing row does"
                             : ", with no card-start mark or binary byte")});
    }
    if (found.size() != 1) {
        return std::nullopt; // none, or several equally: the extension's reader says what it finds
    }
    return found.front();
}

std::optional<std::string> non_deck_kind(std::string_view head) {
    struct Magic {
        std::string_view start;
        const char* kind;
    };
    static constexpr Magic kMagic[] = {
        {"\x89PNG\r\n\x1a\n", "a PNG image"},
        {"%PDF-", "a PDF document"},
        {"GIF87a", "a GIF image"},
        {"GIF89a", "a GIF image"},
        {"\xFF\xD8\xFF", "a JPEG image"},
        {"PK\x03\x04", "a ZIP archive (an office document?)"},
        {"\x1F\x8B", "a gzip-compressed file (gunzip it first)"},
        {"\xFD"
         "7zXZ",
         "an xz-compressed file"},
        {"\x7F"
         "ELF",
         "an ELF executable"},
        {"<?xml", "an XML file"},
        {"<svg", "an SVG picture"},
        {"$date", "a VCD trace"},
        {"$version", "a VCD trace"},
        {"$timescale", "a VCD trace"},
        {"{", "a JSON file (a report, a job or a state?)"},
    };
    for (const Magic& m : kMagic) {
        if (head.starts_with(m.start)) {
            return std::string(m.kind);
        }
    }
    return std::nullopt;
}

std::unique_ptr<CardSource> open_card_source(std::istream& in, const DeckOptions& options) {
    const bool empty_file = in.peek() == std::char_traits<char>::eof();
    if (empty_file) {
        in.clear(); // the peek's end-of-file: each reader finds it again
    }
    std::unique_ptr<CardSource> inner;
    switch (options.format) {
    case DeckFormat::cbn:
        inner = make_cbn_source(in, options.file_name);
        break;
    case DeckFormat::bin:
        inner = make_bin_source(in, options.file_name);
        break;
    case DeckFormat::text:
        inner = make_text_source(in, options.file_name, options.code, options.warn);
        break;
    case DeckFormat::listing:
        inner = make_listing_source(in, options.file_name, *options.layout);
        break;
    case DeckFormat::tape:
        inner = make_tape_source(in, options.file_name);
        break;
    case DeckFormat::five:
        inner = make_five_card_source(in, options.file_name, *options.layout);
        break;
    }
    return std::make_unique<BoundedSource>(std::move(inner), options.file_name, empty_file,
                                           options.max_cards);
}

std::unique_ptr<CardSink> open_card_sink(std::ostream& out, const DeckOptions& options) {
    switch (options.format) {
    case DeckFormat::bin:
        return make_bin_sink(out, options.file_name);
    case DeckFormat::text:
        return make_text_sink(out, options.file_name, options.code);
    case DeckFormat::listing:
        return make_listing_sink(out, options.file_name, *options.layout);
    case DeckFormat::tape:
        return make_tape_sink(out, options.file_name);
    case DeckFormat::five:
        return make_five_card_sink(out, options.file_name, *options.layout);
    case DeckFormat::cbn:
        break;
    }
    return make_cbn_sink(out, options.file_name);
}

} // namespace parsons::cardreader
