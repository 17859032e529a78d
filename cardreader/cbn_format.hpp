// Column-binary card files (.cbn) exactly as SIMH's card library (sim_card.c) writes them.
//
// 160 bytes a card, two bytes a column:
//   first byte  bits 5..0 = rows 12, 11, 0, 1, 2, 3
//   second byte bits 5..0 = rows  4,  5, 6, 7, 8, 9
//   bit 6 of every byte   = odd parity over bits 6..0
//   bit 7                 = set on the first byte of each card only
// A blank card is C0 followed by 159 bytes of 40.
#pragma once

#include "cardreader/deck_io.hpp"

#include <array>
#include <cstdint>
#include <span>

namespace parsons::cardreader {

inline constexpr int kCbnCardBytes = 160;

std::array<std::uint8_t, kCbnCardBytes> cbn_encode(const Card& card);

// Decodes one card's bytes; card_index (1-based) and byte_base (file offset of byte 0) are for
// the error message. Throws DeckError on a missing card mark, a mark inside the card, or a
// parity error.
Card cbn_decode(std::span<const std::uint8_t, kCbnCardBytes> bytes, const std::string& file,
                std::int64_t card_index, std::int64_t byte_base);

std::unique_ptr<CardSource> make_cbn_source(std::istream& in, std::string file);
std::unique_ptr<CardSink> make_cbn_sink(std::ostream& out, std::string file);

} // namespace parsons::cardreader
