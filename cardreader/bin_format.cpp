#include "cardreader/bin_format.hpp"

#include "cardreader/deck_error.hpp"

#include <fmt/format.h>

#include <istream>
#include <ostream>

namespace parsons::cardreader {
namespace {

class BinSource : public CardSource {
public:
    BinSource(std::istream& in, std::string file) : in_(in), file_(std::move(file)) {}

    std::optional<Card> next() override {
        std::array<std::uint8_t, kBinCardBytes> bytes{};
        in_.read(reinterpret_cast<char*>(bytes.data()), kBinCardBytes);
        const auto got = static_cast<std::int64_t>(in_.gcount());
        if (in_.bad()) {
            throw DeckError::in_file(file_, "read error");
        }
        if (got == 0) {
            return std::nullopt;
        }
        ++card_;
        const std::int64_t base = (card_ - 1) * kBinCardBytes;
        if (got < kBinCardBytes) {
            throw DeckError::at_card_byte(
                file_, card_, base + got,
                fmt::format("truncated card: the file ends after {} of its 160 bytes", got));
        }
        return bin_decode(bytes, file_, card_, base);
    }

private:
    std::istream& in_;
    std::string file_;
    std::int64_t card_ = 0;
};

class BinSink : public CardSink {
public:
    BinSink(std::ostream& out, std::string file) : out_(out), file_(std::move(file)) {}
    void write(const Card& card) override {
        auto bytes = bin_encode(card);
        out_.write(reinterpret_cast<const char*>(bytes.data()), kBinCardBytes);
        if (!out_) {
            throw DeckError::in_file(file_, "write error");
        }
    }

private:
    std::ostream& out_;
    std::string file_;
};

} // namespace

std::array<std::uint8_t, kBinCardBytes> bin_encode(const Card& card) {
    std::array<std::uint8_t, kBinCardBytes> bytes{};
    for (int c = 1; c <= kColumns; ++c) {
        const ColumnWord w = card.column(c);
        const auto i = static_cast<std::size_t>(2 * (c - 1));
        bytes.at(i) = static_cast<std::uint8_t>((w & 0x00F) << 4);
        bytes.at(i + 1) = static_cast<std::uint8_t>(w >> 4);
    }
    return bytes;
}

Card bin_decode(std::span<const std::uint8_t, kBinCardBytes> bytes, const std::string& file,
                std::int64_t card_index, std::int64_t byte_base) {
    Card card;
    for (int c = 1; c <= kColumns; ++c) {
        const auto i = static_cast<std::size_t>(2 * (c - 1));
        if ((bytes[i] & 0x0F) != 0) {
            throw DeckError::at_card_byte(
                file, card_index, byte_base + static_cast<std::int64_t>(i),
                fmt::format("bits 3..0 of column {}'s first byte are {:#04x}, not zero: not an "
                            "IBM 1130 binary card (column binary? use --format cbn)",
                            c, bytes[i] & 0x0F));
        }
        card.set_column(c, static_cast<ColumnWord>((bytes[i] >> 4) | (bytes[i + 1] << 4)));
    }
    return card;
}

std::unique_ptr<CardSource> make_bin_source(std::istream& in, std::string file) {
    return std::make_unique<BinSource>(in, std::move(file));
}

std::unique_ptr<CardSink> make_bin_sink(std::ostream& out, std::string file) {
    return std::make_unique<BinSink>(out, std::move(file));
}

} // namespace parsons::cardreader
