// Random decks for the tests that run one deck two ways and compare (fast-forward against
// impulse level in fast_forward_test.cpp, `parsons check` against `parsons run` in
// check_agreement_test.cpp): plausible rather than valid decks, on random profiles, media and
// faults.
//
// The decks: moves of every length, slow-downs well placed or too close, a wrong check or card
// number now and then, patterns that stall. The profiles vary speeds (some faster than the
// switches can step), stepping rate, acceleration, delay 258, screw error, travel limits, soft
// limits, separate registers, hundredths-only counting, the ribbon feed of Fig. 9, the readings
// of the patent and the additions, the measuring chain (backlash, lead error, instrument error and
// cam 160, screw-turn counting) and every kind of injected fault; each deck is fed on cards, on
// five cards a step or on perforated tape (col. 6).
#pragma once

#include "axes/machine_profile.hpp"
#include "cardreader/card.hpp"
#include "cardreader/deck_io.hpp"
#include "cardreader/orders.hpp"
#include "relaylogic/faults.hpp"

#include <random>
#include <tuple>
#include <vector>

namespace parsons::test {

struct Case {
    axes::MachineProfile profile = axes::default_profile();
    std::vector<cardreader::CardOrders> cards;
    std::vector<relaylogic::Fault> faults;
    // The medium the deck is fed on (Fig. 9 / col. 6): it is written to this format and read
    // back by its reader before the run, so the new readers stand in the random decks too.
    cardreader::DeckFormat medium = cardreader::DeckFormat::cbn;
    // Extra holes punched after encoding: (card, column, digit), a double punch.
    std::vector<std::tuple<std::size_t, int, int>> extra_punches;
};

// Condition cards come from their own generator `crng`, so that the decks of rng stay what they
// were before condition cards were added (and with them the stops, lost steps and faults).
// Press synchronisation likewise comes from `srng`: the press, the sync cards and the loop.
Case random_case(std::mt19937& rng, std::mt19937& crng, std::mt19937& srng, std::mt19937& trng);

// The case's cards as punched (fig8), its double punches made.
std::vector<cardreader::Card> punched_cards(const Case& c);

} // namespace parsons::test
