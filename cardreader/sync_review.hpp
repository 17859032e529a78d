// Reading a deck's sync cards (an addition after EP 0436887, Mitsubishi; sync_card.hpp) as the
// operator would before the deck goes into reader 134, with the card and column of every
// finding. All are deck errors: `run` refuses the deck with exit 2 before any motion, `show` and
// `check` name them and exit 2.
//   - a sync card under a profile without press synchronisation (parsons-1952, parsons-safe);
//   - a sync card (not a loop) with no motion card after it: the deck ends, or a loop card
//     comes next; two sync cards before one motion card;
//   - speed sync on an axis the next motion card does not move (its check 0.000);
//   - a travel per pulse the sync drive cannot follow at the press's fastest pulse rate;
//   - a loop to a card number the deck does not hold before the loop card.
// Emulation note: a static reading of the cards, not a run; what the sync units do with the
// press is relaylogic's business.
#pragma once

#include "cardreader/orders.hpp"

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace parsons::cardreader {

// What the review needs of the press and the sync drive (from the machine profile; cardreader/
// does not depend on axes/).
struct PressLimits {
    double strokes_per_min = 2.0; // crank 21's nominal speed
    int pulses_per_degree = 4;    // detector 10
    // The press's fastest over its nominal: (1 + variation) x max(1, change_factor).
    double fastest_factor = 1.0;
    double drive_max_in_per_min = 5.4; // the fastest the sync drive follows

    // Detector 10's pulses a second with the crank at its fastest.
    double fastest_pulses_per_s() const {
        return strokes_per_min * 360.0 / 60.0 * pulses_per_degree * fastest_factor;
    }
    // The largest travel per pulse (hundred-thousandths of an inch) the drive can follow.
    int max_travel_per_pulse() const;
};

struct SyncFinding {
    std::int64_t card = 0; // deck position the finding is on
    int column = 0;        // the column to look at on that card
    std::optional<Axis> axis;
    std::string message;
};

class SyncReview {
public:
    // allowed: the profile has press synchronisation; profile: its name, for the message.
    explicit SyncReview(bool allowed = true, std::string profile = "parsons-extended",
                        PressLimits limits = {})
        : allowed_(allowed), profile_(std::move(profile)), limits_(limits) {}
    // The next readable card of the deck (index 1-based).
    std::vector<SyncFinding> card(std::int64_t index, const CardOrders& orders);
    // A card that could not be read: a sync card before it is not judged against it.
    void skip() { pending_.reset(); }
    // The end of the deck: a sync card with no motion card after it.
    std::vector<SyncFinding> finish();

private:
    void sync_card(std::int64_t index, const CardOrders& orders, std::vector<SyncFinding>& found);
    void loop_card(std::int64_t index, const CardOrders& orders, std::vector<SyncFinding>& found);
    void motion_card(std::int64_t index, const CardOrders& orders, std::vector<SyncFinding>& found);

    struct Pending {
        std::int64_t card = 0;
        SyncOrder order;
    };
    std::optional<Pending> pending_; // a sync card waiting for its motion card
    std::set<int> numbers_;          // the card numbers read so far
    bool allowed_;
    std::string profile_;
    PressLimits limits_;
};

} // namespace parsons::cardreader
