// Text card images (.txt, .crd, .card, .cards): one line a card, one character a column, in IBM 029
// (or 026) keypunch code, read as SIMH's card library reads text decks:
//   - a short line is padded with blanks (a blank line is a blank card);
//   - a tab advances to the next multiple of 8 columns (columns 9, 17, 25, ...);
//   - lower case is folded to upper case;
//   - a CR before the LF (CRLF line ends) is ignored;
//   - SIMH's lines that begin with '~': "~raw" and four octal digits a column (rows 12 .. 9,
//     as many columns as given) is a card of any punches; "~eor" is the end-of-record card
//     (rows 7-8-9 in column 1); "~eof", "~eoi" and a lone "~" end the deck: nothing after them
//     is read (the hopper's end; the 1952 machine has no use for a monitor's control cards).
// Written: a card of keypunch characters as its characters; the end-of-record card as ~eor;
// any other card, as SIMH's own punch writes it, as ~raw (so every card can be written as text,
// and reads back the same).
// Stricter than SIMH, because a deck must never be altered silently: a line longer than 80
// columns is an error (SIMH drops the rest), so is a character the keypunch has no key for, a
// ~raw card with a digit that is not octal, a word cut short or more than 80 words, and a '~'
// line that is none of SIMH's.
#pragma once

#include "cardreader/deck_io.hpp"

namespace parsons::cardreader {

// `warn` (may be empty) is told of an end-of-file mark (~eof, ~eoi, a lone ~) with cards after it.
std::unique_ptr<CardSource> make_text_source(std::istream& in, std::string file, KeypunchCode code,
                                             std::function<void(const std::string&)> warn = {});
std::unique_ptr<CardSink> make_text_sink(std::ostream& out, std::string file, KeypunchCode code);

} // namespace parsons::cardreader
