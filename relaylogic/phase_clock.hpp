// Where a run's time goes, by phase of the card cycle: for `parsons bench` (docs/performance.md).
// The cabinet marks each change of phase on the clock it is given (none: no cost but a null
// test); the clock adds the ticks between marks to the phase in force.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <string_view>

#if defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>
#endif

namespace parsons::relaylogic {

enum class Phase : std::uint8_t {
    setup,         // before the first card: the profile, the deck opened, the outputs made
    read_decode,   // the reader takes a card: the file's bytes read, the columns decoded
    reader_relays, // the reader cycle: feed, the two brush banks, the holding relays, 252's steps
    motion,        // the axes: planning the quiet stretches, impulses, comparers, speed switches
    sequence,      // sequence shaft 280 and the zeroizing circuit
    attachments,   // the later systems' own events (condition cards, press, spindle)
    report,        // after the last card: the result, the summary and the outputs
};
inline constexpr std::size_t kPhases = 7;

constexpr std::string_view phase_name(Phase p) {
    switch (p) {
    case Phase::setup:
        return "setup";
    case Phase::read_decode:
        return "read and decode";
    case Phase::reader_relays:
        return "reader cycle's relays";
    case Phase::motion:
        return "axes' motion";
    case Phase::sequence:
        return "sequence and zeroizing";
    case Phase::attachments:
        return "attachments";
    case Phase::report:
        return "report";
    }
    return "?";
}

class PhaseClock {
public:
    // A cheap monotonic count: the time-stamp counter where there is one, else nanoseconds.
    static std::uint64_t ticks() {
#if defined(__x86_64__) || defined(__i386__)
        return __rdtsc();
#else
        return static_cast<std::uint64_t>(
            std::chrono::steady_clock::now().time_since_epoch().count());
#endif
    }

    void start(Phase p) {
        current_ = p;
        since_ = ticks();
    }
    // From now on the time is `p`'s; the previous phase in force is returned.
    Phase enter(Phase p) {
        const std::uint64_t now = ticks();
        spent_.at(static_cast<std::size_t>(current_)) += now - since_;
        since_ = now;
        const Phase was = current_;
        current_ = p;
        return was;
    }
    void stop() {
        enter(current_);
    }

    std::uint64_t spent(Phase p) const {
        return spent_.at(static_cast<std::size_t>(p));
    }
    std::uint64_t total() const {
        std::uint64_t n = 0;
        for (std::uint64_t s : spent_) {
            n += s;
        }
        return n;
    }

private:
    std::array<std::uint64_t, kPhases> spent_{};
    Phase current_ = Phase::setup;
    std::uint64_t since_ = 0;
};

// Marks `p` on `clock` (if any) for the life of this object, then gives the time back to the
// phase that was in force.
class InPhase {
public:
    InPhase(PhaseClock* clock, Phase p) : clock_(clock) {
        if (clock_ != nullptr) {
            was_ = clock_->enter(p);
        }
    }
    ~InPhase() {
        if (clock_ != nullptr) {
            clock_->enter(was_);
        }
    }
    InPhase(const InPhase&) = delete;
    InPhase& operator=(const InPhase&) = delete;

private:
    PhaseClock* clock_;
    Phase was_ = Phase::setup;
};

} // namespace parsons::relaylogic
