// What the machine will do with a deck, found by running it: the deck goes through the emulator
// itself (relaylogic::ControlCabinet, fast-forward), with the profile, soft limits, feed and
// faults `parsons run` would use, and a MachineStory listening (outputs/report/machine_story.hpp).
// `check` and `show` predict from this run and from nothing else: the machine's rules are
// written once, in relaylogic/ and axes/ (docs/check.md).
#pragma once

#include "cli/support/deck_files.hpp"
#include "outputs/report/machine_story.hpp"

#include "relaylogic/faults.hpp"
#include "relaylogic/run_result.hpp"

#include <string>
#include <vector>

namespace parsons::cli {

struct PredictionRequest {
    std::string input;
    DeckFlags deck;
    std::string profile;
    std::vector<std::string> limits;
    std::vector<std::string> faults; // --fault specs (docs/faults.md)
    std::string feed;                // --feed cards|ribbon, or empty
};

struct Prediction {
    axes::MachineProfile profile; // as applied: --limit and --feed included
    std::string format;           // the deck's format and layout, by name
    std::string layout;
    relaylogic::RunResult result;
    std::vector<std::string> chain; // the relay events that led to the stop (empty: none)
    std::vector<StoryNote> notes;   // what the run did that the deck's author should know
};

// --fault specs, each parsed; a bad one is a DeckError naming it.
std::vector<relaylogic::Fault> parse_faults(const std::vector<std::string>& specs);

// Runs the deck (`deck`, opened from request.input and request.deck), then rewinds it for the
// caller to read again. A deck `run` refuses (a condition, sync or tap card's deck error, a card
// that cannot be read) throws the DeckError `run` would give.
Prediction predict_deck(const PredictionRequest& request, InputDeck& deck);

} // namespace parsons::cli
