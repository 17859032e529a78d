// A sync card (an addition after EP 0436887, Mitsubishi; sync_card.hpp) in the listing: one row
// per order, with the word `sync` where a motion row has its spindle, consecutive rows with the
// same card number forming one card (docs/deck-formats.md):
//
//   card,sync,position,ANGLE          3,sync,position,30          (G101 R30)
//   card,sync,speed,AXIS,TRAVEL       3,sync,speed,table,0.00417  (G95 F, inches per pulse)
//   card,sync,loop,TARGET,COUNT       12,sync,loop,1,100          (M99: back to card 1, 100 times)
//   card,sync,reset                   3,sync,reset                (switch 16A clears register 14)
#pragma once

#include "cardreader/orders.hpp"

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace parsons::cardreader {

// Is this listing line a sync row (its second field the word `sync`)?
bool is_sync_row(std::string_view text);

// Where each order of one sync card came from in the listing (0: not given yet).
struct SyncRowLines {
    std::int64_t position = 0;
    std::int64_t loop = 0;
    std::int64_t reset = 0;
    std::array<std::int64_t, kAxisCount> speed{};
};

// Reads one sync row into `order`, its card number into `number`; throws DeckError naming file
// and line for a bad row, or an order the card already has (`lines`, updated), or a loop
// together with synchronisation or a reset (a loop card stands alone).
void read_sync_row(std::string_view text, const std::string& file, std::int64_t line, int& number,
                   SyncOrder& order, SyncRowLines& lines);

// The listing rows of a sync card, without newlines: its reset row, its position row, its speed
// rows in axis order, its loop row.
std::vector<std::string> sync_rows(const CardOrders& orders);

} // namespace parsons::cardreader
