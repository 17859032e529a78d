#include "cardreader/cbn_format.hpp"
#include "cardreader/deck_error.hpp"

#include "tests/test_support.hpp"

#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <random>
#include <sstream>

using namespace parsons::cardreader;

namespace {

// An independent encoder written straight from SIMH's description of column binary, row by
// row, sharing no code with cbn_format.cpp: the first byte of a column carries rows 12, 11, 0,
// 1, 2, 3 in bits 5..0, the second rows 4 .. 9; bit 6 makes the count of ones odd; bit 7
// marks the first byte of the card.
std::string reference_cbn(const Card& card) {
    const int first_byte_rows[6] = {12, 11, 0, 1, 2, 3};
    const int second_byte_rows[6] = {4, 5, 6, 7, 8, 9};
    std::string bytes;
    for (int col = 1; col <= 80; ++col) {
        for (const int* rows : {first_byte_rows, second_byte_rows}) {
            unsigned byte = 0;
            int ones = 0;
            for (int i = 0; i < 6; ++i) {
                if (card.punched(col, row_named(rows[i]))) {
                    byte |= 1u << (5 - i);
                    ++ones;
                }
            }
            if (ones % 2 == 0) {
                byte |= 0x40;
            }
            bytes += static_cast<char>(byte);
        }
    }
    bytes[0] = static_cast<char>(static_cast<unsigned char>(bytes[0]) | 0x80);
    return bytes;
}

Card random_card(std::mt19937& rng) {
    Card card;
    for (int c = 1; c <= 80; ++c) {
        card.set_column(c, static_cast<ColumnWord>(rng() & 0xFFF));
    }
    return card;
}

std::string write_deck(const std::vector<Card>& cards) {
    std::ostringstream out;
    auto sink = make_cbn_sink(out, "out.cbn");
    for (const Card& c : cards) {
        sink->write(c);
    }
    return out.str();
}

std::string cbn_error(const std::string& bytes) {
    return parsons::test::read_error(bytes, DeckFormat::cbn, "deck.cbn");
}

} // namespace

TEST_CASE("Column binary: a blank card is C0 then 159 bytes of 40", "[cbn]") {
    const std::string bytes = write_deck({Card{}});
    REQUIRE(bytes.size() == 160);
    CHECK(static_cast<unsigned char>(bytes[0]) == 0xC0);
    for (std::size_t i = 1; i < 160; ++i) {
        CHECK(static_cast<unsigned char>(bytes[i]) == 0x40);
    }
}

TEST_CASE("Column binary: parsons writes the same bytes as an independent SIMH-layout encoder",
          "[cbn]") {
    std::mt19937 rng(1952);
    std::vector<Card> cards;
    std::string expected;
    for (int i = 0; i < 200; ++i) {
        cards.push_back(random_card(rng));
        expected += reference_cbn(cards.back());
    }
    CHECK(write_deck(cards) == expected);
}

TEST_CASE("Column binary: a deck reads back card for card", "[cbn]") {
    std::mt19937 rng(2820187);
    std::vector<Card> cards(50);
    for (Card& c : cards) {
        c = random_card(rng);
    }
    std::istringstream in(write_deck(cards));
    DeckOptions options;
    options.format = DeckFormat::cbn;
    auto source = open_card_source(in, options);
    for (const Card& c : cards) {
        auto read = source->next();
        REQUIRE(read);
        CHECK(*read == c);
    }
    CHECK_FALSE(source->next());
}

TEST_CASE("Column binary: a truncated card names the card and byte where the file ends",
          "[cbn][bad-input]") {
    std::string bytes = write_deck({Card{}, Card{}});
    bytes.resize(260);
    CHECK(cbn_error(bytes) == "deck.cbn: card 2, byte 261 (offset 0x104): truncated card: the "
                              "file ends after 100 of its 160 bytes");
}

TEST_CASE("Column binary: a card without the card-start flag is reported, not read",
          "[cbn][bad-input]") {
    std::string bytes = write_deck({Card{}, Card{}});
    bytes[160] = static_cast<char>(0x40);
    CHECK(cbn_error(bytes) == "deck.cbn: card 2, byte 161 (offset 0xa0): no card-start mark: bit "
                              "7 of the first byte of every card must be set");
}

TEST_CASE("Column binary: a card-start flag inside a card is reported", "[cbn][bad-input]") {
    std::string bytes = write_deck({Card{}});
    bytes[21] = static_cast<char>(0xC0);
    CHECK(cbn_error(bytes) ==
          "deck.cbn: card 1, byte 22 (offset 0x15): card-start mark (bit 7) inside the card at "
          "column 11: the card is short or the file is not column binary");
}

TEST_CASE("Column binary: a parity error names card, byte and column", "[cbn][bad-input]") {
    std::string bytes = write_deck({Card{}});
    bytes[5] = static_cast<char>(0x00); // column 3, rows 4-9: even parity
    CHECK(cbn_error(bytes) == "deck.cbn: card 1, byte 6 (offset 0x5): parity error in column 3 "
                              "(byte 0x00 has even parity; column binary uses odd parity)");
}

TEST_CASE("Column binary: an empty file is an error, not an empty deck", "[cbn][bad-input]") {
    CHECK(cbn_error("") == "deck.cbn: empty file: the deck has no cards");
}

// The kind of the .bin low-bit check (issue 11, item 7): no single wrong hole is read silently.
TEST_CASE("Column binary: any one bit flipped in any byte of a card is refused, never read",
          "[cbn][bad-input]") {
    std::mt19937 rng(1130);
    const Card card = random_card(rng);
    const std::string good = write_deck({card, card});
    for (std::size_t i = 0; i < 160; ++i) {
        for (int bit = 0; bit < 7; ++bit) {
            std::string bytes = good;
            bytes.at(160 + i) = static_cast<char>(bytes.at(160 + i) ^ (1 << bit));
            INFO("byte " << i << ", bit " << bit);
            const std::string error = cbn_error(bytes);
            CHECK(
                error.find(fmt::format("deck.cbn: card 2, byte {} (offset {:#x}): parity error in "
                                       "column {} ",
                                       160 + i + 1, 160 + i, i / 2 + 1)) == 0);
        }
    }
}
