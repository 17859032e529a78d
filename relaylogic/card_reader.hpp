// Card reader 134 (Figs. 10, 13): how its first brush bank senses the digit columns of a card
// into the holding relays of the storage banks.
//
// A brush that finds a hole in row d of a digit column sends an impulse that picks relay d of
// the column's bank (Fig. 13). A 1952 reader has no check of its own on this
// (docs/design-rules.md rule 12): a digit column punched twice simply picks two relays, which
// then let the comparer conduct at more positions than the card meant. That is the faithful
// reading, in profile parsons-1952. Refusing such a card with a bad_punch stop is an addition of
// this emulator (profile option refuse_double_punch, on in parsons-safe). Every other bad punch
// (a stray hole, a blank digit inside a number, a speed or motion column the cabinet cannot act
// on) still stops the reader: that refusal, too, is an addition, and its message says so.
//
// Emulation note: with separate registers (an addition) each number has its own register and
// a double-punched digit is read at its lower row only.
#pragma once

#include "cardreader/layout.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace parsons::relaylogic {

// The four number fields of an axis whose digit columns pick storage relays.
inline constexpr std::size_t kNumberFields = 4; // slow-down 1, slow-down 2, stop, check

struct SensedCard {
    // The orders; a double-punched digit column reads as its lowest punched row.
    cardreader::DecodeResult decoded;
    // Per axis, per number field, per digit column (inches first): the relays (bit d = relay
    // d) its punches pick beyond the one the orders hold. All zero for a clean card.
    std::array<std::array<std::array<std::uint16_t, 4>, kNumberFields>, cardreader::kAxisCount>
        extra{};
    std::vector<int> double_columns; // the columns that pick two relays or more
};

// Senses a card. With refuse_double_punch, or when the card has a bad punch of another kind,
// decoded carries the bad punch.
SensedCard sense_card(const cardreader::Card& card, const cardreader::CardLayout& layout,
                      bool refuse_double_punch);

// The brushes' wiring for a motion card (Figs. 10, 13): what a hole in a column picks, as the
// exhibit's reader view draws it (web/reader.js). A digit column of a slow-down or the stop picks
// relay d of its absolute bank (350 inches .. 356 thousandths), of the check its incremental
// bank (324 inches .. 318 thousandths); the speed column's holes step speed switch 236 (the
// second bank of brushes), the motion column sets reversing control 214, the spindle column
// control 165, the card number goes to the card-number check, and a sequence mark (row 12)
// closes contact 226-234 of sequence switch 224. `picks` is the signal's scope.name as the
// cabinet defines it, "#" standing for the row's digit where each row picks its own relay.
// tests/card_reader_view_test.cpp holds it to the machine: every hole's relay picks, and
// nothing picks without a hole.
struct BrushWire {
    int column = 0;
    std::vector<int> rows; // the rows by their printed names (12, 11, 0 .. 9)
    std::string field;     // "table stop, inches"
    std::string picks;     // "table.absolute_storage_350.relay_#"
};
std::vector<BrushWire> brush_wiring(const cardreader::CardLayout& layout);

} // namespace parsons::relaylogic
