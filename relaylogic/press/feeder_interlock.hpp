// The feeder's interlock: an addition after EP 0436887 (Mitsubishi) that a press line has and
// the seed does not draw: the signal by which the numerical control holds the press it follows.
// Synchronisation control processor 17 raises it at a reference block when a synchronised axis
// running on its card is behind its reference travel by more than press.feeder_hold_lag_in, and
// drops it at the first block where every such axis is within half of that, or none runs; like
// processor 63's speeds it reaches the press at the start of the next block (Fig. 6, line C),
// where the clutch and brake hold crank 21 where it stands, and let it go (axes::Press::hold).
// While the press stands the axis makes its lag up (processor 63's stop and go, and its position
// loop on a card with position sync). docs/press-sync.md, "The feeder holds the press".
#pragma once

#include "relaylogic/tracer.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>

namespace parsons::relaylogic {

class FeederInterlock {
public:
    FeederInterlock(Tracer& tracer, double limit_in);

    double limit_in() const { return limit_in_; }
    // A reference block at machine time t, with the most a synchronised axis running on its
    // card is behind its reference (nothing: none runs). Returns what the press is to do from
    // now: held (true) or free — the relay as the last block left it.
    bool block(std::optional<double> most_behind_in, double t);
    bool holding() const { return in_force_; } // the press is held by it now
    double held_since() const { return since_; }
    // When the last hold ended (0: none has): the press has been free since.
    double free_since() const { return free_since_; }

    // The holds begun, and at machine time t the press's time held and the longest hold (the
    // hold in force counted to t).
    std::int64_t holds() const { return holds_; }
    double held_s(double t) const { return held_s_ + (in_force_ ? t - since_ : 0.0); }
    double longest_s(double t) const;

    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    Tracer& tracer_;
    double limit_in_;
    bool relay_ = false;    // processor 17's interlock relay, as computed at the last block
    bool in_force_ = false; // the press is held (the relay of the block before)
    double since_ = 0;      // when the hold in force began
    double free_since_ = 0; // when the last hold ended
    std::int64_t holds_ = 0;
    double held_s_ = 0;    // the holds that ended
    double longest_s_ = 0; // of those
    SignalId signal_;
};

} // namespace parsons::relaylogic
