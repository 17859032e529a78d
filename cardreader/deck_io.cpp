#include "cardreader/deck_io.hpp"

#include "cardreader/bin_format.hpp"
#include "cardreader/cbn_format.hpp"
#include "cardreader/deck_error.hpp"
#include "cardreader/five_card_format.hpp"
#include "cardreader/listing_format.hpp"
#include "cardreader/tape_format.hpp"
#include "cardreader/text_format.hpp"

#include <algorithm>
#include <cctype>

namespace parsons::cardreader {
namespace {

// Refuses a deck with no cards at all: an empty file is a mistake, not an empty job.
class NonEmptySource : public CardSource {
public:
    NonEmptySource(std::unique_ptr<CardSource> inner, std::string file)
        : inner_(std::move(inner)), file_(std::move(file)) {}

    std::optional<Card> next() override {
        auto card = inner_->next();
        if (!card && !any_) {
            throw DeckError::in_file(file_, "empty file: the deck has no cards");
        }
        any_ = true;
        return card;
    }

private:
    std::unique_ptr<CardSource> inner_;
    std::string file_;
    bool any_ = false;
};

} // namespace

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

std::optional<DeckFormat> format_for_path(std::string_view path) {
    const auto dot = path.rfind('.');
    const auto slash = path.find_last_of("/\\");
    if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash)) {
        return std::nullopt;
    }
    std::string ext(path.substr(dot + 1));
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == "cbn") {
        return DeckFormat::cbn;
    }
    if (ext == "bin") {
        return DeckFormat::bin;
    }
    if (ext == "txt" || ext == "crd" || ext == "card" || ext == "cards") {
        return DeckFormat::text;
    }
    if (ext == "csv" || ext == "lst") {
        return DeckFormat::listing;
    }
    if (ext == "tape" || ext == "ptp") {
        return DeckFormat::tape;
    }
    if (ext == "five") {
        return DeckFormat::five;
    }
    return std::nullopt;
}

std::unique_ptr<CardSource> open_card_source(std::istream& in, const DeckOptions& options) {
    std::unique_ptr<CardSource> inner;
    switch (options.format) {
    case DeckFormat::cbn:
        inner = make_cbn_source(in, options.file_name);
        break;
    case DeckFormat::bin:
        inner = make_bin_source(in, options.file_name);
        break;
    case DeckFormat::text:
        inner = make_text_source(in, options.file_name, options.code);
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
    return std::make_unique<NonEmptySource>(std::move(inner), options.file_name);
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
