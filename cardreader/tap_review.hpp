// Reading a deck's tap cards (an addition after EP 0360190, Mitsubishi; tap_card.hpp) as the
// operator would before the deck goes into reader 134, with the card and column of every
// finding. All are deck errors: `run` refuses the deck with exit 2 before any motion, `show` and
// `check` name them and exit 2.
//   - a tap card under a profile without spindle synchronisation (parsons-1952, parsons-safe):
//     column 76;
//   - a tool no spindle head 31 of the profile holds (PC 130 has nothing to put on): column 2;
//   - a tool whose head holds a cutter, not a tap (it would be fed as a tap): column 2;
//   - a speed S above spindle motor 27's fastest: column 15;
//   - a feed the follower drive cannot follow: the tool turns S x A rev/min (A: the ratio of
//     gear unit 30 with that tool's head, the figure memory 12a holds, claim 1), so the axis
//     must feed pitch x S x A in/min: column 10, with the most pitch it can be at that speed;
//   - a feed slower than the drive's least (kLeastTapFeedInPerMin): column 10, with the least
//     pitch at that speed;
//   - an index wait (rigid tapping, an addition) with a head whose ratio A is not 1/n: the
//     motor's index then never puts the tool at one angle: column 19;
//   - a retract multiple k (the faster retract, an addition) with k x S above motor 27's
//     fastest, or k x pitch x S x A above the drive's fastest: column 20.
// Emulation note: a static reading of the cards, not a run; what motor 27, PC 130 and the feed
// do with the card is relaylogic's business.
#pragma once

#include "cardreader/orders.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace parsons::cardreader {

// The slowest feed a tap card may order (the follower drive's least steady speed, in/min): a
// slower one would take hours a hole. The review refuses it on the card; the cabinet's own
// refusal (relaylogic/tapping/tapping_units.cpp) uses the same figure.
inline constexpr double kLeastTapFeedInPerMin = 0.5;

// What the review needs of the spindle and the follower drive (from the machine profile;
// cardreader/ does not depend on axes/). The defaults are the built-in profile's.
struct SpindleLimits {
    struct Head {
        int tool = 0;
        double ratio = 1.0; // tool revolutions per motor revolution (A)
        bool tap = true;    // it holds a tap (false: a cutter, which a tap card may not call)
    };
    std::vector<Head> heads = {{1, 0.25, true}, {2, 1.0 / 3.0, true}, {3, 0.5, false}};
    double max_rpm = 240.0;            // motor 27's fastest
    double drive_max_in_per_min = 5.4; // the fastest the follower drive follows

    const Head* head(int tool) const;
    // The feed (in/min) a tap of this pitch at this speed with this head needs: pitch x S x A.
    static double feed_in_per_min(int pitch, int rpm, double ratio);
    // The largest pitch (hundred-thousandths of an inch per tool revolution) the drive can
    // follow at `rpm` through `ratio`.
    int max_pitch(int rpm, double ratio) const;
    // The smallest pitch that feeds at least kLeastTapFeedInPerMin at `rpm` through `ratio`.
    static int min_pitch(int rpm, double ratio);
};

// Rigid tapping's index wait (an addition): encoder 32's index comes once a motor revolution,
// and the tool turns A of a revolution for each, so the tool stands at one angle at every n-th
// index only where A = 1/n. That n (1..1000), or none when 1/A is not a whole number.
std::optional<int> motor_revs_per_tool_rev(double ratio);

struct TapFinding {
    std::int64_t card = 0; // deck position the finding is on
    int column = 0;        // the column to look at on that card
    std::optional<Axis> axis;
    std::string message;
};

class TapReview {
public:
    // allowed: the profile has spindle synchronisation; profile: its name, for the message.
    explicit TapReview(bool allowed = true, std::string profile = "parsons-extended",
                       SpindleLimits limits = {})
        : allowed_(allowed), profile_(std::move(profile)), limits_(std::move(limits)) {}
    // The next readable card of the deck (index 1-based): findings on a tap card, none on any
    // other card.
    std::vector<TapFinding> card(std::int64_t index, const CardOrders& orders) const;

private:
    void retract_findings(std::int64_t index, const TapOrder& t, const SpindleLimits::Head* head,
                          std::vector<TapFinding>& found) const;

    bool allowed_;
    std::string profile_;
    SpindleLimits limits_;
};

} // namespace parsons::cardreader
