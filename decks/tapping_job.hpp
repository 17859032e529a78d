// The tapping job: a plate of tapped holes on the 1952 machine with the spindle synchronisation
// of EP 0360190 (Mitsubishi, claim 1), an addition (docs/tapping.md). Two taps of
// different pitch sit in two spindle heads 31 with different gear ratios (gear unit 30): the
// plate shows whether the NC computed the tool's speed with the right ratio (S x A), because a
// wrong ratio cuts a wrong pitch.
//
//   cross (Y)                                      vertical (the feed axis, sense reverse)
//     ^   row 2 (tool 2)  o <---- o <---- o             start  -+-  surface + clearance
//     |                                   ^                     |   (motor 27 runs up here)
//     |   row 1 (tool 1)  o ----> o ----> o           surface  -+-  the tap enters
//     |                                                         |   full threads
//     +-----------------------------------> table (X)   chamfer -+-  chamfer_revs x pitch
//   (0, 0): the head rises here, off the plate            bottom -+-  surface - thread depth
//
//   card 1          the head up to the start height (vertical, sequence position 1), then the
//                   cross slide and the table to the first hole (positions 4 and 5)
//   then per hole   a tap card (tool T of its row, the feed axis vertical, sense reverse, depth
//                   = clearance + thread depth, pitch = the head's tap, S), then a motion card
//                   to the next hole (table and cross slide; the head stays at the start height)
// Rows go back and forth (the shortest way); row r is tapped with tools[r mod the tools given].
//
// S per tool: the fastest motor 27 allows (max_rpm) at which the feed, pitch x S x A, stays
// within the follower drive's sync_drive.max_in_per_min (A: the head's ratio, the figure memory
// 12a holds). The clearance must let the motor run up to S before the tap's point reaches the
// surface: the feed follows the tool from the first turn, so the run-up's travel is checked.
//
// Every motion card is a whole 1952 card: all five axes punched, an axis that does not move with
// stop = where it stands and check 0; slow-downs by decks/move_planner.hpp.
// Emulation note: every axis starts a deck at its reference zero, so the vertical's zero lies
// below the plate (the head stands beside the plate at table and cross 0 until card 1 raises
// it); the tap's sense into the work is reverse (the counters count down as it goes in).
#pragma once

#include "axes/machine_profile.hpp"
#include "cardreader/orders.hpp"

#include <optional>
#include <string>
#include <vector>

namespace parsons::decks {

struct TappingOptions {
    int rows = 2;
    int holes_per_row = 3;
    // The first hole (table X, cross Y) and the spacing of the holes, inches as the counters read.
    // (The defaults let every move start fast: round figures such as 1.000 -> 2.000 would put
    // the shared-bank hazard on the way, and the planner would fall back to speed 3.)
    double first_x_in = 1.125;
    double first_y_in = 1.125;
    double spacing_x_in = 1.125;
    double spacing_y_in = 1.125;
    // On the vertical (the feed axis): the plate's surface, the clearance above it the tap starts
    // from, and the thread's depth below it.
    double surface_in = 1.250;
    double clearance_in = 0.100;
    double thread_depth_in = 0.500;
    std::vector<int> tools = {1, 2}; // the tool of each row, in turn
    std::optional<int> rpm;          // S for every hole; none: the fastest each tap allows
    double tolerance_percent = 5.0;  // the thread proof's tolerance on the pitch
    axes::RatioSource ratio_source = axes::RatioSource::transferred;
    // Rigid tapping (an addition): every tap card's feed waits for encoder 32's index (column 19).
    bool index_wait = false;
    // The faster retract (an addition): every tap card comes out at retract x S (column 20).
    int retract = 1;
    // Rigid peck tapping (an addition): every tap card pecks this deep, inches (columns 21-24;
    // 0: one pass).
    double peck_in = 0;
};

// One hole of the plate, in the order it is tapped.
struct TappingHole {
    int hole = 0;    // 1, 2, ...
    int row = 0;     // 1, 2, ...
    int card = 0;    // the number of its tap card
    double x_in = 0; // table
    double y_in = 0; // cross slide
    int tool = 0;    // the head that taps it
    double tap_pitch_in = 0;
    double head_ratio = 0; // that head's gear ratio A
    int rpm = 0;           // S
    double feed_in_per_min = 0;
    double surface_in = 0; // on the feed axis (vertical)
    double start_in = 0;   // surface + clearance
    double thread_depth_in = 0;
    double clearance_in = 0;
    double tolerance_percent = 0;
};

struct TappingDeck {
    std::vector<cardreader::CardOrders> cards;
    std::vector<TappingHole> holes;
};

// Throws JobError naming the option when the plate cannot be tapped (positions outside the
// counters, a tool no head holds or whose head holds a cutter, a speed over motor 27's or a feed
// over the drive's, a clearance too short for the run-up, a thread shorter than the chamfer) and
// PlanError as plan_move does.
TappingDeck make_tapping_deck(const TappingOptions& options, const axes::MachineProfile& profile);

// The profile the job runs under: `base` with spindle synchronisation on and the ratio's way
// into memory 12a of the options.
axes::MachineProfile tapping_profile(const TappingOptions& options, axes::MachineProfile base);

// "transferred", "stored"; and back (none for another word).
const char* ratio_source_name(axes::RatioSource source);
std::optional<axes::RatioSource> ratio_source_named(const std::string& name);

// What the thread proof needs, written beside the deck (DECK.job.json, "job": "tapping").
struct TappingJob {
    axes::RatioSource ratio_source = axes::RatioSource::transferred;
    cardreader::Axis feed_axis = cardreader::Axis::vertical;
    cardreader::Motion sense = cardreader::Motion::reverse; // into the work
    int rows = 0;
    int holes_per_row = 0;
    double clearance_in = 0;
    double thread_depth_in = 0;
    double tolerance_percent = 5.0;
    double chamfer_revs = 0; // the profile's, when the job was generated
    std::vector<TappingHole> holes;
    std::string profile_file; // DECK.profile.json
    std::int64_t deck_cards = 0;

    // The hole its tap card's number names, if the job has one.
    const TappingHole* hole_on_card(int number) const;
};

std::string tapping_job_to_json(const TappingJob& job);
// Throws JobError("KEY: what is wrong"); "job" must be "tapping".
TappingJob tapping_job_from_json(const std::string& text);
// Is this job-file text a tapping job?
bool is_tapping_job(const std::string& text);

} // namespace parsons::decks
