// Where the part stands against the reading commutators 96-102 gave, cause by cause: what the
// summary names when a part is not where its counters say (docs/report.md). Each figure is its
// own table's, or nut 78's, at the place it acts (LeadScrewAxis::chain_figures).
#pragma once

namespace parsons::axes {

// Inches, part minus reading. Only what the chain does not measure: through instrument shaft
// 74 the lead error, backlash and slip of lead screw 22 are measured (they are 0 here);
// counting screw turns, they are not.
struct ChainFigures {
    bool counts_screw_turns = false; // MeasuringChain::screw_turns (the departure)
    double at_in = 0;                // where they act: the reading (shaft 74) or the engaged screw
    double instrument_in = 0;        // shaft 74's own screw (instrument_error_in)
    double cam_160_in = 0;     // cam 160's correction where it corrects what the counters read
    double screw_error_in = 0; // the residual screw error given directly (screw_error_in)
    double lead_in = 0;        // lead error of lead screw 22 (lead_error_in)
    double backlash_in = 0;    // nut 78: backlash taken up since the forward flank
    double slip_in = 0;        // the drive slipped (negative: the part lags going forward)
    double sum() const {
        return instrument_in + cam_160_in + screw_error_in + lead_in + backlash_in + slip_in;
    }
};

} // namespace parsons::axes
