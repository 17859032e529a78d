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
#pragma once

#include "cardreader/deck_io.hpp"
#include "cardreader/orders.hpp"

#include <array>

namespace parsons::cardreader {

inline constexpr std::string_view kListingHeader =
    "card,spindle,axis,motion,speed,slow1,slow2,stop,check,seq";

struct ListedCard {
    CardOrders orders;
    long first_line = 0;
    std::array<long, kAxisCount> axis_line{}; // the line each axis row came from
};

class ListingReader {
public:
    ListingReader(std::istream& in, std::string file);
    // The next complete card, or nothing at the end. Throws DeckError naming file and line.
    std::optional<ListedCard> next();

private:
    std::optional<std::string> next_data_line();

    std::istream& in_;
    std::string file_;
    long line_ = 0;
    bool header_seen_ = false;
};

// One listing row for one axis of a card, without a newline.
std::string listing_row(const CardOrders& orders, Axis axis);

std::unique_ptr<CardSource> make_listing_source(std::istream& in, std::string file,
                                                const CardLayout& layout);
std::unique_ptr<CardSink> make_listing_sink(std::ostream& out, std::string file,
                                            const CardLayout& layout);

} // namespace parsons::cardreader
