// The feeder's interlock (relaylogic/press/feeder_interlock.hpp says what it is).
#include "relaylogic/press/feeder_interlock.hpp"

#include "axes/lead_screw_axis.hpp"
#include "axes/state_json.hpp"

#include <algorithm>

namespace parsons::relaylogic {

FeederInterlock::FeederInterlock(Tracer& tracer, double limit_in)
    : tracer_(tracer), limit_in_(limit_in),
      signal_(tracer.define("press", "feeder_interlock.hold",
                            "the feeder's interlock: processor 17 holds the press (clutch out, "
                            "brake on) while a synchronised axis lags its reference by more than "
                            "press.feeder_hold_lag_in (an addition: docs/press-sync.md)",
                            "", 1)) {}

bool FeederInterlock::block(std::optional<double> most_behind_in, double t) {
    const bool hold = relay_;
    // The relay picks past the limit and holds until the lag is half of it (or no axis runs):
    // a press let go at the limit itself would stop again within a block.
    const double behind = most_behind_in.value_or(0.0);
    relay_ = most_behind_in.has_value() && (relay_ ? behind > limit_in_ / 2 : behind > limit_in_);
    if (hold != in_force_) {
        in_force_ = hold;
        if (hold) {
            since_ = t;
            ++holds_;
        } else {
            held_s_ += t - since_;
            longest_s_ = std::max(longest_s_, t - since_);
            free_since_ = t;
        }
        tracer_.set(signal_, hold ? 1U : 0U);
    }
    return hold;
}

double FeederInterlock::longest_s(double t) const {
    return std::max(longest_s_, in_force_ ? t - since_ : 0.0);
}

nlohmann::json FeederInterlock::save() const {
    using axes::exact;
    return {{"relay", relay_},
            {"in_force", in_force_},
            {"since_s", exact(since_)},
            {"holds", holds_},
            {"held_s", exact(held_s_)},
            {"longest_s", exact(longest_s_)},
            {"free_since_s", exact(free_since_)}};
}

void FeederInterlock::load(const nlohmann::json& j) {
    using axes::exact;
    using axes::member;
    using axes::read;
    relay_ = read<bool>(j, "relay");
    in_force_ = read<bool>(j, "in_force");
    since_ = exact(member(j, "since_s"));
    holds_ = read<std::int64_t>(j, "holds");
    held_s_ = exact(member(j, "held_s"));
    longest_s_ = exact(member(j, "longest_s"));
    free_since_ = exact(member(j, "free_since_s"));
    if (holds_ < 0 || !(held_s_ >= 0) || !(longest_s_ >= 0) || (in_force_ && holds_ == 0)) {
        throw axes::StateError("feeder_interlock: holds and times out of range");
    }
    tracer_.set(signal_, in_force_ ? 1U : 0U);
}

} // namespace parsons::relaylogic
