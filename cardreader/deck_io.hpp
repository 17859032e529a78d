// Decks as streams of cards: a reader yields one card at a time, a writer takes one at a time,
// so no deck has to fit in memory. The format comes from the file's extension or is named.
//
//   .cbn          column binary, as SIMH's sim_card.c reads and writes it     (cbn_format.hpp)
//   .bin          IBM 1130 / bitsavers binary, 12-bit row word << 4, LE     (bin_format.hpp)
//   .txt .crd .card .cards  80-column text card images in IBM 029 (or 026) code (text_format.hpp)
//   .csv .lst     the listing: one row per axis per card                     (listing_format.hpp)
//   .tape .ptp    eight-channel perforated tape, 161 frames a card            (tape_format.hpp)
//   .five         column binary, five per-axis cards a step (col. 6)        (five_card_format.hpp)
#pragma once

#include "cardreader/card.hpp"
#include "cardreader/hollerith.hpp"
#include "cardreader/layout.hpp"

#include <array>
#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace parsons::cardreader {

enum class DeckFormat : std::uint8_t { cbn, bin, text, listing, tape, five };
inline constexpr std::array<DeckFormat, 6> kDeckFormats = {DeckFormat::cbn,  DeckFormat::bin,
                                                           DeckFormat::text, DeckFormat::listing,
                                                           DeckFormat::tape, DeckFormat::five};

// A format whose cards follow one another with no feed gap (Fig. 9's ribbon; tape).
bool format_is_continuous(DeckFormat f);

std::string_view format_name(DeckFormat f);
std::optional<DeckFormat> format_named(std::string_view name);
// The file-name extensions of a format, without the dot, lower case ("txt", "crd", ...): the
// ones format_for_path knows it by (in any case).
std::span<const std::string_view> format_extensions(DeckFormat f);
std::optional<DeckFormat> format_for_path(std::string_view path);
// The format of a deck told from its first bytes (standard input has no extension):
// a card-start mark (bit 7 of the first byte) is column binary, a '#' or a "card," header a
// listing, printable characters text card images, and 16-bit words whose low four bits are
// all clear the .bin format. Nothing when the bytes fit none of them.
std::optional<DeckFormat> sniff_format(std::string_view head);
// How much of a deck's beginning the commands read to tell its format.
inline constexpr std::size_t kDeckHeadBytes = 4096;

// What a deck plainly is when its extension says another format (docs/deck-formats.md, "When
// the content outranks the extension"), told from its first bytes (at most kDeckHeadBytes) by
// signatures that do not guess: whole column-binary cards (a card-start mark on each card's
// first byte alone, every byte of odd parity), whole .bin cards that are neither text nor of
// odd parity, a tape card after its leader, the listing's header as the first line that is
// not a comment, printable lines of 80 columns at most (and, against a listing's extension, no
// comma). Nothing when the bytes fit the extension's own format, fit no format, or fit more
// than one: the extension's reader then reads them and names what is wrong. `why` says what
// in the bytes decided.
struct ContentFormat {
    DeckFormat format = DeckFormat::cbn;
    std::string why;
};
std::optional<ContentFormat> content_outranks(DeckFormat extension, std::string_view head);
// "a PNG image", "a PDF document" ...: what a common file that is no deck is, from its magic
// number, so that the error says so. Nothing when the bytes look like none of them.
std::optional<std::string> non_deck_kind(std::string_view head);

// Which deck this is, for a job description written beside it: the number of cards and a
// 64-bit FNV-1a hash of every column word in order (not for security: for a mix-up).
class DeckFingerprint {
public:
    void add(const Card& card);
    std::int64_t cards() const { return cards_; }
    std::string hex() const;

private:
    std::int64_t cards_ = 0;
    std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

// A card's number is four digits (columns 77-80): a deck holds at most 9,999 cards. Every
// reader open_card_source makes refuses the card past that (DeckError naming it), so that no
// input, however long (/dev/zero, an endless pipe), is read without bound.
inline constexpr std::int64_t kMaxDeckCards = 9999;

class CardSource {
public:
    virtual ~CardSource() = default;
    // The next card, or nothing at the end of the deck. Throws DeckError naming where.
    virtual std::optional<Card> next() = 0;
    // How many physical cards pass the reader for each card next() returns: one, or five for
    // five separate cards a step (col. 6), each of which takes a card cycle of its own.
    virtual int cards_a_step() const { return 1; }
};

class CardSink {
public:
    virtual ~CardSink() = default;
    // Throws DeckError when the format cannot hold the card (naming card and column).
    virtual void write(const Card& card) = 0;
};

struct DeckOptions {
    DeckFormat format = DeckFormat::cbn;
    std::string file_name;                     // for messages
    KeypunchCode code = KeypunchCode::ibm029;  // text card images
    const CardLayout* layout = &fig8_layout(); // listing <-> cards
    // The most cards (steps) a deck may hold. Only `parsons bench` raises it, to time the
    // engine on decks longer than any a user may feed (its card numbers repeat; the machine's
    // sequence check passes 9999 to 0000).
    std::int64_t max_cards = kMaxDeckCards;
    // Told of what in the deck is no error but would surprise its owner (a SIMH end-of-file
    // mark with cards after it): "FILE:LINE: what". Nothing is said when empty.
    std::function<void(const std::string&)> warn;
};

// A reader that also refuses an empty deck ("empty file: no cards").
std::unique_ptr<CardSource> open_card_source(std::istream& in, const DeckOptions& options);
std::unique_ptr<CardSink> open_card_sink(std::ostream& out, const DeckOptions& options);

} // namespace parsons::cardreader
