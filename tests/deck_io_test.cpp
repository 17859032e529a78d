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
