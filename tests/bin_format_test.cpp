#include "cardreader/bin_format.hpp"
#include "cardreader/deck_error.hpp"

#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <random>
#include <sstream>

using namespace parsons::cardreader;

TEST_CASE("Binary cards: each column is the row word shifted left 4, little-endian", "[bin]") {
    Card card;
    card.set_column(1, 0x800); // row 12
    card.set_column(2, 0x001); // row 9
    card.set_column(3, 0xA5F);
    auto bytes = bin_encode(card);
    CHECK(bytes[0] == 0x00);
    CHECK(bytes[1] == 0x80);
    CHECK(bytes[2] == 0x10);
    CHECK(bytes[3] == 0x00);
    CHECK(bytes[4] == 0xF0);
    CHECK(bytes[5] == 0xA5);
    CHECK(bin_decode(bytes, "x.bin", 1, 0) == card);
}

TEST_CASE("Binary cards: a deck reads back card for card", "[bin]") {
    std::mt19937 rng(1130);
    std::vector<Card> cards(40);
    std::ostringstream out;
    auto sink = make_bin_sink(out, "x.bin");
    for (Card& c : cards) {
        for (int col = 1; col <= 80; ++col) {
            c.set_column(col, static_cast<ColumnWord>(rng() & 0xFFF));
        }
        sink->write(c);
    }
    std::istringstream in(out.str());
    auto source = make_bin_source(in, "x.bin");
    for (const Card& c : cards) {
        auto read = source->next();
        REQUIRE(read);
        CHECK(*read == c);
    }
    CHECK_FALSE(source->next());
}

TEST_CASE("Binary cards: bad bytes and short files name card and byte", "[bin][bad-input]") {
    auto error_of = [](const std::string& bytes) -> std::string {
        std::istringstream in(bytes);
        auto source = make_bin_source(in, "deck.bin");
        try {
            while (source->next()) {
            }
        } catch (const DeckError& e) {
            return e.what();
        }
        return "no error";
    };
    std::string bytes(320, '\0');
    bytes[160 + 6] = 0x03;
    CHECK(error_of(bytes) == "deck.bin: card 2, byte 167 (offset 0xa6): bits 3..0 of column 4's "
                             "first byte are 0x03, not zero: not an IBM 1130 binary card (column "
                             "binary? use --format cbn)");
    CHECK(error_of(std::string(170, '\0')) == "deck.bin: card 2, byte 171 (offset 0xaa): truncated "
                                              "card: the file ends after 10 of its 160 bytes");
}

// SIMH (sim_card.c, MODE_BIN) ORs the first byte of every column together and sets CARD_ERR
// when any of bits 3..0 is set: the card is a read error, not a card. So is it here (an error,
// exit 2), for every column and every one of the four bits, on any card of the deck.
TEST_CASE("Binary cards: a frame with any low bit set is refused, never read silently (SIMH "
          "CARD_ERR)",
          "[bin][bad-input]") {
    Card card;
    for (int col = 1; col <= 80; ++col) {
        card.set_column(col, static_cast<ColumnWord>((col * 37) & 0xFFF));
    }
    const auto good = bin_encode(card);
    const std::string one(good.begin(), good.end());
    const int which = GENERATE(1, 3);
    for (int col = 1; col <= 80; ++col) {
        for (int bit = 0; bit < 4; ++bit) {
            std::string bytes = one + one + one;
            const auto at = static_cast<std::size_t>((which - 1) * 160 + 2 * (col - 1));
            bytes.at(at) = static_cast<char>(bytes.at(at) | (1 << bit));
            std::istringstream in(bytes);
            auto source = make_bin_source(in, "deck.bin");
            INFO("card " << which << ", column " << col << ", bit " << bit);
            for (int k = 1; k < which; ++k) {
                CHECK(source->next() == card);
            }
            CHECK_THROWS_WITH(source->next(),
                              fmt::format("deck.bin: card {}, byte {} (offset {:#x}): bits 3..0 "
                                          "of column {}'s first byte are {:#04x}, not zero: not "
                                          "an IBM 1130 binary card (column binary? use --format "
                                          "cbn)",
                                          which, at + 1, at, col, 1 << bit));
        }
    }
}
