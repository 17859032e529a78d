// The tool changer: an addition after EP 0640901 (Siemens), whose example action is
// a tool change begun before the machine reaches the exact change position (claims 5, 6).
//
// The 1952 machine had one cutter, changed by hand between jobs. Here a changer holds the
// profile's tools (number and cutter radius); a tool change takes the profile's
// tool_change_s, and the new tool is in the spindle when it is acknowledged. The cut proof
// sweeps each stretch of the path with the radius of the tool that cut it.
//
// The changer is one machine: it makes one change at a time. A change ordered while another is
// under way waits for it (the seed's tripping unit ALE has each action performed and
// acknowledged, claim 2, and refuses none): it begins when the changer is free and, if the
// spindle is still running down, when the spindle stands (the tripping unit says when). Each
// acknowledgement puts the tool its own change ordered in the spindle.
//
// Emulation note: the changer's arm, magazine and drawbar are one timed action; the cutter
// is not at risk while the axes move during the change (the seed's point: the change runs
// while the tool travels to the change position).
#pragma once

#include "axes/machine_profile.hpp"

#include <algorithm>
#include <deque>

namespace parsons::axes {

struct ToolChange {
    int tool = 0;
    double start_s = 0; // when the changer begins it
    double done_s = 0;  // when the tool is in the spindle
    bool operator==(const ToolChange&) const = default;
};

class ToolChanger {
public:
    explicit ToolChanger(int first_tool = 1) : in_spindle_(first_tool) {}
    // Orders a change to `tool` at time t, to begin no earlier than `not_before` (the spindle
    // at rest); returns when the new tool is in the spindle.
    double change(int tool, double t, double not_before, const ActionTimes& times) {
        const double start =
            std::max({t, not_before, changes_.empty() ? t : changes_.back().done_s});
        changes_.push_back(ToolChange{tool, start, start + times.tool_change_s});
        return changes_.back().done_s;
    }
    // The change to `tool` is complete (its acknowledgement): the oldest such change.
    void complete(int tool) {
        const auto it = std::find_if(changes_.begin(), changes_.end(),
                                     [tool](const ToolChange& c) { return c.tool == tool; });
        if (it != changes_.end()) {
            in_spindle_ = tool;
            changes_.erase(it);
        }
    }
    int in_spindle() const { return in_spindle_; }
    // The tool of the change under way or next to begin (0 when none is ordered).
    int changing_to() const { return changes_.empty() ? 0 : changes_.front().tool; }
    // Changes ordered behind the one under way.
    int waiting() const { return changes_.empty() ? 0 : static_cast<int>(changes_.size()) - 1; }
    const std::deque<ToolChange>& changes() const { return changes_; }
    void restore(int in_spindle, std::deque<ToolChange> changes) {
        in_spindle_ = in_spindle;
        changes_ = std::move(changes);
    }

private:
    int in_spindle_;
    std::deque<ToolChange> changes_; // in the order they were ordered (and will be done)
};

} // namespace parsons::axes
