#include "cardreader/deck_io.hpp"

#include "cardreader/bin_format.hpp"
#include "cardreader/cbn_format.hpp"
#include "cardreader/deck_error.hpp"
#include "cardreader/five_card_format.hpp"
#include "cardreader/listing_format.hpp"
#include "cardreader/tape_format.hpp"
#include "cardreader/text_format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cctype>
#include <istream>

namespace parsons::cardreader {
namespace {

// Refuses a deck with no cards at all: an empty file is a mistake, not an empty job.
class NonEmptySource : public CardSource {
public:
    NonEmptySource(std::unique_ptr<CardSource> inner, std::string file, bool empty_file)
        : inner_(std::move(inner)), file_(std::move(file)), empty_file_(empty_file) {}

    std::optional<Card> next() override {
        auto card = inner_->next();
        if (!card && !any_) {
            throw DeckError::in_file(file_, empty_file_
                                                ? "empty file: the deck has no cards"
                                                : "no cards: the file holds nothing but a "
                                                  "header, comments, blank lines or blank tape");
        }
        any_ = true;
        return card;
    }
    int cards_a_step() const override { return inner_->cards_a_step(); }

private:
    std::unique_ptr<CardSource> inner_;
    std::string file_;
    bool empty_file_ = false;
    bool any_ = false;
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
    return std::make_unique<NonEmptySource>(std::move(inner), options.file_name, empty_file);
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
