// The listing: what a 1952 programmer handed the keypunch operator, one row per axis per card.
//
//   card,spindle,axis,motion,speed,slow1,slow2,stop,check,seq
//   1,0,table,+,1,8.785,8.885,8.985,8.985,12
//
// CSV with that header line; '#' starts a comment (whole line or after the fields); blank
// lines are ignored. A card is five consecutive rows, one per axis in any order, with the same
// card number and spindle. Numbers are inches with exactly three decimals, 0.000 .. 9.999;
// slow1 and slow2 may be blank; seq lists the punched sequence positions (1..5) as digits.
// The writer writes the rows of each card in table, cross, vertical, swivel, tilt order.
//
// A condition card (an addition after EP 0640901, docs/deck-formats.md) is one row per
// condition, 1..5 consecutive rows with the same card number and the word `if` where a motion
// row has its spindle:
//
//   card,if,event,axis,sense,position,action,parameter
//   3,if,1,cross,-,1.250,tool-change,2
//
// sense is + (forward), - (reverse) or * (either); parameter is blank where the action takes
// none (spindle, coolant), the tool number, the axis to hold (a name) or the lamp number.
//
// A sync card (an addition after EP 0436887, docs/deck-formats.md) is one row per order,
// consecutive rows with the same card number and the word `sync` (sync_listing.hpp):
//
//   3,sync,position,30
//   3,sync,speed,table,0.00417
//   12,sync,loop,1,100
//
// A tap card (an addition after EP 0360190, docs/deck-formats.md) is one row with the word `tap`
// (tap_listing.hpp):
//
//   12,tap,1,vertical,reverse,0.600,0.05000,240
#pragma once

#include "cardreader/deck_io.hpp"
#include "cardreader/orders.hpp"

#include <array>

namespace parsons::cardreader {

inline constexpr std::string_view kListingHeader =
    "card,spindle,axis,motion,speed,slow1,slow2,stop,check,seq";

struct ListedCard {
    CardOrders orders;
    std::int64_t first_line = 0;
    std::array<std::int64_t, kAxisCount> axis_line{}; // the line each axis row came from
};

class ListingReader {
public:
    ListingReader(std::istream& in, std::string file);
    // The next complete card, or nothing at the end. Throws DeckError naming file and line.
    std::optional<ListedCard> next();

private:
    std::optional<std::string> next_data_line();
    std::optional<ListedCard> next_condition_card(std::string first);
    std::optional<ListedCard> next_sync_card(std::string first);
    std::optional<ListedCard> next_tap_card(std::string first);
    std::optional<ListedCard> next_segment_card(std::string first);

    std::optional<std::string> pending_; // a line read ahead, the first of the next card

    std::istream& in_;
    std::string file_;
    std::int64_t line_ = 0;
    bool header_seen_ = false;
};

// One listing row for one axis of a card, without a newline.
std::string listing_row(const CardOrders& orders, Axis axis);
// One listing row for condition `index` of a condition card, without a newline.
std::string condition_row(const CardOrders& orders, int index);

std::unique_ptr<CardSource> make_listing_source(std::istream& in, std::string file,
                                                const CardLayout& layout);
std::unique_ptr<CardSink> make_listing_sink(std::ostream& out, std::string file,
                                            const CardLayout& layout);

} // namespace parsons::cardreader
