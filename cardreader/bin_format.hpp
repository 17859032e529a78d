// Binary card files (.bin): the IBM 1130 / bitsavers layout that SIMH also reads.
//
// 160 bytes a card, two bytes a column: the 12-bit row word (row 12 in bit 11 .. row 9 in
// bit 0) shifted left by 4 and stored little-endian:
//   first byte  = (word & 0x00F) << 4    (rows 6, 7, 8, 9 in bits 7..4; bits 3..0 zero)
//   second byte =  word >> 4             (rows 12, 11, 0, 1, 2, 3, 4, 5 in bits 7..0)
// No card mark and no parity: the only check is that bits 3..0 of every first byte are zero.
#pragma once

#include "cardreader/deck_io.hpp"

#include <array>
#include <cstdint>
#include <span>

namespace parsons::cardreader {

inline constexpr int kBinCardBytes = 160;

std::array<std::uint8_t, kBinCardBytes> bin_encode(const Card& card);
Card bin_decode(std::span<const std::uint8_t, kBinCardBytes> bytes, const std::string& file,
                std::int64_t card_index, std::int64_t byte_base);

std::unique_ptr<CardSource> make_bin_source(std::istream& in, std::string file);
std::unique_ptr<CardSink> make_bin_sink(std::ostream& out, std::string file);

} // namespace parsons::cardreader
