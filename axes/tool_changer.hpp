// The tool changer: an addition after EP 0640901 (Siemens), whose example action is
// a tool change begun before the machine reaches the exact change position (claims 5, 6).
//
// The 1952 machine had one cutter, changed by hand between jobs. Here a changer holds the
// profile's tools (number and cutter radius); a tool change takes the profile's
// tool_change_s, and the new tool is in the spindle when it is acknowledged. The cut proof
// sweeps each stretch of the path with the radius of the tool that cut it.
//
// Emulation note: the changer's arm, magazine and drawbar are one timed action; the cutter
// is not at risk while the axes move during the change (the seed's point: the change runs
// while the tool travels to the change position).
#pragma once

#include "axes/machine_profile.hpp"

#include <algorithm>

namespace parsons::axes {

class ToolChanger {
public:
    explicit ToolChanger(int first_tool = 1) : in_spindle_(first_tool) {}
    // Starts a change to `tool` at time t; returns when the new tool is in the spindle.
    double change(int tool, double t, const ActionTimes& times) {
        changing_to_ = tool;
        return t + times.tool_change_s;
    }
    // The change started last is complete (its acknowledgement).
    void complete() {
        if (changing_to_ != 0) {
            in_spindle_ = changing_to_;
            changing_to_ = 0;
        }
    }
    int in_spindle() const { return in_spindle_; }
    int changing_to() const { return changing_to_; } // 0 when no change is under way
    void restore(int in_spindle, int changing_to) {
        in_spindle_ = in_spindle;
        changing_to_ = changing_to;
    }

private:
    int in_spindle_;
    int changing_to_ = 0;
};

} // namespace parsons::axes
