#include "cardreader/deck_error.hpp"
#include "cardreader/deck_io.hpp"

#include <catch2/catch.hpp>

#include <random>
#include <sstream>

using namespace parsons::cardreader;

TEST_CASE("Deck files: the format follows the extension", "[deck-io]") {
    CHECK(format_for_path("a/b/deck.cbn") == DeckFormat::cbn);
    CHECK(format_for_path("DECK.BIN") == DeckFormat::bin);
    CHECK(format_for_path("cards.txt") == DeckFormat::text);
    CHECK(format_for_path("cards.crd") == DeckFormat::text);
    CHECK(format_for_path("job.csv") == DeckFormat::listing);
    CHECK(format_for_path("job.lst") == DeckFormat::listing);
    CHECK_FALSE(format_for_path("dir.cbn/deck"));
    CHECK_FALSE(format_for_path("deck"));
    CHECK(format_named("listing") == DeckFormat::listing);
    CHECK_FALSE(format_named("csv"));
}

TEST_CASE("Deck files: every reader is total: random bytes give cards or a DeckError",
          "[deck-io][bad-input]") {
    std::mt19937 rng(80);
    const std::string alphabet = "0123456789,.+-\n\r\t #ABCtablecrossverticalswiveltilt";
    for (DeckFormat format :
         {DeckFormat::cbn, DeckFormat::bin, DeckFormat::text, DeckFormat::listing}) {
        for (int trial = 0; trial < 300; ++trial) {
            std::string bytes(rng() % 700, '\0');
            for (char& b : bytes) {
                b = trial % 2 == 0 ? static_cast<char>(rng()) : alphabet[rng() % alphabet.size()];
            }
            if (trial % 3 == 0 && format == DeckFormat::cbn) {
                for (std::size_t i = 0; i < bytes.size(); ++i) { // mostly well-formed
                    bytes[i] = static_cast<char>(i % 160 == 0 ? 0xC0 : 0x40);
                }
                if (!bytes.empty()) {
                    bytes[rng() % bytes.size()] = static_cast<char>(rng());
                }
            }
            std::istringstream in(bytes);
            DeckOptions options;
            options.format = format;
            options.file_name = "random";
            auto source = open_card_source(in, options);
            int cards = 0;
            try {
                while (source->next() && cards < 1000) {
                    ++cards;
                }
            } catch (const DeckError& e) {
                CHECK(std::string(e.what()).rfind("random", 0) == 0);
            }
            CHECK(cards <= 700);
        }
    }
}

TEST_CASE("Deck files: auto tells cbn, bin, text and listing from the first bytes as SIMH does",
          "[deck-io][simh]") {
    std::string cbn(160, '\x40');
    cbn[0] = static_cast<char>(0xC0);            // card-start mark, odd parity
    CHECK(sniff_format(cbn) == DeckFormat::cbn); // a blank card: .bin words too, but parity says
    cbn[5] = 0x00;                               // a parity fault: then its .bin words win
    CHECK(sniff_format(cbn) == DeckFormat::bin);
    cbn[5] = 0x01; // neither: the card-start mark still says column binary
    CHECK(sniff_format(cbn) == DeckFormat::cbn);
    std::string bin(160, '\0');
    bin[1] = static_cast<char>(0x80); // row 12 of column 1
    bin[2] = static_cast<char>(0x10); // row 9 of column 2: the low four bits stay clear
    CHECK(sniff_format(bin) == DeckFormat::bin);
    bin[2] = static_cast<char>(0x11); // a low bit set: not .bin, and not printable either
    CHECK_FALSE(sniff_format(bin));
    CHECK(sniff_format("HELLO 1952\n~raw0007\n") == DeckFormat::text);
    CHECK(sniff_format("card,spindle,axis\n") == DeckFormat::listing);
    CHECK(sniff_format("CARD,spindle,axis\n") == DeckFormat::listing);
    CHECK(sniff_format("# a listing\ncard,") == DeckFormat::listing);
    CHECK(sniff_format("\xEF\xBB\xBF"
                       "card,spindle") == DeckFormat::listing);
    // A whole first card of .bin words wins over text, as in sim_card.c (a blank card).
    CHECK(sniff_format(std::string(160, '\0')) == DeckFormat::bin);
    CHECK_FALSE(sniff_format(""));
}

TEST_CASE("Deck files: a common file that is no deck is named by its magic number",
          "[deck-io][bad-input]") {
    CHECK(non_deck_kind("\x89PNG\r\n\x1a\n....") == "a PNG image");
    CHECK(non_deck_kind("%PDF-1.7") == "a PDF document");
    CHECK(non_deck_kind(std::string("PK\x03\x04", 4)) == "a ZIP archive (an office document?)");
    CHECK(non_deck_kind("\x1f\x8b\x08") == "a gzip-compressed file (gunzip it first)");
    CHECK(non_deck_kind("<svg xmlns") == "an SVG picture");
    CHECK(non_deck_kind("$date\n  today\n$end") == "a VCD trace");
    CHECK(non_deck_kind("{\n  \"status\"") == "a JSON file (a report, a job or a state?)");
    CHECK_FALSE(non_deck_kind("card,spindle,axis"));
    CHECK_FALSE(non_deck_kind("HELLO"));
    std::string cbn(160, '\x40');
    cbn[0] = static_cast<char>(0xC0);
    CHECK_FALSE(non_deck_kind(cbn));
}
