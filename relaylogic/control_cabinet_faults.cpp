// Control cabinet 52, injected faults (relaylogic/faults.hpp): set up before a run, and after
// it what the faults that act unseen did.
#include "relaylogic/control_cabinet.hpp"

#include <fmt/format.h>

#include <cmath>

namespace parsons::relaylogic {

using cardreader::Axis;
using cardreader::axis_name;

HoldingRelayBank& ControlCabinet::bank_numbered(AxisCircuit& c, int numeral) {
    if (numeral >= 350) {
        return c.absolute_storage.bank((numeral - 350) / 2); // 350, 352, 354, 356
    }
    return c.incremental_storage.bank((324 - numeral) / 2); // 324, 322, 320, 318
}

SteppingSwitch& ControlCabinet::switch_numbered(AxisCircuit& c, int numeral) {
    if (numeral >= 310) {
        return c.increment_counter.stepping_switch(static_cast<std::size_t>((numeral - 310) / 2));
    }
    return c.absolute_counter.stepping_switch(static_cast<std::size_t>((numeral - 104) / 2));
}

void ControlCabinet::apply_faults(cardreader::CardSource& deck) {
    // A resumed machine has its faults in its state already (stuck relays, a slip under way)
    // and what they did so far; only the reader's faults are set up again.
    if (!resuming_) {
        effects_.clear();
    }
    std::vector<Fault> feed_faults;
    std::vector<std::size_t> feed_effects;
    for (std::size_t i = 0; i < faults_.size(); ++i) {
        const Fault& f = faults_[i];
        if (resuming_) {
            if (f.kind == FaultKind::feed_twice || f.kind == FaultKind::swap_cards ||
                f.kind == FaultKind::short_card) {
                feed_faults.push_back(f);
                feed_effects.push_back(i);
            }
            continue;
        }
        effects_.push_back(FaultEffect{f.spec, false, ""});
        AxisCircuit& c = *circuits_.at(cardreader::axis_index(f.axis));
        switch (f.kind) {
        case FaultKind::stuck_relay:
            bank_numbered(c, f.numeral).stick(f.digit);
            effects_.back().acted = true;
            effects_.back().effect = fmt::format("relay {} of {} bank {} was stuck closed from the "
                                                 "start",
                                                 f.digit, axis_name(f.axis), f.numeral);
            break;
        case FaultKind::dead_relay:
            bank_numbered(c, f.numeral).kill(f.digit);
            break;
        case FaultKind::skip_step:
            switch_numbered(c, f.numeral).skip_on_step(f.n);
            break;
        case FaultKind::slip:
            c.plant.slip_from(f.n, f.count);
            break;
        case FaultKind::feed_twice:
        case FaultKind::swap_cards:
        case FaultKind::short_card:
            feed_faults.push_back(f);
            feed_effects.push_back(effects_.size() - 1);
            break;
        case FaultKind::drop_impulse:
            break;
        case FaultKind::stale_ratio:
        case FaultKind::transfer_hang:
            break; // PC 130's (tapping units, when the profile has them)
        }
    }
    if (!feed_faults.empty()) {
        std::vector<FaultEffect*> targets;
        for (std::size_t i : feed_effects) {
            targets.push_back(&effects_.at(i));
        }
        faulty_feed_ = std::make_unique<FaultyFeed>(deck, feed_faults, targets);
        deck_ = faulty_feed_.get();
    }
}

// After the run: what the faults that act unseen did.
void ControlCabinet::report_faults() {
    for (std::size_t i = 0; i < faults_.size(); ++i) {
        const Fault& f = faults_[i];
        FaultEffect& e = effects_.at(i);
        AxisCircuit& c = *circuits_.at(cardreader::axis_index(f.axis));
        const std::string_view axis = axis_name(f.axis);
        if (f.kind == FaultKind::dead_relay && bank_numbered(c, f.numeral).refused_picks() > 0) {
            e.acted = true;
            e.effect = fmt::format("relay {} of {} bank {} failed to pick {} time{}", f.digit, axis,
                                   f.numeral, bank_numbered(c, f.numeral).refused_picks(),
                                   bank_numbered(c, f.numeral).refused_picks() == 1 ? "" : "s");
        } else if (f.kind == FaultKind::skip_step &&
                   !switch_numbered(c, f.numeral).skip_pending()) {
            e.acted = true;
            e.effect = fmt::format("{} stepping switch {} skipped a position on its step {}", axis,
                                   f.numeral, f.n);
        } else if (f.kind == FaultKind::slip && c.plant.slip_in() != 0) {
            e.acted = true;
            e.effect = slip_effect(f, c);
        }
        for (const auto& a : attachments_) {
            a->fault_effect(*this, f, e); // stale-ratio, transfer-hang: PC 130's
        }
        if (!e.acted && e.effect.empty()) {
            e.effect = "never came into play in this run";
        }
    }
}

// What a slip did depends on what the counters measure (docs/design-rules.md rule 3).
std::string ControlCabinet::slip_effect(const Fault& f, const AxisCircuit& c) const {
    const double slipped = std::abs(c.plant.slip_in());
    const std::int64_t thousandths = std::lround(slipped / axes::kInchesPerImpulse);
    const std::string what =
        fmt::format("the {} drive slipped for {:.3f} in of screw travel from its impulse {}",
                    axis_name(f.axis), slipped, f.n);
    if (c.plant.measuring_chain() == axes::MeasuringChain::screw_turns) {
        return fmt::format("{}: the counters counted {} impulse{} of screw turns the part never "
                           "made and it lags them by {:.3f} in, which no 1952 check can see "
                           "(screw-turn counting, a departure from the patent)",
                           what, thousandths, thousandths == 1 ? "" : "s", slipped);
    }
    return fmt::format("{}: the part stood while the screw turned; instrument shaft 74 follows "
                       "the part, so the counters did not count it and the axis ran on to the "
                       "real position its card asked for (Fig. 3, claims 8-10)",
                       what);
}

} // namespace parsons::relaylogic
