// What the contouring attachment (an addition after EP 0636958, Black & Decker) reports of a run:
// the segments, each junction's decision, the steps its motors lost and how far the path as cut
// left the programmed path (docs/contouring.md).
#pragma once

#include "relaylogic/contouring/interpolator.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace parsons::relaylogic {

struct JunctionRecord {
    int first = 0; // card numbers of the two segments
    int second = 0;
    JunctionKind kind = JunctionKind::none;
    double decided_s = -1;       // when the control cycle decided it (-1: it never could)
    double decided_at_in = 0;    // how far along the first segment the tool then was
    double difference = 0;       // the largest change of a motor's pulse rate at nominal, steps/s
    double at_s = 0;             // when the tool reached the junction
    double speed_in_per_min = 0; // the path speed there
    std::array<std::int64_t, 3> lost{}; // steps each motor lost there
};

struct ContouringResult {
    bool used = false; // a segment card was read
    int segments = 0;  // travelled (begun)
    std::vector<JunctionRecord> junctions;
    std::array<std::int64_t, 3> lost{}; // steps lost in all, X Y Z
    std::array<double, 3> offset_in{};  // where the rotor stands against the path, inches
    double largest_offset_in = 0;       // the farthest the tool was from the programmed path
    double motion_s = 0;                // from the first segment's start to the last one's end
    double first_start_s = -1;
    double last_end_s = -1;
    std::array<double, 3> position_in{}; // where the pulses put the axes at the end
    const char* policy = "rule";
};

} // namespace parsons::relaylogic
