// Monitoring unit PRG of EP 0640901 (Siemens, claim 1): an addition, not in the 1952
// patent. "The internal buffer (PFR) supplies ... the condition to a monitoring unit (PRG)";
// "the tripping unit (ALE) obtains a status signal from the monitoring unit (PRG) upon
// fulfilment of the condition", and "the respective status signal is the respective
// identifier" (claim 3).
//
// Built here the way the 1952 cabinet builds its comparers (relaylogic/storage.hpp): each
// channel k of PRG is four banks of ten holding relays (inches, tenths, hundredths,
// thousandths) into which the armed condition's position is picked, and a sense relay
// (forward, reverse or both contacts closed). The channel's comparer is a circuit through the
// wipers of the watched axis's absolute counter 104-110 and the bank relays they stand on, in
// series with the sense contact that matches reversing control 214 of that axis. The circuit
// is read each time one of the counter's switches steps (the wiper arriving on a relay), so a
// condition is met when the counter steps ONTO its position while counting in its sense: a
// position the counter already stands on when the motion card is read is not passed.
//
// Emulation note: under the profile's hundredths-only counting (count_hundredths_at_speed_1)
// switch 110 stands still at speed 1, so the reading moves ten thousandths at a time and a
// position between two such readings is never stepped onto (condition_not_met), as with any
// comparer on that counter.
#pragma once

#include "cardreader/orders.hpp"
#include "relaylogic/conditions/internal_buffer.hpp"
#include "relaylogic/counters.hpp"
#include "relaylogic/storage.hpp"

#include <array>
#include <memory>
#include <vector>

namespace parsons::relaylogic {

class MonitoringUnit {
public:
    explicit MonitoringUnit(Tracer& tracer);
    // PFR supplies the condition of pair k: its position into channel k's banks, its sense
    // into the sense relay.
    void arm(int k, const ConditionEntry& condition);
    void disarm(int k);
    void clear();
    bool watching(cardreader::Axis axis) const {
        return watch_.at(cardreader::axis_index(axis)) != 0;
    }
    // The channels whose circuit closes now that the counter of `axis` stepped to `counter`,
    // counting in `direction` (+1 up, -1 down): bit k for channel k. Each reports its event.
    unsigned on_counter_step(cardreader::Axis axis, const Digits& counter, int direction);
    // Fast-forward: the positions the armed channels of `axis` watch for in `direction`.
    template <typename F>
    void each_watched(cardreader::Axis axis, int direction, F&& f) const {
        const unsigned mask = watch_.at(cardreader::axis_index(axis));
        for (int k = 0; k < InternalBuffer::kChannels; ++k) {
            if ((mask >> k & 1U) != 0 && senses(k, direction)) {
                f(positions_.at(static_cast<std::size_t>(k)));
            }
        }
    }
    // The status signal (the identifier of the last condition met).
    void report(int event);
    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    bool senses(int k, int direction) const;

    Tracer& tracer_;
    std::vector<std::array<std::unique_ptr<HoldingRelayBank>, 4>> banks_;
    std::array<cardreader::PassingSense, InternalBuffer::kChannels> sense_{};
    std::array<int, InternalBuffer::kChannels> positions_{};
    std::array<cardreader::Axis, InternalBuffer::kChannels> axis_{};
    std::array<unsigned, cardreader::kAxisCount> watch_{}; // armed channels, bit k, per axis
    std::array<SignalId, InternalBuffer::kChannels> sense_signal_{};
    SignalId status_;
};

} // namespace parsons::relaylogic
