// Perforated tape (.tape, .ptp): the third medium of the patent, col. 6 ("the machine tool could
// be controlled from perforated tape instead of punched cards"). The patent gives no code for
// the tape; this layout is the emulator's choice (an addition), written down in
// docs/deck-formats.md with the reasons.
//
// Eight-channel tape, one byte a frame, channel n in bit n-1; the sprocket hole (between
// channels 3 and 4) is in every frame and is not stored. A card is 161 frames:
//
//   frames 1..160   two frames a column, column 1 first: rows 12 11 0 1 2 3 of the column in
//                   channels 6..1, then rows 4 5 6 7 8 9 in channels 6..1; channel 7 is the
//                   check channel (odd parity over channels 1..7, so a data frame is never
//                   blank); channel 8 is not punched.
//   frame 161       end of card: channel 8 alone (as EIA RS-227's end-of-block).
//
// Blank frames (sprocket only) are leader and trailer: allowed before a card begins, never
// inside one. Every error names the frame (1 = the first byte of the file) and the channel.
#pragma once

#include "cardreader/deck_io.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace parsons::cardreader {

inline constexpr int kTapeDataFrames = 160;
inline constexpr std::uint8_t kTapeEndOfCard = 0x80; // channel 8
inline constexpr std::uint8_t kTapeCheckBit = 0x40;  // channel 7
inline constexpr std::uint8_t kTapeDataBits = 0x3F;  // channels 1..6

// The 161 frames of one card (data frames, then the end-of-card frame).
std::vector<std::uint8_t> tape_encode(const Card& card);

std::unique_ptr<CardSource> make_tape_source(std::istream& in, std::string file);
std::unique_ptr<CardSink> make_tape_sink(std::ostream& out, std::string file);

} // namespace parsons::cardreader
