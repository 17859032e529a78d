#include "cardreader/cbn_format.hpp"

#include "cardreader/deck_error.hpp"

#include <fmt/format.h>

#include <bit>
#include <cstring>
#include <istream>
#include <ostream>

namespace parsons::cardreader {
namespace {

constexpr std::uint8_t kCardMark = 0x80;
constexpr std::uint8_t kParityBit = 0x40;
constexpr std::uint8_t kSixBits = 0x3F;

// Adds bit 6 so that bits 6..0 hold an odd number of ones.
std::uint8_t with_odd_parity(std::uint8_t six) {
    return std::popcount(static_cast<unsigned>(six)) % 2 == 0 ? six | kParityBit : six;
}

constexpr bool parity_ok(std::uint8_t byte) {
    return std::popcount(static_cast<unsigned>(byte & 0x7F)) % 2 == 1;
}

// Whether every byte of a card may stand there: the first with its card-start mark taken off,
// no byte with a card-start mark (bit 7), and each byte's bits 6..0 an odd number of ones.
// Eight bytes at a time, each byte's parity folded into its own bit 0, so that reading a good
// card costs a few operations a word (test "Column binary: a card is refused exactly when one
// of its bytes breaks the rule", against the rule byte by byte).
bool all_good_bytes(std::span<const std::uint8_t, kCbnCardBytes> bytes) {
    constexpr std::uint64_t kEach = 0x0101010101010101ULL;
    static_assert(kCbnCardBytes % 8 == 0);
    std::uint64_t marks = 0;
    std::uint64_t parity = kEach;
    for (std::size_t i = 0; i < kCbnCardBytes; i += 8) {
        std::array<std::uint8_t, 8> eight{};
        std::memcpy(eight.data(), bytes.data() + i, eight.size());
        if (i == 0) {
            eight[0] = static_cast<std::uint8_t>(eight[0] & ~kCardMark);
        }
        std::uint64_t x = 0;
        std::memcpy(&x, eight.data(), eight.size()); // byte order does not matter: bytes stay apart
        marks |= x & (kEach * kCardMark);
        std::uint64_t p = x & (kEach * 0x7F);
        p ^= (p >> 4) & (kEach * 0x0F);
        p ^= (p >> 2) & (kEach * 0x03);
        p ^= (p >> 1) & kEach;
        parity &= p;
    }
    return marks == 0 && (parity & kEach) == kEach;
}

class CbnSource : public CardSource {
public:
    CbnSource(std::istream& in, std::string file) : in_(in), file_(std::move(file)) {}

    std::optional<Card> next() override {
        std::array<std::uint8_t, kCbnCardBytes> bytes{};
        in_.read(reinterpret_cast<char*>(bytes.data()), kCbnCardBytes);
        const auto got = static_cast<std::int64_t>(in_.gcount());
        if (in_.bad()) {
            throw DeckError::in_file(file_, "read error");
        }
        if (got == 0) {
            return std::nullopt;
        }
        ++card_;
        const std::int64_t base = (card_ - 1) * kCbnCardBytes;
        if (got < kCbnCardBytes) {
            throw DeckError::at_card_byte(
                file_, card_, base + got,
                fmt::format("truncated card: the file ends after {} of its 160 bytes", got));
        }
        return cbn_decode(bytes, file_, card_, base);
    }

private:
    std::istream& in_;
    std::string file_;
    std::int64_t card_ = 0;
};

class CbnSink : public CardSink {
public:
    CbnSink(std::ostream& out, std::string file) : out_(out), file_(std::move(file)) {}
    void write(const Card& card) override {
        auto bytes = cbn_encode(card);
        out_.write(reinterpret_cast<const char*>(bytes.data()), kCbnCardBytes);
        if (!out_) {
            throw DeckError::in_file(file_, "write error");
        }
    }

private:
    std::ostream& out_;
    std::string file_;
};

} // namespace

std::array<std::uint8_t, kCbnCardBytes> cbn_encode(const Card& card) {
    std::array<std::uint8_t, kCbnCardBytes> bytes{};
    for (int c = 1; c <= kColumns; ++c) {
        const ColumnWord w = card.column(c);
        const auto i = static_cast<std::size_t>(2 * (c - 1));
        bytes.at(i) = with_odd_parity(static_cast<std::uint8_t>((w >> 6) & kSixBits));
        bytes.at(i + 1) = with_odd_parity(static_cast<std::uint8_t>(w & kSixBits));
    }
    bytes[0] |= kCardMark;
    return bytes;
}

Card cbn_decode(std::span<const std::uint8_t, kCbnCardBytes> bytes, const std::string& file,
                std::int64_t card_index, std::int64_t byte_base) {
    if ((bytes[0] & kCardMark) == 0) {
        throw DeckError::at_card_byte(
            file, card_index, byte_base,
            "no card-start mark: bit 7 of the first byte of every card must be set");
    }
    const bool good = all_good_bytes(bytes);
    // A bad byte: the first one is named (only a card that has one is read byte by byte).
    for (std::size_t i = 0; !good && i < bytes.size(); ++i) {
        const std::uint8_t b = i == 0 ? static_cast<std::uint8_t>(bytes[i] & ~kCardMark) : bytes[i];
        const int column = static_cast<int>(i / 2) + 1;
        if ((b & kCardMark) != 0) {
            throw DeckError::at_card_byte(
                file, card_index, byte_base + static_cast<std::int64_t>(i),
                fmt::format("card-start mark (bit 7) inside the card at column {}: the card is "
                            "short or the file is not column binary",
                            column));
        }
        if (!parity_ok(b)) {
            throw DeckError::at_card_byte(
                file, card_index, byte_base + static_cast<std::int64_t>(i),
                fmt::format("parity error in column {} (byte {:#04x} has even parity; column "
                            "binary uses odd parity)",
                            column, bytes[i]));
        }
    }
    std::array<ColumnWord, kColumns> words{};
    for (std::size_t column = 0; column < words.size(); ++column) {
        words[column] = static_cast<ColumnWord>((bytes[2 * column] & kSixBits) << 6 |
                                                (bytes[2 * column + 1] & kSixBits));
    }
    return Card(words);
}

std::unique_ptr<CardSource> make_cbn_source(std::istream& in, std::string file) {
    return std::make_unique<CbnSource>(in, std::move(file));
}

std::unique_ptr<CardSink> make_cbn_sink(std::ostream& out, std::string file) {
    return std::make_unique<CbnSink>(out, std::move(file));
}

} // namespace parsons::cardreader
