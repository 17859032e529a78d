// Instrument shaft 74 and the measuring chain of Fig. 3 (claims 8-10, 23: "measuring means
// independent of said main lead screw"): gears 70-72 and slip clutch (or fluid coupling) 80
// drive the unloaded shaft 74 from lead screw 22 a little faster than the screw; follower 76
// on it butts against nut 78 of the part, so the shaft turns with the part's real position and
// the clutch slips. Gear train 82-92 turns commutators 96-102 at 1000 impulses an inch of
// shaft 74.
//
// How we represent it: the counters' reading q and the part's position p are tied by the
// instrument's residual error r = (shaft 74's own error) + (the profile's residual
// screw_error_in): p = q + r(q). Nothing between motor and part (screw slip, backlash in nut
// 78, lead screw 22's lead error) enters: they are measured. What the chain itself gets wrong
// (r) is not. Compensating cam 160 is drawn at "the table lead screw 22" and corrects that
// screw's lead (axes/lead_screw_axis.cpp), so it is not in r; under the interpretation
// cam_160_on_instrument_shaft (docs/machine-profile.md) it corrects shaft 74's screw instead:
// r = (shaft 74's own error) - (cam 160's correction) + screw_error_in.
// Emulation note: follower 76 is taken to stay against nut 78 both ways (the patent says
// "normally butts"; a follower that left the nut going back would count the screw, not the
// part), and gears 70-72 and clutch 80 only ensure that; they have no figure of their own.
#pragma once

#include "axes/machine_profile.hpp"
#include "axes/screw_error_table.hpp"

namespace parsons::axes {

class InstrumentShaft {
public:
    InstrumentShaft() = default;
    // cam_160_here: the interpretation cam_160_on_instrument_shaft (cam 160 corrects this
    // shaft's screw, not lead screw 22).
    InstrumentShaft(const AxisProfile& p, bool cam_160_here)
        : residual_(
              cam_160_here
                  ? ScrewErrorTable::sum(
                        {{&p.screw_error_in, 1}, {&p.instrument_error_in, 1}, {&p.cam_160_in, -1}})
                  : ScrewErrorTable::sum({{&p.screw_error_in, 1}, {&p.instrument_error_in, 1}})) {}

    // Where the part stands when the counters read q, and the reading for the part at p.
    double part_at_reading(double q) const { return residual_.apply(q); }
    double reading_at_part(double p) const { return residual_.invert(p); }
    bool exact() const { return residual_.empty(); }
    // The least part travel per unit of reading (the residual's least slope).
    double least_part_per_reading() const { return residual_.slope_range().first; }

private:
    ScrewErrorTable residual_;
};

} // namespace parsons::axes
