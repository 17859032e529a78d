// The decks `parsons bench` writes (cli/bench_command.cpp): each axis shuttling between two
// positions, and the press job looped. Written through the keypunch (cardreader::encode), read
// back by `parsons run` as any deck is.
#pragma once

#include "cardreader/orders.hpp"

#include <array>
#include <string>

namespace parsons::cli::bench {

// Each axis shuttles between two positions (a, b) at its speed, with the patent's slow-downs
// and sequence (12, 12, 34, 34, 5). The first card starts every axis from zero.
struct Shuttle {
    int a, b, speed;
    cardreader::SequencePattern seq;
};

// Every axis moves, the table 9 inches at speed 1: millions of impulses.
inline constexpr std::array<Shuttle, 5> kLongMoves = {{{485, 9485, 1, 0b00011},
                                                       {1085, 2985, 2, 0b00011},
                                                       {500, 1500, 2, 0b01100},
                                                       {200, 400, 3, 0b01100},
                                                       {100, 200, 3, 0b10000}}};
// Only the table moves, 0.010 in a card at speed 3; the others stand (check 0).
inline constexpr std::array<Shuttle, 5> kShortMoves = {{{1000, 1010, 3, 0b00001},
                                                        {500, 500, 3, 0b00010},
                                                        {500, 500, 3, 0b00100},
                                                        {500, 500, 3, 0b01000},
                                                        {500, 500, 3, 0b10000}}};
// Only the table moves, 9.999 in a card (10 inches, near enough: the counters), at speed 3
// like the short moves, so that the two decks differ only in the length of the move.
inline constexpr std::array<Shuttle, 5> kTenInchMoves = {{{0, 9999, 3, 0b00001},
                                                          {500, 500, 3, 0b00010},
                                                          {500, 500, 3, 0b00100},
                                                          {500, 500, 3, 0b01000},
                                                          {500, 500, 3, 0b10000}}};

// `cards` cards of the shuttles, numbered from 1, to a .cbn file at `path`.
void write_deck(const std::string& path, int cards, const std::array<Shuttle, 5>& shuttles);

// The press job (an addition after EP 0436887), `cycles` times round its loop card: wait for
// crank 21 at 30 deg, the table out 0.600 in at 0.00125 in a detector pulse (speed sync), back
// at the three-speed motor's speed 1, loop. Each cycle is one revolution of the press.
void write_press_deck(const std::string& path, int cycles);

} // namespace parsons::cli::bench
