// The story of a run told from its trace: what each axis's relays did on each card, in the
// operator's words with the patent's numerals, and the chain of relay events that led to a stop
// ("card 1, table: motor 38 started on speed 1; at 3.503 the absolute comparer 122' met
// slow-down 1 and relay 256 stepped 236 to speed 2; ...").
//
// It is an observer of the machine like any trace (relaylogic/machine_observer.hpp), and it
// decides nothing: every event it tells is one the cabinet made. It only names what it hears:
// which punched number a counter reading is, which speed switch 236 stood on. `parsons check`
// and `parsons show` tell it (docs/check.md); it follows no impulse, so the run it hears may
// fast-forward.
#pragma once

#include "cardreader/orders.hpp"
#include "relaylogic/machine_observer.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace parsons::cli {

// One thing the run did that a deck's author should know about, on one card and axis: an
// equality at a number no field punches (the shared banks 350-356), a stop number met on a
// speed that only slows the axis, an axis that came to rest away from its stop.
struct StoryNote {
    std::int64_t card = 0; // deck position, 1-based
    int number = -1;       // the card number punched on it
    std::optional<cardreader::Axis> axis;
    std::string message;
};

class MachineStory : public relaylogic::MachineObserver {
public:
    bool follows_impulses() const override { return true; }
    bool follows_motion() const override { return false; }
    void on_signal_defined(const relaylogic::SignalInfo& info, std::uint32_t initial) override;
    void on_signal(double t, relaylogic::SignalId id, std::uint32_t old_value,
                   std::uint32_t new_value) override;
    void on_card(double t, std::int64_t index, const cardreader::CardOrders& orders) override;
    void on_stop(double t, const relaylogic::StopInfo& stop) override;
    void on_finish(double t) override;

    // The chain of relay events that led to the stop: the card before the stop's card and the
    // stop's card, for the stop's axis (or each axis that ran on them when no axis stopped the
    // machine), then the stop itself. Empty when the run did not stop.
    std::vector<std::string> stop_chain() const;
    // What the run did that the deck's author should know, card by card (see StoryNote).
    const std::vector<StoryNote>& notes() const { return notes_; }

private:
    // What one signal is to the story.
    enum class Part : std::uint8_t {
        none,
        speed_switch_236,
        motor,
        absolute_comparer,
        incremental_comparer,
        delay_258,
        absolute_counter,
        increment_counter,
        lamp,
    };
    struct Signal {
        Part part = Part::none;
        int axis = -1; // 0..4, or -1 for a shared part
        int digit = 0; // a counter's place: 0 thousandths .. 3 inches
        std::string numeral;
        std::uint32_t value = 0;
    };
    // One axis on one card: its phrases in order, and what the instant being heard holds.
    struct AxisTale {
        bool ran = false;
        std::vector<std::string> phrases;
        // The instant being gathered (signals of one axis change together at one instant).
        double instant = -1;
        bool absolute_met = false;
        bool increment_met = false;
        std::optional<std::uint32_t> speed_before; // 236 before the instant's first step
        bool motor_started = false;
        bool motor_stopped = false;
        bool delay_held = false; // delay 258 held channel 257 open as the instant began
        std::vector<std::string> lamps;
        int equalities = 0;        // absolute equalities told on this card
        std::optional<int> off_at; // the reading as its motor was last switched off
    };
    struct CardTale {
        std::int64_t index = 0;
        int number = -1;
        cardreader::CardOrders orders;
        std::array<AxisTale, cardreader::kAxisCount> axes;
    };

    void close_instant(int axis);
    void close_card();
    int reading(int axis, Part counter) const; // thousandths, as the counter's switches stand
    std::string label(int axis, int reading) const;
    std::string speed_name(std::uint32_t speed) const;
    std::vector<std::string> tale_lines(const CardTale& card,
                                        const std::optional<cardreader::Axis>& axis) const;

    std::vector<Signal> signals_;
    std::array<std::array<std::uint32_t, 4>, cardreader::kAxisCount> absolute_{};
    std::array<std::array<std::uint32_t, 4>, cardreader::kAxisCount> increment_{};
    std::array<std::uint32_t, cardreader::kAxisCount> speed_{};
    std::array<std::string, cardreader::kAxisCount> motor_numeral_{};
    std::array<bool, cardreader::kAxisCount> delay_held_{};
    std::array<bool, cardreader::kAxisCount> absolute_on_{}; // comparer 122' conducting
    std::optional<CardTale> previous_;
    std::optional<CardTale> current_;
    std::optional<relaylogic::StopInfo> stop_;
    std::optional<CardTale> stop_previous_; // the two cards of the stop, kept when it came
    std::optional<CardTale> stop_card_;
    std::vector<StoryNote> notes_;
};

} // namespace parsons::cli
