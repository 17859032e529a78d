// Five separate cards a step, one for each lead screw (col. 6: "Five separate cards, one for
// each lead screw, may be employed if desired"). The patent gives no layout for such a card;
// this one is the emulator's (documented in docs/card-layout.md, "Five cards a step"):
//
//   column 1       spindle direction (165), the same on all five cards of a step
//   columns 2..    the axis's own columns of the one-card layout, in the same order
//                  (table: fig8 columns 2-19 -> 2-19; cross: 20-33 -> 2-15; ...)
//   column 76      axis mark: one punch, row 1 table, 2 cross, 3 vertical, 4 swivel, 5 tilt
//   columns 77-80  the step's card number, the same on all five cards
//
// The file is column binary (.cbn encoding), five cards a step, in any order within the
// step. The reader reassembles the five into the one card of the layout, so the cabinet
// senses the same holes either way; the writer splits a card into five. The source says it
// passes five cards a step (cards_a_step()), and the cabinet gives each a card cycle, so the
// motors start after the fifth: why the patent prefers one card "from the standpoint of
// economy and speed" (ControlCabinet::feed, relaylogic/control_cabinet_reader.cpp).
#pragma once

#include "cardreader/deck_io.hpp"

#include <array>

namespace parsons::cardreader {

inline constexpr int kAxisMarkColumn = 76;

// The five per-axis cards of one card, table first; the error names the column the five-card
// layout has no room for.
struct FiveCards {
    std::array<Card, kAxisCount> cards{};
    std::optional<std::string> error;
};
FiveCards split_into_five(const Card& card, const CardLayout& layout);

std::unique_ptr<CardSource> make_five_card_source(std::istream& in, std::string file,
                                                  const CardLayout& layout);
std::unique_ptr<CardSink> make_five_card_sink(std::ostream& out, std::string file,
                                              const CardLayout& layout);

} // namespace parsons::cardreader
