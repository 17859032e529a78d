// Choosing each axis's start speed and slow-downs for one move, from the machine profile's
// physics, the way a 1952 programmer chose them with the machine's figures in hand.
//
//   - The axis must reach its stop on speed 3, where the coast after switching off
//     (v3^2 / 2 a_brake) stays under half a thousandth; a profile whose speed 3 coasts
//     further cannot give an exact deck, and says so.
//   - A faster start speed is used only when the move is long enough to slow down from it
//     before the stop: from speed v to w takes (v^2 - w^2) / 2a of travel; the slow-downs are
//     placed with half as much again to spare, rounded up to whole thousandths.
//   - A speed whose impulses would come faster than the stepping switches follow
//     (max_stepping_rate_per_s) is never used: the counters would fall behind.
//   - Only the table has two slow-down fields (layout fig8), so only the table starts on
//     speed 1; the others start at most on speed 2.
//   - Never a card with the shared-bank hazard (docs/design-rules.md rule 2): if the slow-downs
//     would also compare equal somewhere on the way, they are moved further from the stop, a
//     thousandth at a time; failing that, the move starts one speed slower.
//   - Corner slow-down (EP 0636958, Black & Decker): where the path turns sharply at the
//     station this card goes to, the move is made at the lowest speed.
#pragma once

#include "axes/machine_profile.hpp"
#include "cardreader/orders.hpp"

#include <stdexcept>

namespace parsons::decks {

class PlanError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

struct MoveRequest {
    int from = 0; // thousandths, where the axis stands (the previous card's stop)
    int to = 0;   // thousandths, the stop
    int slow_down_fields = 1;
    bool corner = false; // approach at the lowest speed
    cardreader::SequencePattern sequence = 0;
};

// The axis order for one move. Throws PlanError if the profile cannot stop within half a
// thousandth even from speed 3.
cardreader::AxisOrder plan_move(const MoveRequest& move, const axes::AxisProfile& axis,
                                const axes::MachineProfile& profile);

// Thousandths of travel needed to slow from speed position `from` to `to` (1..3), with the
// margin plan_move uses.
int slow_down_room(const axes::AxisProfile& axis, int from, int to);

} // namespace parsons::decks
