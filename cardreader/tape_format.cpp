#include "cardreader/tape_format.hpp"

#include "cardreader/deck_error.hpp"

#include <fmt/format.h>

#include <bit>
#include <istream>
#include <ostream>

namespace parsons::cardreader {
namespace {

std::uint8_t data_frame(ColumnWord six) {
    const auto bits = static_cast<std::uint8_t>(six & kTapeDataBits);
    return std::popcount(static_cast<unsigned>(bits)) % 2 == 0 ? bits | kTapeCheckBit : bits;
}

// "frame 17, channel 7 (card 1, column 9, rows 12-3)"
std::string where(std::int64_t frame, int channel, std::int64_t card, int data_index) {
    const int column = data_index / 2 + 1;
    return fmt::format("frame {}, channel {} (card {}, column {}, rows {})", frame, channel, card,
                       column, data_index % 2 == 0 ? "12-3" : "4-9");
}

class TapeSource : public CardSource {
public:
    TapeSource(std::istream& in, std::string file) : in_(in), file_(std::move(file)) {}

    std::optional<Card> next() override {
        int c = skip_leader();
        if (c == std::char_traits<char>::eof()) {
            return std::nullopt;
        }
        ++card_;
        Card card;
        for (int i = 0; i < kTapeDataFrames; ++i) {
            if (i > 0) {
                c = next_frame();
            }
            if (c == std::char_traits<char>::eof()) {
                throw error(fmt::format("frame {}: the tape ends inside card {} after {} of its "
                                        "160 data frames",
                                        frame_ + 1, card_, i));
            }
            const auto f = static_cast<std::uint8_t>(c);
            if ((f & kTapeEndOfCard) != 0) {
                throw error(fmt::format("{}: end of card (channel 8) after only {} of the card's "
                                        "160 data frames: a frame is missing",
                                        where(frame_, 8, card_, i), i));
            }
            if (std::popcount(static_cast<unsigned>(f)) % 2 == 0) {
                throw error(fmt::format("{}: check channel wrong: frame {:#04x} has an even number "
                                        "of holes in channels 1-7 (odd parity){}",
                                        where(frame_, 7, card_, i), f,
                                        f == 0 ? "; blank tape inside a card" : ""));
            }
            const auto six = static_cast<ColumnWord>(f & kTapeDataBits);
            const int column = i / 2 + 1;
            card.set_column(column, i % 2 == 0
                                        ? static_cast<ColumnWord>(six << 6)
                                        : static_cast<ColumnWord>(card.column(column) | six));
        }
        c = next_frame();
        if (c == std::char_traits<char>::eof()) {
            throw error(fmt::format("frame {}: the tape ends where card {}'s end-of-card frame "
                                    "(channel 8) should be",
                                    frame_ + 1, card_));
        }
        if (static_cast<std::uint8_t>(c) != kTapeEndOfCard) {
            throw error(fmt::format("frame {}, channel 8: card {} has 160 data frames but frame "
                                    "{:#04x} is not the end of card (channel 8 alone)",
                                    frame_, card_, static_cast<std::uint8_t>(c)));
        }
        return card;
    }

private:
    int next_frame() {
        const int c = in_.get();
        if (in_.bad()) {
            throw DeckError::in_file(file_, "read error");
        }
        if (c != std::char_traits<char>::eof()) {
            ++frame_;
        }
        return c;
    }
    // Blank frames between cards are leader; a stray end-of-card frame there is refused.
    int skip_leader() {
        for (;;) {
            const int c = next_frame();
            if (c == std::char_traits<char>::eof() || c != 0) {
                if (c == kTapeEndOfCard) {
                    throw error(fmt::format("frame {}, channel 8: end of card where no card has "
                                            "begun",
                                            frame_));
                }
                return c;
            }
        }
    }
    DeckError error(const std::string& what) const { return DeckError::in_file(file_, what); }

    std::istream& in_;
    std::string file_;
    std::int64_t frame_ = 0; // frames read so far; the last one read is frame_ (1-based)
    std::int64_t card_ = 0;
};

class TapeSink : public CardSink {
public:
    TapeSink(std::ostream& out, std::string file) : out_(out), file_(std::move(file)) {}
    void write(const Card& card) override {
        const auto frames = tape_encode(card);
        out_.write(reinterpret_cast<const char*>(frames.data()),
                   static_cast<std::streamsize>(frames.size()));
        if (!out_) {
            throw DeckError::in_file(file_, "write error");
        }
    }

private:
    std::ostream& out_;
    std::string file_;
};

} // namespace

std::vector<std::uint8_t> tape_encode(const Card& card) {
    std::vector<std::uint8_t> frames;
    frames.reserve(kTapeDataFrames + 1);
    for (int c = 1; c <= kColumns; ++c) {
        const ColumnWord w = card.column(c);
        frames.push_back(data_frame(static_cast<ColumnWord>(w >> 6)));
        frames.push_back(data_frame(w));
    }
    frames.push_back(kTapeEndOfCard);
    return frames;
}

std::unique_ptr<CardSource> make_tape_source(std::istream& in, std::string file) {
    return std::make_unique<TapeSource>(in, std::move(file));
}

std::unique_ptr<CardSink> make_tape_sink(std::ostream& out, std::string file) {
    return std::make_unique<TapeSink>(out, std::move(file));
}

} // namespace parsons::cardreader
