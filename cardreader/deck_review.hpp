// Reading a deck as a careful operator would before it goes into reader 134, for what can be
// seen on the cards themselves and is no prediction of the machine: advice on how the deck is
// written (a start speed that does not match the slow-downs punched, a slow-down that is not on
// the way to its stop), and the deck errors of the additions' cards (condition, sync and tap
// cards), which `run` itself refuses a deck for (cli/support/deck_files.hpp).
//
// What the machine will do with a deck (a check that disagrees, a card number out of order, a
// sequence stall, an equality in the shared banks, a coast the counters count) is found by
// running it: `parsons check` and `parsons show` run the deck on the emulator
// (cli/support/deck_prediction.hpp). No rule of the machine is written here a second time.
//
// Travel is counted as the counters count it: modulo 10 inches in the direction of motion, so
// a move across 9.999 / 0.000 is judged by its real length.
#pragma once

#include "cardreader/condition_review.hpp"
#include "cardreader/orders.hpp"
#include "cardreader/sync_review.hpp"
#include "cardreader/tap_review.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace parsons::cardreader {

// Every number the shared absolute banks compare equal at for this axis's slow-downs and
// stop, ascending (includes the punched numbers themselves).
std::vector<Thousandths> shared_bank_matches(const AxisOrder& order);

// The matches that are not punched numbers and that the counters pass on the way from
// `from` to the stop in the motion's direction (start included, stop excluded).
std::vector<Thousandths> spurious_matches_on_path(const AxisOrder& order, Thousandths from);
// Whether there is any (the generator's test of each placement it tries: it stops at the
// first).
bool spurious_match_on_path(const AxisOrder& order, Thousandths from);

// Travel from `from` to `to` in the motion's direction, as the counters count it (0 .. 9.999:
// they wrap 9.999 -> 0.000 forward and 0.000 -> 9.999 in reverse).
Thousandths travel_in_motion(Thousandths from, Thousandths to, Motion motion);

struct ReviewNote {
    std::optional<Axis> axis; // none for whole-card notes
    std::string message;
    // Condition, sync and tap cards (additions): the card and column the note is about (0: this
    // card, no column), and whether it is a deck error (`run` refuses the deck; show and check
    // exit 2).
    std::int64_t card = 0;
    int column = 0;
    bool deck_error = false;
};

// Reviews a deck card by card, remembering where each axis's stop number stands (every axis
// starts the deck at the reference zero). Every note that is not a deck error is advice.
class DeckReviewer {
public:
    DeckReviewer() = default;

    std::vector<ReviewNote> review(const CardOrders& orders);
    // A card that could not be read in full: its numbers are unknown, so the next card's
    // number and checks are not judged against a guess.
    void skip();
    // Condition cards: whether the profile has condition units (default: yes), its name and
    // the tools of its changer.
    void allow_conditions(bool allowed, std::string profile, std::vector<int> tools = {}) {
        conditions_ = ConditionReview(allowed, std::move(profile), std::move(tools));
    }
    // Sync cards: whether the profile has press synchronisation (default: yes), its name and
    // what its press and sync drive allow.
    void allow_sync(bool allowed, std::string profile, PressLimits limits = {}) {
        sync_ = SyncReview(allowed, std::move(profile), limits);
    }
    // Tap cards: whether the profile has spindle synchronisation (default: yes), its name and
    // what its spindle heads, motor 27 and follower drive allow.
    void allow_tap(bool allowed, std::string profile, SpindleLimits limits = {}) {
        tap_ = TapReview(allowed, std::move(profile), std::move(limits));
    }
    // Segment cards: whether the profile has contouring (default: yes) and its name.
    void allow_segments(bool allowed, std::string profile) {
        segments_allowed_ = allowed;
        segments_profile_ = std::move(profile);
    }
    // After the last card: a condition or sync card with no motion card after it.
    std::vector<ReviewNote> finish();

private:
    std::vector<ReviewNote> condition_notes(const CardOrders& orders);

    ConditionReview conditions_;
    SyncReview sync_;
    TapReview tap_;
    bool segments_allowed_ = true;
    std::string segments_profile_;
    std::int64_t index_ = 0; // cards reviewed or skipped
    std::array<std::optional<Thousandths>, kAxisCount> position_{
        Thousandths{0}, Thousandths{0}, Thousandths{0}, Thousandths{0}, Thousandths{0}};
};

} // namespace parsons::cardreader
