// Press synchronisation (an addition after EP 0436887): what a run reports of the press and the
// job's cycles (relaylogic/press/press_attachment.hpp).
#pragma once

#include "cardreader/orders.hpp"

#include <cstdint>
#include <optional>

namespace parsons::relaylogic {

// The sync drive asked for more than it follows: a synchronised axis's travel per pulse times
// the crank's speed past sync_drive.max_in_per_min (the drive runs at its top speed and the axis
// falls behind the crank for as long as that lasts: the lag then grows past the bound
// docs/press-sync.md gives). The first time it happened, and the most asked over the run.
struct DriveSaturation {
    cardreader::Axis axis = cardreader::Axis::table; // the first axis asked too much
    std::int64_t card = 0;                           // its motion card (deck position, 1-based)
    int number = -1;                                 // the card's number (-1: none punched)
    int speed_position = 1;                          // speed switch 236's position then
    double t_s = 0;                                  // machine time the drive was first asked
    double asked_in_per_min = 0;                     // what the crank asked then
    double crank_factor = 1;          // the crank's speed then over the press's rated speed
    double most_asked_in_per_min = 0; // the most any axis was asked, the whole run
    double drive_max_in_per_min = 0;  // sync_drive.max_in_per_min
};

// The feeder's interlock (press.feeder_hold_lag_in): how often and how long it held the press.
struct FeederHolds {
    double limit_in = 0;    // press.feeder_hold_lag_in
    std::int64_t holds = 0; // holds begun
    double held_s = 0;      // the press's machine time held, all holds
    double longest_s = 0;   // the longest hold
    bool holding = false;   // held at the end of the run
};

struct PressResult {
    int revolution = 0;               // the crank's revolution (1 = the first)
    double crank_angle_deg = 0;       // where crank 21 stood at the last detector edge taken
    int position_register = 0;        // register 14, detector pulses
    std::int64_t register_resets = 0; // switch 16A operated by sync cards' reset orders
    bool press_stopped = false;       // motor 22 stopped (the profile's stop)
    std::int64_t cycles = 0;          // how many times the job reached its loop card (M99)
    std::int64_t loop_backs = 0;      // how many times the reader went back
    // Time between two loop-backs: the job's cycle (none with fewer than two loop-backs).
    std::optional<double> mean_cycle_s;
    std::optional<double> shortest_cycle_s;
    std::optional<double> longest_cycle_s;
    double waited_s = 0; // machine time cards spent held by position reader 60
    // Processor 63's reference travel (F a pulse since the axis started) minus the axis's
    // counted travel, the largest at any reference block: on cards with position sync (the
    // loop takes it out) and on speed-only cards (nothing does).
    double max_lag_position_sync_in = 0;
    double max_lag_speed_only_in = 0;
    // The axis's counted travel past its reference travel, the largest at any block.
    double max_lead_position_sync_in = 0;
    double max_lead_speed_only_in = 0;
    // The drive could not follow the crank: when, which axis, how much it was asked.
    std::optional<DriveSaturation> drive_saturated;
    // The feeder's interlock, when the profile has one.
    std::optional<FeederHolds> feeder_interlock;
    // The deck used it (a sync card was read): the report and the summary show the press only
    // then (it turns under parsons-extended whatever the deck).
    bool used = false;
};

} // namespace parsons::relaylogic
