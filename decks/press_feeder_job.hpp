// The press-feeder job: the workpiece transfer of EP 0436887 (Mitsubishi, Fig. 3
// and Fig. 4) on the 1952 machine, an addition (press synchronisation, docs/press-sync.md).
// The feeder's arm is the table (X, toward the press) and the cross slide (Y, along the
// conveyors); the press stands beside the machine (axes/press.hpp).
//
//            carry-out conveyor  Y = carry_out_y    .------------.
//                   ^                               |  die zone  |  X > zone_edge_x
//   press line      |  Y = press_y   retracted ---->|-- insert   |
//                   v                               |            |
//            carry-in conveyor   Y = carry_in_y     '------------'
//
//   cards 1, 2   SYNC speed (both axes); HOME: table to the retracted X, cross slide to the
//                press line
//   cards 3, 4   SYNC speed (Y); CARRY-IN (Fig. 3 N01): cross slide to the carry-in conveyor
//   cards 5, 6   SYNC speed (Y); cross slide back to the press line (the Y half of N03)
//   cards 7, 8   SYNC position R = insert angle (30) + speed F; INSERT: table into the zone
//   cards 9, 10  SYNC speed F only (N05); RETRACT: table back out of the zone
//   cards 11, 12 SYNC position R = take-out angle (190) + speed F (N06); TAKE-OUT
//   cards 13, 14 SYNC speed F only; CARRY-OUT: table out (the X half of N08)
//   cards 15, 16 SYNC speed (Y); cross slide to the carry-out conveyor (the Y half of N08)
//   cards 17, 18 SYNC speed (Y); RETURN (N10): cross slide back to the press line
//   card 19      LOOP (N11, M99): back to card 3, cycles - 1 times
// Every move follows the press: the moves other than the table's four at the 1952 speed they
// start on, at the press's rated speed (docs/press-sync.md).
// Fig. 3's joint X-Y travels are split: in a 1952 card two axes running together must be
// punched so that the one that stops first is known (col. 11's sequence).
// Clamp and unclamp (M15, M16) take no time of their own here: the card cycle between two
// moves stands for them.
//
// F per move: the travel over the detector pulses of the crank degrees the move is given
// (F = distance / (degrees x pulses_per_degree)), rounded to 0.00001 in; every follower speed
// is checked against the sync drive's maximum and the counters' stepping rate.
//
// The speed-only variant (the seed's Fig. 7, "conventional"): the same cards with the position
// sync taken off the sync cards. Its timing (the press's start angle, the degrees given to the
// retract and the carry-out) is found by running it (cli/press_feeder.cpp) so that at the
// nominal press speed its feeder crosses the zone edge at the crank angles the position deck
// crosses it at; the generator here takes those degrees as options.
//
// Emulation note: the cross slide has one slow-down field (layout fig8), so it cannot start on
// speed 1 and still stop on speed 3: it is never speed-synchronised (the seed's F covers the
// X-Y path); it runs at its fixed speeds on cards of its own.
#pragma once

#include "axes/machine_profile.hpp"
#include "cardreader/orders.hpp"

#include <string>
#include <vector>

namespace parsons::decks {

struct PressFeederOptions {
    // The feeder (inches, as the counters read).
    double retracted_x_in = 0.400;
    double zone_edge_x_in = 0.700; // the die zone begins past this X
    double insert_x_in = 0.800;
    double carry_in_y_in = 0.200;
    double press_y_in = 0.300;
    double carry_out_y_in = 0.400;
    // The press: die 20 is clear of the feeder at this height above bottom dead centre.
    double safe_height_in = 0.25;
    double strokes_per_min = 1.2; // at 1 the speed-only timing crawls under the drive's least speed
    double start_angle_deg = 0.0; // crank 21 when the run starts (the speed-only timing)
    int cycles = 4;               // passes of the cycle (cards 3-19)
    // The crank degrees each speed-synchronised move is given.
    int insert_angle_deg = 30; // R of the insert's sync card
    double insert_deg = 50;
    double retract_deg = 40;
    int takeout_angle_deg = 190; // R of the take-out's sync card
    double takeout_deg = 50;
    double carry_out_deg = 40;
    bool speed_only = false;
};

// One speed-synchronised move: its card (index into cards), F and the follower's speed at the
// nominal press speed.
struct SyncedMove {
    std::string name; // insert, retract, take-out, carry-out
    std::size_t card = 0;
    double degrees = 0;
    int travel_per_pulse = 0; // 0.00001 in
    double speed_in_per_min = 0;
};

struct PressFeederDeck {
    std::vector<cardreader::CardOrders> cards;
    std::vector<SyncedMove> moves;
    int cycle_card = 2; // the number of the first card of the cycle (the loop's target)
};

// Throws JobError naming the option when the geometry cannot make the job (positions out of
// order or out of the counters' range, a follower speed over the drive's maximum or the
// counters' stepping rate, a move too short to be speed-synchronised) and PlanError as
// plan_move does.
PressFeederDeck make_press_feeder_deck(const PressFeederOptions& options,
                                       const axes::MachineProfile& profile);

// The profile the job runs under: `base` with press synchronisation on and the press of the
// options (strokes a minute, start angle).
axes::MachineProfile press_feeder_profile(const PressFeederOptions& options,
                                          axes::MachineProfile base);

// What the proof needs, written beside the deck (DECK.job.json, "job": "press-feeder").
struct PressFeederJob {
    std::string variant = "position+speed"; // or "speed-only"
    PressFeederOptions options;
    int cycle_card = 2;
    std::string profile_file; // DECK.profile.json, the profile to run it under
    std::int64_t deck_cards = 0;
};

std::string press_job_to_json(const PressFeederJob& job);
// Throws JobError("KEY: what is wrong"); "job" must be "press-feeder".
PressFeederJob press_job_from_json(const std::string& text);
// Is this job-file text a press-feeder job?
bool is_press_job(const std::string& text);

} // namespace parsons::decks
