// Text card images (.txt, .crd, .card, .cards): one line a card, one character a column, in IBM 029
// (or 026) keypunch code, read as SIMH's card library reads text decks:
//   - a short line is padded with blanks (a blank line is a blank card);
//   - a tab advances to the next multiple of 8 columns (columns 9, 17, 25, ...);
//   - lower case is folded to upper case;
//   - a CR before the LF (CRLF line ends) is ignored.
// Stricter than SIMH, because a deck must never be altered silently: a line longer than 80
// columns is an error (SIMH drops the rest), so is a character the keypunch has no key for,
// and a card whose column holds holes no key makes cannot be written as text at all.
#pragma once

#include "cardreader/deck_io.hpp"

namespace parsons::cardreader {

std::unique_ptr<CardSource> make_text_source(std::istream& in, std::string file, KeypunchCode code);
std::unique_ptr<CardSink> make_text_sink(std::ostream& out, std::string file, KeypunchCode code);

} // namespace parsons::cardreader
