// Press synchronisation (an addition after EP 0436887): what a run reports of the press and the
// job's cycles (relaylogic/press/press_attachment.hpp).
#pragma once

#include <cstdint>
#include <optional>

namespace parsons::relaylogic {

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
    // The deck used it (a sync card was read): the report and the summary show the press only
    // then (it turns under parsons-extended whatever the deck).
    bool used = false;
};

} // namespace parsons::relaylogic
