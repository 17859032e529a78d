// The GTKWave save file beside a VCD trace: `parsons run DECK --trace out.vcd` writes out.gtkw,
// and `gtkwave out.gtkw` opens the trace with every signal in view, one group per scope (the
// five axes, then the cabinet and any attachment), each axis's real position first as an
// analogue step wave, then its relays and switches in the order the VCD declares them, each
// named with its patent numeral.
//
// The save file is made from the list of variables the VCD writer declared (VcdWriter::
// declared()), never from a second list: a signal added to the machine is in both.
//
// The format is GTKWave's own (what its File > Write Save File writes, read back by its
// savefile.c): "[dumpfile]" and "[savefile]" name the trace and the save file, "@HEX" sets the
// display flags of the lines after it (the bits of TraceEntFlagBits in GTKWave's
// src/analyzer.h), a line "-NAME" is a blank or comment trace (a group's begin or end under
// the group flags), any other line a signal by its full name.
#pragma once

#include "outputs/traces/trace_outputs.hpp"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace parsons::cli {

// GTKWave's trace flags (analyzer.h, enum TraceEntFlagBits: the bit numbers in brackets).
namespace gtkwave_flag {
inline constexpr std::uint64_t kDecimal = 1ULL << 2;             // TR_DEC
inline constexpr std::uint64_t kBinary = 1ULL << 3;              // TR_BIN
inline constexpr std::uint64_t kRightJustify = 1ULL << 5;        // TR_RJUSTIFY
inline constexpr std::uint64_t kBlank = 1ULL << 9;               // TR_BLANK
inline constexpr std::uint64_t kAnalogStep = 1ULL << 15;         // TR_ANALOG_STEP
inline constexpr std::uint64_t kAnalogBlankStretch = 1ULL << 17; // TR_ANALOG_BLANK_STRETCH
inline constexpr std::uint64_t kReal = 1ULL << 18;               // TR_REAL
inline constexpr std::uint64_t kGroupBegin = 1ULL << 23;         // TR_GRP_BEGIN
inline constexpr std::uint64_t kGroupEnd = 1ULL << 24;           // TR_GRP_END

// A relay, lamp or motor (1 bit): 0/1 as a wave (@28).
inline constexpr std::uint64_t kWire = kBinary | kRightJustify;
// A stepping switch or counter (several bits): its position in decimal (@24).
inline constexpr std::uint64_t kSwitch = kDecimal | kRightJustify;
// A real position: a real value drawn as an analogue step wave (@48020).
inline constexpr std::uint64_t kPosition = kReal | kAnalogStep | kRightJustify;
// The blank lines under an analogue wave that make it taller (@20000; GTKWave drops the blank
// flag of a line that stretches an analogue wave).
inline constexpr std::uint64_t kTaller = kAnalogBlankStretch;
// A group's first and last line (@800200, @1000200).
inline constexpr std::uint64_t kBegin = kGroupBegin | kBlank;
inline constexpr std::uint64_t kEnd = kGroupEnd | kBlank;
} // namespace gtkwave_flag

// How many blank lines stretch each position's wave: four rows tall in all.
inline constexpr int kGtkwavePositionStretch = 3;

// The save file's text. `dumpfile` and `savefile` are the names of the trace and of the save
// file as they sit side by side (no folder): GTKWave finds the trace beside the save file
// wherever the pair is and whatever the current directory (it reads [dumpfile] relative to the
// folder of [savefile], and puts that folder where it found the save file), so the bytes do
// not depend on where the run was made.
std::string gtkwave_save_file(const std::vector<VcdVariable>& declared, std::string_view dumpfile,
                              std::string_view savefile);

// The name GTKWave shows a variable by: "table.position_in", "table.motor_38",
// "table.absolute_counter_110[3:0]".
std::string gtkwave_signal_name(const VcdVariable& v);

} // namespace parsons::cli
