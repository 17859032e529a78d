#include "relaylogic/storage.hpp"

#include <algorithm>

namespace parsons::relaylogic {

HoldingRelayBank::HoldingRelayBank(Tracer& tracer, const std::string& scope,
                                   const std::string& numeral, const std::string& what)
    : tracer_(tracer) {
    for (int d = 0; d < 10; ++d) {
        signals_.at(static_cast<std::size_t>(d)) =
            tracer.define(scope, what + "_" + numeral + ".relay_" + std::to_string(d),
                          "holding relay " + std::to_string(d) + " of bank " + numeral, numeral, 1);
    }
}

void HoldingRelayBank::pick(int digit) {
    const auto i = static_cast<std::size_t>(digit);
    if ((dead_ >> i & 1U) != 0) {
        ++refused_;
        return;
    }
    closed_ = static_cast<std::uint16_t>(closed_ | (1U << i));
    tracer_.set(signals_.at(i), 1);
}

void HoldingRelayBank::release_all() {
    if (tracer_.observer() != nullptr) {
        for (std::size_t i = 0; i < 10; ++i) {
            if ((closed_ >> i & 1U) != 0 && (stuck_ >> i & 1U) == 0) {
                tracer_.set(signals_.at(i), 0);
            }
        }
    }
    closed_ = stuck_;
}

void HoldingRelayBank::stick(int digit) {
    const auto i = static_cast<std::size_t>(digit);
    stuck_ = static_cast<std::uint16_t>(stuck_ | (1U << i));
    closed_ = static_cast<std::uint16_t>(closed_ | (1U << i));
    tracer_.set(signals_.at(i), 1);
}

void HoldingRelayBank::kill(int digit) {
    dead_ = static_cast<std::uint16_t>(dead_ | (1U << static_cast<unsigned>(digit)));
}

std::vector<int> HoldingRelayBank::closed_relays() const {
    std::vector<int> out;
    for (int d = 0; d < 10; ++d) {
        if (closed(d)) {
            out.push_back(d);
        }
    }
    return out;
}

AbsoluteStorage::AbsoluteStorage(Tracer& tracer, const std::string& scope, bool separate)
    : banks_{HoldingRelayBank(tracer, scope, std::to_string(kAbsoluteBanks[0]),
                              kAbsoluteStorageName),
             HoldingRelayBank(tracer, scope, std::to_string(kAbsoluteBanks[1]),
                              kAbsoluteStorageName),
             HoldingRelayBank(tracer, scope, std::to_string(kAbsoluteBanks[2]),
                              kAbsoluteStorageName),
             HoldingRelayBank(tracer, scope, std::to_string(kAbsoluteBanks[3]),
                              kAbsoluteStorageName)},
      separate_registers_(separate) {}

void AbsoluteStorage::store(std::span<const int> numbers) {
    numbers_.assign(numbers.begin(), numbers.end());
    for (int n : numbers) {
        const Digits d = value_digits(n);
        for (std::size_t i = 0; i < 4; ++i) {
            banks_.at(i).pick(d.at(i));
        }
    }
}

void AbsoluteStorage::clear() {
    numbers_.clear();
    for (auto& b : banks_) {
        b.release_all();
    }
}

bool AbsoluteStorage::conducts_separately(const Digits& counter) const {
    return std::find(numbers_.begin(), numbers_.end(), digits_value(counter)) != numbers_.end();
}

IncrementalStorage::IncrementalStorage(Tracer& tracer, const std::string& scope)
    : banks_{HoldingRelayBank(tracer, scope, std::to_string(kIncrementalBanks[0]),
                              kIncrementalStorageName),
             HoldingRelayBank(tracer, scope, std::to_string(kIncrementalBanks[1]),
                              kIncrementalStorageName),
             HoldingRelayBank(tracer, scope, std::to_string(kIncrementalBanks[2]),
                              kIncrementalStorageName),
             HoldingRelayBank(tracer, scope, std::to_string(kIncrementalBanks[3]),
                              kIncrementalStorageName)} {}

void IncrementalStorage::store(int check) {
    const Digits d = value_digits(check);
    for (std::size_t i = 0; i < 4; ++i) {
        banks_.at(i).pick(d.at(i));
    }
}

void IncrementalStorage::clear() {
    for (auto& b : banks_) {
        b.release_all();
    }
}

} // namespace parsons::relaylogic
