// What a generated deck can hold, and the smallest sizes the machine can cut: the limits every
// generator (decks/*_job.hpp) checks before it does the work, so that a typo in an option is
// refused with the limit and its reason instead of computing for minutes or filling the disk
// (docs/airfoil-math.md, "What a deck can hold"). The CLI, the demo, the benchmark and the web
// page all generate through decks/, so they all meet the same refusals.
//
// Values too big for the counters (a chord whose path spans more than 9.999 in, a fixture
// screw past its travel) are refused by each generator where it lays the job out, with the
// span it would need; the limits here are the ones that do not depend on the layout.
#pragma once

#include "cardreader/deck_io.hpp"

#include <cstdint>
#include <string>

namespace parsons::decks {

// A card's number is four digits (columns 77-80 of every card kind): a deck of more than 9,999
// cards would repeat card numbers, so the card-number check could not tell a card lost from
// the card 10,000 places on, and an operator could not put a dropped deck back in order.
inline constexpr std::int64_t kMaxDeckCards = cardreader::kMaxDeckCards;

// The machine moves in impulses of 0.001 in (one step of a counter's lowest decade).
inline constexpr double kImpulseIn = 0.001;
// A cutter radius of less than one impulse is a point to the machine: the counters cannot
// offset the path from the surface by less than the smallest move they make.
inline constexpr double kLeastCutterRadiusIn = kImpulseIn;
// A section (a template's chord, a wing's root or tip chord) or a wing's span of less than a
// hundred impulses is no shape to the machine: each station is quantised to the impulse (up to
// 0.0007 in off), and a 12 %-thick section of 0.1 in chord is only 12 impulses thick.
inline constexpr double kLeastShapeIn = 100 * kImpulseIn;

// 10000003 -> "10,000,003": a count as a person reads it.
std::string count_text(std::int64_t count);

// Throws JobError when `cards` is more than kMaxDeckCards: "WHAT: the deck would need [at
// least ]N cards[ (DETAIL)], more than the 9,999 a deck can number (...)". WHAT names the
// option that asked for them, as the user typed it ("--stations 10000000").
void refuse_past_deck_limit(std::int64_t cards, const std::string& what, bool at_least = false,
                            const std::string& detail = {});

// Throws JobError naming `option` and `value` when the value is NaN or infinite.
void refuse_unless_finite(const std::string& option, double value);

// Throws JobError naming `option` and `value` unless it is a finite length of at least
// kLeastShapeIn (`what`: "chord", "span"): "--chord 1e-300: a chord under 0.100 in is no shape
// to the machine, which moves in impulses of 0.001 in: give at least 0.100 in, a hundred
// impulses".
void refuse_unless_shape(const std::string& option, double value_in, const std::string& what);

// Throws JobError naming `option` and `value` unless it is a finite cutter radius of at least
// kLeastCutterRadiusIn.
void refuse_unless_cutter(const std::string& option, double radius_in);

} // namespace parsons::decks
