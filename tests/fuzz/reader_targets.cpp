// The deck readers as fuzz targets: .cbn, .bin, text card images and the listing.
//
// Every card a reader yields is also decoded by the fig8 layout and reviewed as `parsons show`
// does, and written back in the same format and read again: the card must come back the same.
// A reader may refuse the bytes only with a DeckError whose message starts with the file name.
#include "tests/fuzz/fuzz_targets.hpp"

#include "cardreader/bin_format.hpp"
#include "cardreader/cbn_format.hpp"
#include "cardreader/deck_error.hpp"
#include "cardreader/deck_io.hpp"
#include "cardreader/deck_review.hpp"
#include "cardreader/five_card_format.hpp"
#include "cardreader/layout.hpp"
#include "cardreader/listing_format.hpp"
#include "cardreader/segment_listing.hpp"
#include "cardreader/sync_listing.hpp"
#include "cardreader/tap_listing.hpp"
#include "cardreader/tape_format.hpp"
#include "cardreader/text_format.hpp"

#include <fmt/format.h>

#include <functional>
#include <sstream>
#include <string>
#include <string_view>

namespace parsons::fuzz {
namespace {

using namespace parsons::cardreader;

constexpr const char* kFile = "fuzz-deck";

void check_names_file(const DeckError& e, const std::string& file) {
    if (std::string_view(e.what()).rfind(file, 0) != 0) {
        throw Finding(fmt::format("a DeckError that does not start with the file name '{}': {}",
                                  file, e.what()));
    }
}

// A condition, sync, tap or segment card (additions) that decodes is punched again by the keypunch
// into a card that reads as the same orders (not always the same holes: a parameter punched 0000
// is punched blank), and its listing rows read back as the same orders.
void extension_round_trip(const CardOrders& orders) {
    const std::string_view kind = orders.kind == CardKind::sync      ? "sync"
                                  : orders.kind == CardKind::tap     ? "tap"
                                  : orders.kind == CardKind::segment ? "segment"
                                                                     : "condition";
    const EncodeResult punched = encode(orders, fig8_layout());
    const DecodeResult again = punched ? decode(punched.card, fig8_layout()) : DecodeResult{};
    if (!punched || !again || again.orders != orders) {
        throw Finding(
            fmt::format("{} card: decoded, punched again and read, it came out different", kind));
    }
    std::ostringstream rows;
    rows << kListingHeader << '\n';
    for (int i = 0; i < orders.condition_count; ++i) {
        rows << condition_row(orders, i) << '\n';
    }
    if (orders.kind == CardKind::sync) {
        for (const std::string& row : sync_rows(orders)) {
            rows << row << '\n';
        }
    }
    if (orders.kind == CardKind::tap) {
        rows << tap_row(orders) << '\n';
    }
    if (orders.kind == CardKind::segment) {
        rows << segment_row(orders) << '\n';
    }
    std::istringstream in(rows.str());
    ListingReader reader(in, "rows.csv");
    const auto back = reader.next();
    if (!back || back->orders != orders || reader.next()) {
        throw Finding(fmt::format("{} card: its listing rows read back as other orders", kind));
    }
}

// Reads the whole deck; each card is decoded, reviewed and handed to `check`.
void read_deck(Bytes input, DeckOptions options, const std::function<void(const Card&)>& check) {
    options.file_name = kFile;
    std::istringstream in(as_string(input));
    auto source = open_card_source(in, options);
    DeckReviewer reviewer;
    try {
        while (auto card = source->next()) {
            const DecodeResult decoded = decode(*card, fig8_layout());
            if (decoded) {
                reviewer.review(decoded.orders);
                if (decoded.orders.kind != CardKind::motion) {
                    extension_round_trip(decoded.orders);
                }
            } else {
                reviewer.skip();
            }
            check(*card);
        }
        reviewer.finish();
    } catch (const DeckError& e) {
        check_names_file(e, kFile);
    }
}

// One card written with `sink_for` and read back with `source_for` must be the same card.
template <typename SinkFor, typename SourceFor>
void round_trip(const Card& card, const char* format, SinkFor sink_for, SourceFor source_for) {
    std::ostringstream out;
    sink_for(out)->write(card);
    std::istringstream in(out.str());
    auto back = source_for(in)->next();
    if (!back || *back != card) {
        throw Finding(
            fmt::format("{}: a card read, written and read again came back different", format));
    }
}

void read_text(Bytes input, KeypunchCode code) {
    DeckOptions options;
    options.format = DeckFormat::text;
    options.code = code;
    read_deck(input, options, [code](const Card& card) {
        // Every column of a card read from text came from a key, so the writer can write it.
        round_trip(
            card, "text", [code](std::ostream& out) { return make_text_sink(out, "out", code); },
            [code](std::istream& in) { return make_text_source(in, "out", code); });
    });
}

} // namespace

void fuzz_cbn(Bytes input) {
    DeckOptions options;
    options.format = DeckFormat::cbn;
    read_deck(input, options, [](const Card& card) {
        round_trip(
            card, "cbn", [](std::ostream& out) { return make_cbn_sink(out, "out"); },
            [](std::istream& in) { return make_cbn_source(in, "out"); });
    });
}

void fuzz_bin(Bytes input) {
    DeckOptions options;
    options.format = DeckFormat::bin;
    read_deck(input, options, [](const Card& card) {
        round_trip(
            card, "bin", [](std::ostream& out) { return make_bin_sink(out, "out"); },
            [](std::istream& in) { return make_bin_source(in, "out"); });
    });
}

void fuzz_tape(Bytes input) {
    DeckOptions options;
    options.format = DeckFormat::tape;
    read_deck(input, options, [](const Card& card) {
        round_trip(
            card, "tape", [](std::ostream& out) { return make_tape_sink(out, "out"); },
            [](std::istream& in) { return make_tape_source(in, "out"); });
    });
}

void fuzz_five(Bytes input) {
    DeckOptions options;
    options.format = DeckFormat::five;
    read_deck(input, options, [](const Card& card) {
        // A card reassembled from five per-axis cards splits into five again, and back.
        round_trip(
            card, "five",
            [](std::ostream& out) { return make_five_card_sink(out, "out", fig8_layout()); },
            [](std::istream& in) { return make_five_card_source(in, "out", fig8_layout()); });
    });
}

void fuzz_text(Bytes input) {
    read_text(input, KeypunchCode::ibm029);
    read_text(input, KeypunchCode::ibm026);
}

void fuzz_listing(Bytes input) {
    DeckOptions options;
    options.format = DeckFormat::listing;
    read_deck(input, options, [](const Card& card) {
        // The keypunch made this card from a listing the reader accepted: it must decode, and
        // its listing rows must keypunch the same card again.
        if (!decode(card, fig8_layout())) {
            throw Finding("listing: a card keypunched from an accepted listing does not decode");
        }
        round_trip(
            card, "listing",
            [](std::ostream& out) { return make_listing_sink(out, "out", fig8_layout()); },
            [](std::istream& in) { return make_listing_source(in, "out", fig8_layout()); });
    });
}

} // namespace parsons::fuzz
