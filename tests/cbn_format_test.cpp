#include "cardreader/cbn_format.hpp"
#include "cardreader/deck_error.hpp"

#include "tests/test_support.hpp"

#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <bit>
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

TEST_CASE("Column binary: a card is refused exactly when one of its bytes breaks the rule, byte "
          "by byte, wherever the bad bytes stand",
          "[cbn][bad-input]") {
    // The rule one byte at a time, as SIMH states it: bit 7 on the first byte only, odd parity
    // over bits 6..0. The reader checks eight bytes at a time; each of them, and each pair, is
    // made bad in turn here, besides cards of random bytes.
    auto byte_good = [](std::size_t i, std::uint8_t b) {
        const auto low = static_cast<unsigned>(b & 0x7F);
        const bool mark_ok = i == 0 ? (b & 0x80) != 0 : (b & 0x80) == 0;
        return mark_ok && std::popcount(low) % 2 == 1;
    };
    std::mt19937 rng(1952);
    const std::string good = write_deck({random_card(rng)});
    std::array<std::uint8_t, kCbnCardBytes> base{};
    std::copy(good.begin(), good.end(), base.begin());
    auto check = [&](const std::array<std::uint8_t, kCbnCardBytes>& bytes) {
        bool expect_good = true;
        for (std::size_t i = 0; i < bytes.size(); ++i) {
            expect_good = expect_good && byte_good(i, bytes[i]);
        }
        bool read = true;
        try {
            const Card card = cbn_decode(bytes, "deck.cbn", 1, 0);
            for (int c = 1; c <= 80; ++c) {
                const auto i = static_cast<std::size_t>(2 * (c - 1));
                REQUIRE(card.column(c) ==
                        static_cast<ColumnWord>((bytes[i] & 0x3F) << 6 | (bytes[i + 1] & 0x3F)));
            }
        } catch (const DeckError&) {
            read = false;
        }
        return read == expect_good;
    };
    REQUIRE(check(base));
    // A blank card too (every byte 0x40 after the first): a check that wrongly calls good bytes
    // bad only sends the reader to its byte-by-byte search, so the bad bytes are set among
    // bytes that are as plain as they can be, where one wrongly called good shows.
    std::array<std::uint8_t, kCbnCardBytes> blank{};
    blank.fill(0x40);
    blank[0] = 0xC0;
    int refused = 0;
    for (const auto& card : {base, blank}) {
        for (std::size_t i = 0; i < kCbnCardBytes; ++i) {
            for (unsigned v = 0; v < 256; ++v) { // every byte position, every value
                auto bytes = card;
                bytes[i] = static_cast<std::uint8_t>(v | (i == 0 ? 0x80 : 0));
                INFO("byte " << i << " = " << v);
                REQUIRE(check(bytes));
                refused += byte_good(i, bytes[i]) ? 0 : 1;
            }
        }
    }
    CHECK(refused > 20000);
    int read = 0;
    for (int n = 0; n < 3000; ++n) {
        auto bytes = base;
        // One to three bytes anywhere set to anything, the first keeping its mark.
        const int k = 1 + static_cast<int>(rng() % 3);
        for (int j = 0; j < k; ++j) {
            const std::size_t i = rng() % kCbnCardBytes;
            bytes[i] = static_cast<std::uint8_t>(rng() & 0xFF);
            bytes[0] |= 0x80;
        }
        INFO("case " << n);
        REQUIRE(check(bytes));
        bool all = true;
        for (std::size_t i = 0; i < bytes.size(); ++i) {
            all = all && byte_good(i, bytes[i]);
        }
        read += all ? 1 : 0;
    }
    CHECK(read > 100); // both outcomes met: cards read and cards refused
    CHECK(read < 2900);
}
