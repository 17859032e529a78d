// Storage: banks of holding relays (Fig. 13) set by the card reader, one bank per digit: the
// patent's "card number storage unit 136", the "storage and comparer unit 136" of Figs. 2, 11
// and 12 ("In the card storage unit 136 there are provided a number of banks of relay switches
// indicated in Fig. 12 at 350, 352, 354 and 356").
//
// A holding relay (coil 368) closes on an impulse from the reader's brushes and holds until
// the zeroizing circuit's clearing channel 294 momentarily de-energizes the coils.
//
// Absolute storage, banks 350 (inches), 352, 354, 356 (thousandths), channel 218: the slow-downs
// and the stop SHARE the banks, as the patent describes: 8.785 / 8.885 / 8.985 close relay 8 of
// 350, relays 7, 8, 9 of 352, relay 8 of 354 and relay 5 of 356. The absolute comparer 122'
// conducts whenever every counter switch stands on a closed relay, so numbers that differ in more
// than one digit also match at spurious positions (docs/design-rules.md rule 2). The profile option
// separate_registers gives each number its own register instead (a departure from the patent, off
// by default).
//
// Incremental storage, banks 318 (thousandths), 320, 322, 324 (inches), channel 220: the check.
#pragma once

#include "relaylogic/counters.hpp"

#include <array>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <vector>

namespace parsons::relaylogic {

// The banks by digit place, inches first: absolute 350-356, incremental 324-318 (Fig. 12), and
// the names their relays' signals carry ("absolute_storage_352.relay_7"). The reader's wiring
// (relaylogic/card_reader.cpp, brush_wiring) names the relays by these.
inline constexpr std::array<int, 4> kAbsoluteBanks = {350, 352, 354, 356};
inline constexpr std::array<int, 4> kIncrementalBanks = {324, 322, 320, 318};
inline constexpr const char* kAbsoluteStorageName = "absolute_storage";
inline constexpr const char* kIncrementalStorageName = "incremental_storage";

class HoldingRelayBank {
public:
    HoldingRelayBank(Tracer& tracer, const std::string& scope, const std::string& numeral,
                     const std::string& what);
    void pick(int digit);
    void release_all();
    // Faults: relay `digit` stuck closed (it never releases) or dead (it never picks).
    void stick(int digit);
    void kill(int digit);
    std::int64_t refused_picks() const { return refused_; } // picks a dead relay did not follow
    // The state a saved machine keeps (relaylogic/machine_state.cpp).
    nlohmann::json save() const;
    void load(const nlohmann::json& j);
    bool closed(int digit) const { return (closed_ >> digit & 1U) != 0; }
    // Relay d closed <=> bit d set.
    std::uint16_t closed_mask() const { return closed_; }
    std::vector<int> closed_relays() const;

private:
    Tracer& tracer_;
    std::uint16_t closed_ = 0;
    std::uint16_t stuck_ = 0;
    std::uint16_t dead_ = 0;
    std::int64_t refused_ = 0;
    std::array<SignalId, 10> signals_{};
};

class AbsoluteStorage {
public:
    AbsoluteStorage(Tracer& tracer, const std::string& scope, bool separate_registers);
    // The reader's first brush bank: slow-downs and stop into banks 350-356.
    void store(std::span<const int> numbers);
    void store(std::initializer_list<int> numbers) {
        store(std::span<const int>(numbers.begin(), numbers.size()));
    }
    void clear();
    // Comparer 122': does the circuit through the banks close for these counter digits?
    bool conducts(const Digits& counter) const {
        if (separate_registers_) {
            return conducts_separately(counter);
        }
        return banks_[0].closed(counter[0]) && banks_[1].closed(counter[1]) &&
               banks_[2].closed(counter[2]) && banks_[3].closed(counter[3]);
    }
    const HoldingRelayBank& bank(int i) const { return banks_.at(static_cast<std::size_t>(i)); }
    HoldingRelayBank& bank(int i) { return banks_.at(static_cast<std::size_t>(i)); }
    bool separate_registers() const { return separate_registers_; }
    // The numbers stored (with separate registers, each in its own).
    const std::vector<int>& numbers() const { return numbers_; }
    // The state a saved machine keeps (relaylogic/machine_state.cpp).
    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    bool conducts_separately(const Digits& counter) const;

    std::array<HoldingRelayBank, 4> banks_; // 350, 352, 354, 356
    bool separate_registers_;
    std::vector<int> numbers_;
};

class IncrementalStorage {
public:
    IncrementalStorage(Tracer& tracer, const std::string& scope);
    void store(int check);
    void clear();
    // Comparer 122'': does the circuit through banks 318-324 close for counter 112?
    bool conducts(const Digits& increment) const {
        return banks_[0].closed(increment[0]) && banks_[1].closed(increment[1]) &&
               banks_[2].closed(increment[2]) && banks_[3].closed(increment[3]);
    }
    const HoldingRelayBank& bank(int i) const { return banks_.at(static_cast<std::size_t>(i)); }
    HoldingRelayBank& bank(int i) { return banks_.at(static_cast<std::size_t>(i)); }
    // The state a saved machine keeps (relaylogic/machine_state.cpp).
    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    std::array<HoldingRelayBank, 4> banks_; // 324 (inches), 322, 320, 318 (thousandths)
};

} // namespace parsons::relaylogic
