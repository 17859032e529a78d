// The property test over the accepted space (tests/property_test.cpp, docs/testing.md): a case
// drawn from a seed, the invariants the docs promise checked on it, and shrinking a failing
// case to the smallest profile and deck that still fail the same invariant.
#pragma once

#include "tests/random_decks.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace parsons::test {

struct PropertyCase {
    std::uint64_t seed = 0;
    // The profile file as a user writes it: "name" (the built-in profile it is applied over)
    // and only the keys that differ from that profile.
    nlohmann::json profile;
    std::vector<std::string> drawn;  // the keys drawn from their documented range
    std::string out_of_range;        // a key drawn just past its range ("": none)
    Case deck;                       // cards, faults, medium, double punches (deck.profile unused)
    bool deep = false;               // impulse level and a saved state's resume checked too
    std::int64_t interrupt_card = 0; // deep: the run is cut as this card (1-based) is fed
};

// The case of a seed: the deck recipe of tests/random_decks.hpp (every kind of card, medium
// and fault), its profile written as a partial file over a built-in one, then a few keys
// redrawn within their documented range (tests/property/key_ranges.hpp), now and then one
// just past it. One case in `deep_every` is deep.
PropertyCase draw_case(std::uint64_t seed, int deep_every);

struct Violation {
    std::string invariant; // its name (docs/testing.md, "The property test")
    std::string detail;
};

// Runs the case (in-process: the loader, `run`'s own run_deck, `check`'s predict_deck, the
// cabinet at both paces, a save and resume) and returns the first invariant it breaks.
std::optional<Violation> check_case(const PropertyCase& c);

// The smallest case it can reach that still breaks the same invariant: faults dropped, double
// punches dropped, cards dropped, profile keys reset to the built-in profile's, one at a time
// while the failure persists (at most `budget` trial runs).
PropertyCase shrink(const PropertyCase& c, const Violation& v, int budget);

// The seed, the profile file, the faults and the deck (as a listing, and its medium), enough
// to run it again with `parsons run`.
std::string describe(const PropertyCase& c);

// Writes the case's files (profile.json, the deck in its medium and as deck.csv, faults.txt)
// into `dir`.
void write_case(const PropertyCase& c, const std::string& dir);

} // namespace parsons::test
