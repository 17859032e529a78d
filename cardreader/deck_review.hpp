// Reading a deck as a careful operator would before it goes into reader 134: the things the
// machine will stop on, or silently do wrong, that can be seen on the cards themselves.
//
//  - the shared-bank hazard: slow-downs and stop share the absolute storage banks 350-356
//    (Fig. 12), one bank of ten relays per digit, so the absolute comparer also conducts at
//    every number whose digits each stand on a closed relay (docs/design-rules.md rule 2);
//  - a check that is not |stop - previous stop| (the increment comparer 122'' disagrees);
//  - a card number that is not the previous one + 1 (the card-number check: no numeral);
//  - a start speed that does not match the slow-downs punched (3 - start speed of them);
//  - a slow-down the counters never pass before the stop;
//  - the sequence pattern replayed on stepping shaft 280: a position no running axis answers
//    (a sequence stall), an axis with no position, axes punched together at one position only;
//  - with the machine's dynamics: the speed an axis still has when it reaches its stop, and
//    the coast v^2 / 2a after it (a slow-down too close to its stop).
// Travel is counted as the counters count it: modulo 10 inches in the direction of motion, so
// a move across 9.999 / 0.000 is judged by its real length.
// Emulation note: this is a static reading of the cards, not a run; the machine itself
// (relaylogic/) is what decides what happens.
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

// Travel from `from` to `to` in the motion's direction, as the counters count it (0 .. 9.999:
// they wrap 9.999 -> 0.000 forward and 0.000 -> 9.999 in reverse).
Thousandths travel_in_motion(Thousandths from, Thousandths to, Motion motion);

// What the review needs of an axis's motor (from the machine profile; cardreader/ does not
// depend on axes/): speeds 1..3 of switch 236, the rate of change between them, the braking
// deceleration once switched off.
struct AxisDynamics {
    std::array<double, 3> speed_in_per_s{};
    double acceleration_in_per_s2 = 0;
    double braking_in_per_s2 = 0;
};

// The speed (in/s) an axis has when its counters reach the stop, starting from rest at `from`:
// it runs toward the start speed and toward each slower speed from each slow-down it passes,
// changing speed at the acceleration (v^2 changes by 2 a per inch).
double speed_at_stop(const AxisOrder& order, Thousandths from, const AxisDynamics& dynamics);

// How far past the stop it coasts once switched off there: v^2 / (2 braking).
double coast_in(const AxisOrder& order, Thousandths from, const AxisDynamics& dynamics);

struct ReviewNote {
    std::optional<Axis> axis; // none for whole-card notes (card number)
    std::string message;
    // The machine will stop on it (a card number out of order, a check that is not the
    // travel, a sequence stall in every order, a coast the next check will count), not
    // only a risk: `parsons check` then exits 3. The coast is a STOP on the card after it.
    bool stops = false;
    // Condition, sync and tap cards (additions): the card and column the note is about (0: this
    // card, no column), and whether it is a deck error (`run` refuses the deck; show and check
    // exit 2).
    std::int64_t card = 0;
    int column = 0;
    bool deck_error = false;
};

// Reviews a deck card by card, remembering where each axis stands (every axis starts the
// deck at the reference zero) and the previous card number.
class DeckReviewer {
public:
    DeckReviewer() = default;
    // With the machine's dynamics, the review also estimates each stop's coast.
    explicit DeckReviewer(const std::array<AxisDynamics, kAxisCount>& dynamics)
        : dynamics_(dynamics) {}

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
    // After the last card: a condition or sync card with no motion card after it.
    std::vector<ReviewNote> finish();

private:
    void review_sequence(const CardOrders& orders,
                         const std::array<std::optional<Thousandths>, kAxisCount>& travel,
                         std::vector<ReviewNote>& notes) const;

    std::vector<ReviewNote> condition_notes(const CardOrders& orders);

    std::optional<std::array<AxisDynamics, kAxisCount>> dynamics_;
    ConditionReview conditions_;
    SyncReview sync_;
    TapReview tap_;
    std::int64_t index_ = 0; // cards reviewed or skipped
    std::optional<int> previous_number_;
    // The coast the previous card's stop leaves on each axis (0 where none is warned of): the
    // counters count it, so this card's check disagrees.
    std::array<double, kAxisCount> coast_{};
    std::array<std::optional<Thousandths>, kAxisCount> position_{
        Thousandths{0}, Thousandths{0}, Thousandths{0}, Thousandths{0}, Thousandths{0}};
};

} // namespace parsons::cardreader
