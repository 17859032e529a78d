// Injected faults (run --fault SPEC, repeatable): what the 1952 machine had to survive, and
// what its checks could and could not see. docs/faults.md tells each one's story.
//
//   drop-impulse:AXIS:N          contact set B of commutator 102 misses the axis's Nth impulse
//   stuck-relay:AXIS:BANK:D      holding relay D of storage bank BANK (350-356 absolute,
//                                318-324 incremental) is stuck closed: it never releases
//   dead-relay:AXIS:BANK:D       holding relay D of bank BANK never picks
//   skip-step:AXIS:SWITCH:N      stepping switch SWITCH (104-110 absolute, 310-316 increment)
//                                skips a position on its Nth step: the wiper moves two
//   feed-twice:N                 the reader feeds the deck's Nth card twice
//   swap-cards:N                 the deck's cards N and N+1 come in the other order
//   short-card:N                 the deck's Nth card is short: columns 61-80 never reach the
//                                brushes (the card number among them)
//   slip:AXIS:N:M                from the axis's Nth impulse the drive slips for M
//                                thousandths of screw travel (M <= 10000): the screw turns,
//                                the part stands. Instrument shaft 74 follows the part, so the
//                                patent's counters do not count it; counting screw turns (a
//                                departure) they do, and the part lags them
//   stale-ratio:N                spindle synchronisation (an addition after EP 0360190): at
//                                the Nth head exchange PC 130 sends no gear ratio; the NC
//                                computes the tool's speed with the old one
//   transfer-hang:N              the Nth gear ratio transfer never completes (the data never
//                                reaches the NC): transfer_timeout
//
// Impulses and steps count from 1 over the whole run; cards by their place in the deck.
#pragma once

#include "cardreader/deck_io.hpp"
#include "cardreader/orders.hpp"

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace parsons::relaylogic {

enum class FaultKind : std::uint8_t {
    drop_impulse,
    stuck_relay,
    dead_relay,
    skip_step,
    feed_twice,
    swap_cards,
    short_card,
    slip,
    stale_ratio,   // spindle sync: the Nth head exchange transfers no ratio
    transfer_hang, // spindle sync: the Nth ratio transfer never completes
};

struct Fault {
    FaultKind kind = FaultKind::drop_impulse;
    cardreader::Axis axis = cardreader::Axis::table;
    std::int64_t n = 1;     // the impulse, the step or the card (deck position), from 1
    int numeral = 0;        // the bank or the stepping switch
    int digit = 0;          // the relay of the bank
    std::int64_t count = 0; // slip: thousandths of screw travel the part does not follow
    std::string spec;
};

class FaultSpecError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Throws FaultSpecError with a message that names the spec and what is wrong with it.
Fault parse_fault(const std::string& spec);
Fault drop_impulse(cardreader::Axis axis, std::int64_t impulse);

// What a fault did in the run, for the report.
struct FaultEffect {
    std::string spec;
    bool acted = false;
    std::string effect; // one sentence; empty while it has not acted
};

// The card reader's feed with the deck faults (twice, swapped, short) applied.
class FaultyFeed : public cardreader::CardSource {
public:
    FaultyFeed(cardreader::CardSource& deck, std::vector<Fault> faults,
               std::vector<FaultEffect*> effects);
    std::optional<cardreader::Card> next() override;
    int cards_a_step() const override { return deck_.cards_a_step(); }

private:
    std::optional<cardreader::Card> pull();

    cardreader::CardSource& deck_;
    std::vector<Fault> faults_;
    std::vector<FaultEffect*> effects_;
    std::int64_t pulled_ = 0; // cards taken from the deck
    std::optional<cardreader::Card> again_;
};

} // namespace parsons::relaylogic
