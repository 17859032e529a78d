// Helpers for the machine tests: decks built from orders, an observer that records every
// signal change by name, and a run helper.
#pragma once

#include "axes/machine_profile.hpp"
#include "cardreader/layout.hpp"
#include "relaylogic/control_cabinet.hpp"

#include <map>
#include <string>
#include <vector>

namespace parsons::test {

// A deck held in memory.
class VectorDeck : public cardreader::CardSource {
public:
    explicit VectorDeck(std::vector<cardreader::Card> cards) : cards_(std::move(cards)) {}
    std::optional<cardreader::Card> next() override {
        if (next_ >= cards_.size()) {
            return std::nullopt;
        }
        return cards_[next_++];
    }

private:
    std::vector<cardreader::Card> cards_;
    std::size_t next_ = 0;
};

struct Change {
    double t;
    std::string signal; // "table.motor_38"
    std::uint32_t old_value;
    std::uint32_t new_value;
};

// Records every change, and the value of every signal at each zeroizing (end of card).
class Recorder : public relaylogic::MachineObserver {
public:
    void on_signal_defined(const relaylogic::SignalInfo& info, std::uint32_t initial) override;
    void on_signal(double t, relaylogic::SignalId id, std::uint32_t old_value,
                   std::uint32_t new_value) override;

    std::vector<Change> changes;
    std::map<std::string, std::uint32_t> value;                   // current value by name
    std::vector<std::map<std::string, std::uint32_t>> at_zeroize; // snapshot per card

    std::vector<Change> of(const std::string& signal) const;
    // Absolute counter reading of an axis (thousandths) in a snapshot.
    static int counter(const std::map<std::string, std::uint32_t>& snapshot,
                       const std::string& axis);

private:
    std::vector<std::string> names_;
};

// An axis order: motion from the sign of (stop - from), slow-downs as given.
cardreader::AxisOrder order(int from, int stop, int speed, std::optional<int> slow1 = {},
                            std::optional<int> slow2 = {}, cardreader::SequencePattern seq = 1);

// A card with every axis idle (check 0 at its position `at`) except those set afterwards.
cardreader::CardOrders idle_card(int number, const std::array<int, 5>& at);

relaylogic::RunResult run_orders(const std::vector<cardreader::CardOrders>& cards,
                                 const axes::MachineProfile& profile = axes::default_profile(),
                                 relaylogic::MachineObserver* observer = nullptr,
                                 const std::vector<relaylogic::Fault>& faults = {},
                                 relaylogic::Pace pace = relaylogic::Pace::fast_forward);

// Two runs of one deck ended the same (Catch2 REQUIREs): completion, cards, machine time, the
// stop, every axis's counters, position, impulses, lost steps, slip, screw and commutator, the
// faults' effects, condition actions, the tool, the press, the tapping and each card's times.
// The paces and the observed and unobserved impulse level must all agree on it
// (tests/fast_forward_test.cpp, tests/quiet_stretch_test.cpp).
void require_same(const relaylogic::RunResult& a, const relaylogic::RunResult& b);

} // namespace parsons::test
