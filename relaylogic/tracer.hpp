// The signal registry and the trace hook every component reports through.
//
// Each component defines its signals once (name, patent numeral, width, initial value) and
// calls set() when one changes. With no observer attached, set() is a single test of a null
// pointer: nothing is stored, formatted or compared.
#pragma once

#include "relaylogic/machine_observer.hpp"

#include <nlohmann/json.hpp>

#include <vector>

namespace parsons::relaylogic {

class Tracer {
public:
    SignalId define(std::string scope, std::string name, std::string component, std::string numeral,
                    int width, std::uint32_t initial = 0);

    // Attaches an observer (or none) and announces every signal defined so far.
    void attach(MachineObserver* observer);
    MachineObserver* observer() const { return observer_; }

    void set_time(double seconds) { now_ = seconds; }
    double now() const { return now_; }

    [[gnu::always_inline]] void set(SignalId id, std::uint32_t value) {
        // An unchanged value is no event: judged here, where the call is inlined, so that the
        // many set() calls that change nothing cost a comparison (the commutator contact sets
        // are re-set at every impulse). A change goes out of line: inlined, the change log's
        // appends made the impulse loop that sets nothing ~18 instructions an impulse longer
        // (docs/performance.md).
        if (observer_ != nullptr && values_[id] != value) [[unlikely]] {
            report(id, value);
        }
    }

    const std::vector<SignalInfo>& signals() const { return infos_; }
    // Every signal's value by name ("table.absolute_counter_104": 8). Kept only while an
    // observer is attached: a run that saves its state attaches one.
    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    // A changed value to the observer: appended to its change log if it keeps one, else
    // on_signal().
    [[gnu::noinline]] void report(SignalId id, std::uint32_t value);

    MachineObserver* observer_ = nullptr;
    ChangeLog* log_ = nullptr; // the observer's change log, if it keeps one
    double now_ = 0;
    std::vector<SignalInfo> infos_;
    std::vector<std::uint32_t> values_;
};

} // namespace parsons::relaylogic
