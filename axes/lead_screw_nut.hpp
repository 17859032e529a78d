// Lead screw 22 and its nut 78 (Fig. 3), and the drive between motor and part: what lies
// between the turns of the main screw and where the part (table 14, cutter head 28, fixture
// 15, sine plate 16) really is.
//
//   motor 38 -> lead screw 22 --(backlash b)--> nut 78 = the part      s: screw travel, inches
//                                                                      (turns x lead)
//   * lead error: with the nut engaged, the part stands at G(sigma) = sigma + L(sigma), L the
//     screw's error table (profile key lead_error_in) less the correction of compensating cam
//     160, which the patent draws "for the table lead screw 22" (cam_160_in; none under the
//     interpretation cam_160_on_instrument_shaft);
//   * backlash in nut 78: the screw drives the nut on one flank going forward and on the
//     other going back; between them it turns b inches with the part standing still;
//   * slip (the fault slip:AXIS:N:M): for M thousandths of screw travel the drive slips and
//     the part stands while the screw turns.
//
// How we represent it: sigma, the "engaged screw position", is the screw travel the part has
// actually followed; the part is at G(sigma). During one stretch of motion in direction d
// (from screw position s0, engaged position sigma0) the part stands over a dead travel of the
// screw (the backlash gap left to take up, then the slip left) and then follows:
//
//     sigma(s) = d > 0 ? max(sigma0, s - o_end) : min(sigma0, s - o_end)
//
// where o_end, the screw's lead over the part once the dead travel is taken up, is the flank's
// offset (forward o_f, reverse o_f - b) plus the slip left. A new stretch begins at every phase
// of the motor (LeadScrewAxis::start_phase) and where a slip begins; at its start the dead
// travel the stretch before used up is booked. Booking nothing leaves every number as it was,
// so the same instant seen twice changes nothing (fast-forward and impulse level agree).
// Emulation note: the part has no mass of its own here; it moves with the screw or stands.
#pragma once

#include "axes/screw_error_table.hpp"
#include "axes/state_json.hpp"

#include <algorithm>

namespace parsons::axes {

class LeadScrewNut {
public:
    LeadScrewNut() = default;
    LeadScrewNut(double backlash_in, ScrewErrorTable part)
        : b_(backlash_in), part_(std::move(part)) {}
    // At rest at screw position s, forward flank engaged, nothing slipped.
    void reset_at(double s) { *this = LeadScrewNut(b_, part_, s); }
    // The part as a function of the engaged screw position: G, or (counting screw turns) the
    // screw's whole residual error.
    void set_part_table(ScrewErrorTable part) { part_ = std::move(part); }

    // A new stretch of motion in direction d from screw position s; a slip of extra_slip_in
    // inches of screw travel begins there.
    void rebase(double s, int d, double extra_slip_in = 0) {
        const double travel = d_ * (s - s0_);
        if (travel > 0) {
            const double used =
                travel >= dead_ ? slip_left_ : std::clamp(travel - gap_, 0.0, slip_left_);
            slip_left_ -= used;
            o_f_ += d_ * used;
            slipped_ -= d_ * used;
        }
        sigma0_ = sigma_at(s);
        s0_ = s;
        d_ = d >= 0 ? +1 : -1;
        slip_left_ += extra_slip_in;
        const double flank = d_ > 0 ? o_f_ : o_f_ - b_;
        o_end_ = flank + d_ * slip_left_;
        gap_ = std::max(0.0, d_ * (flank - (s - sigma0_)));
        dead_ = gap_ + slip_left_;
    }

    // Where the part follows the screw to, at screw position s within this stretch.
    double sigma_at(double s) const {
        return d_ > 0 ? std::max(sigma0_, s - o_end_) : std::min(sigma0_, s - o_end_);
    }
    // The screw position that engages sigma (beyond the dead travel of this stretch).
    double screw_at(double sigma) const { return sigma + o_end_; }
    double part_at_screw(double s) const { return part_.apply(sigma_at(s)); }
    double sigma_at_part(double p) const { return part_.invert(p); }
    double o_end() const { return o_end_; }
    // The greatest part travel per unit of engaged screw travel (G's greatest slope).
    double greatest_part_per_screw() const { return part_.slope_range().second; }
    // How far the part lags the screw through slipping so far (negative going forward), and
    // the slip still to come.
    double slip_in() const { return slipped_; }
    // The slip so far at screw position s, this stretch's share included (slip_in() books it
    // only at the next stretch): the same booking rebase() makes, changing nothing.
    double slip_now_in(double s) const {
        const double travel = d_ * (s - s0_);
        if (travel <= 0) {
            return slipped_;
        }
        const double used =
            travel >= dead_ ? slip_left_ : std::clamp(travel - gap_, 0.0, slip_left_);
        return slipped_ - d_ * used;
    }
    double slip_left_in() const { return slip_left_; }

    nlohmann::json save() const {
        return nlohmann::json{
            {"s0", exact(s0_)},     {"sigma0", exact(sigma0_)},       {"d", d_},
            {"o_f", exact(o_f_)},   {"o_end", exact(o_end_)},         {"gap", exact(gap_)},
            {"dead", exact(dead_)}, {"slip_left", exact(slip_left_)}, {"slipped", exact(slipped_)}};
    }
    void load(const nlohmann::json& j) {
        s0_ = exact(member(j, "s0"));
        sigma0_ = exact(member(j, "sigma0"));
        d_ = read<int>(j, "d") >= 0 ? +1 : -1;
        o_f_ = exact(member(j, "o_f"));
        o_end_ = exact(member(j, "o_end"));
        gap_ = exact(member(j, "gap"));
        dead_ = exact(member(j, "dead"));
        slip_left_ = exact(member(j, "slip_left"));
        slipped_ = exact(member(j, "slipped"));
    }

private:
    LeadScrewNut(double b, ScrewErrorTable part, double s)
        : b_(b), part_(std::move(part)), s0_(s), sigma0_(s) {}

    double b_ = 0;
    ScrewErrorTable part_;
    double s0_ = 0;     // this stretch: from screw position s0_,
    double sigma0_ = 0; // engaged position sigma0_,
    int d_ = +1;        // in direction d_,
    double o_end_ = 0;  // screw minus engaged position once the dead travel is taken up
    double gap_ = 0;    // backlash left to take up at its start
    double dead_ = 0;   // gap_ + the slip left at its start
    double o_f_ = 0;    // screw minus engaged position on the forward flank
    double slip_left_ = 0;
    double slipped_ = 0;
};

} // namespace parsons::axes
