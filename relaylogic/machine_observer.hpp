// The trace hook: every relay, stepping switch, lamp and motor of the cabinet is a signal; a
// MachineObserver hears each signal defined once, then every change, in machine time.
//
// Components never print. They own their state and report changes through a Tracer, which
// does nothing but a null test when no observer is attached, so the hot path pays nothing
// for tracing it does not use. The CLI turns observers into VCD, JSON lines, CSV and plots.
#pragma once

#include "cardreader/orders.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace parsons::cardreader {
class Card;
struct CardLayout;
} // namespace parsons::cardreader

namespace parsons::relaylogic {

using SignalId = std::uint32_t;

struct SignalInfo {
    SignalId id = 0;
    std::string scope;     // "table", "cabinet": one VCD scope per axis plus the shared parts
    std::string name;      // "absolute_storage_352.relay_7", "speed_switch_236"
    std::string component; // "absolute storage bank 352"
    std::string numeral;   // the patent's reference numeral: "352"
    int width = 1;         // bits: 1 for a relay, 4 for a ten-position stepping switch
};

// Why the machine stopped itself (docs/design-rules.md, Interfaces; docs/stop-codes.md).
enum class StopReason : std::uint8_t {
    out_of_order_card,
    check_mismatch,
    missed_impulse,
    sequence_stall,
    bad_punch,
    soft_limit,        // the job's movement range (soft limits, after EP 0360190; an addition)
    limit_switch,      // a part reached a travel-limit switch (travel_min_in / travel_max_in; an
                       // addition)
    condition_not_met, // a condition card's condition was not met by the end of its motion card
    condition_refused, // the cabinet cannot take a condition card (profile, deck, buffer)
    tool_change_interlock, // a tool change tripped while the spindle is commanded to turn
    sync_timeout,          // press synchronisation: the crank never came, or stood (an addition)
    sync_refused,          // the cabinet cannot take a sync card (profile, deck)
    transfer_timeout, // spindle sync: PC 130's gear ratio transfer never completed (an addition)
    tap_refused,      // the cabinet cannot take a tap card (profile, tool, speed)
    segment_refused,  // the cabinet cannot take a segment card (profile: no contouring)
    interrupted,      // not a check: the operator stopped the run (SIGINT, SIGTERM)
};

std::string_view stop_reason_name(StopReason r);

struct StopInfo {
    StopReason reason = StopReason::check_mismatch;
    std::int64_t card = 0;                // position in the deck, 1-based
    int card_number = -1;                 // the number punched on it, if it could be read
    std::optional<cardreader::Axis> axis; // the axis that stopped the machine, if one did
    std::string message;                  // one sentence an operator understands
    std::vector<std::string> lamps;       // "lamp 270 (absolute comparer conducting)", ...
};

// What the condition units (an addition after EP 0640901, Siemens) report, each by its event
// identifier (claim 3): PRG found the condition met, ALE initiated the action, the action was
// acknowledged.
enum class ConditionEventKind : std::uint8_t { met, action_started, acknowledged };

std::string_view condition_event_name(ConditionEventKind k); // "condition_met", ...

struct ConditionEvent {
    ConditionEventKind kind = ConditionEventKind::met;
    int event = 0;
    std::int64_t card = 0; // the motion card being machined (deck position)
    int card_number = -1;  // its number
    std::int64_t condition_card = 0;
    cardreader::Axis axis = cardreader::Axis::table;
    cardreader::Thousandths position = 0;
    cardreader::PassingSense sense = cardreader::PassingSense::either;
    cardreader::ActionKind action = cardreader::ActionKind::lamp;
    int parameter = 0;
    int tool_in_spindle = 0; // after the event
    // An every-condition (an addition beyond EP 0640901's claims): which firing, 1, 2, ...;
    // 0 for a once-condition.
    int firing = 0;
};

// Every signal change as it came, in three arrays: what an observer that keeps the changes as
// they are (the exhibit page's record) hands the tracer, which then appends to it itself, in
// bulk, instead of calling on_signal() once a change (docs/web.md, the recorded run).
struct ChangeLog {
    std::vector<double> t;
    std::vector<std::uint32_t> id;
    std::vector<std::uint32_t> value;
    std::size_t limit = 0;  // changes kept at most; those after are counted as lost
    bool truncated = false; // a change came past the limit

    [[gnu::always_inline]] void append(double seconds, std::uint32_t signal, std::uint32_t v) {
        if (t.size() >= limit) {
            truncated = true;
            return;
        }
        t.push_back(seconds);
        id.push_back(signal);
        value.push_back(v);
    }
};

class MachineObserver {
public:
    virtual ~MachineObserver() = default;
    // Called once per signal before the run starts, with the signal's initial value.
    virtual void on_signal_defined(const SignalInfo& /*info*/, std::uint32_t /*initial*/) {}
    // Called after all signals are defined; time starts at 0.
    virtual void on_start() {}
    virtual void on_signal(double /*seconds*/, SignalId /*id*/, std::uint32_t /*old_value*/,
                           std::uint32_t /*new_value*/) {}
    // The real positions of the five axes changed (at every commutator impulse and when an
    // axis comes to rest); inches.
    virtual void on_motion(double /*seconds*/, const std::array<double, 5>& /*real_in*/) {}
    // The run begins (the reader about to feed, a saved state already loaded): where the five
    // axes stand, inches. Only to an observer that follows motion; a replay starts its picture
    // there, so that every instant before the first motion has one.
    virtual void on_run_start(double /*seconds*/, const std::array<double, 5>& /*real_in*/) {}
    // The first bank of brushes senses a card (deck position 1-based; a step of five cards as
    // the one card they make): its holes, and the layout its columns are wired by. Before the
    // card's checks, so a card the reader then refuses is seen too.
    virtual void on_brushes(double /*seconds*/, std::int64_t /*index*/,
                            const cardreader::Card& /*card*/,
                            const cardreader::CardLayout& /*layout*/) {}
    // A card was read and decoded (deck position 1-based).
    virtual void on_card(double /*seconds*/, std::int64_t /*index*/,
                         const cardreader::CardOrders&) {}
    // The machine stopped itself.
    virtual void on_stop(double /*seconds*/, const StopInfo& /*stop*/) {}
    // A condition was met, its action initiated or acknowledged (condition cards, an addition).
    virtual void on_condition(double /*seconds*/, const ConditionEvent& /*event*/) {}
    // The run is over (completed or stopped and every axis at rest).
    virtual void on_finish(double /*seconds*/) {}
    // Does this observer follow every signal change and motion as it happens (a trace, a
    // path)? One that only wants cards, stops and the finish says no, and the cabinet may then
    // fast-forward: the signal changes it is sent come a stretch of impulses at a time.
    virtual bool follows_impulses() const { return true; }
    // Its change log, if it keeps every change as it came and nothing more: the tracer appends
    // each change there and calls on_signal() no more. nullptr: on_signal() at each change.
    virtual ChangeLog* change_log() { return nullptr; }
    // Does it want on_motion? An observer that ignores motion says no (overrides this), and
    // the cabinet then does not work out the five real positions at every impulse for it.
    virtual bool follows_motion() const { return true; }
};

// Sends every call to several observers, in order.
class ObserverFanOut : public MachineObserver {
public:
    void add(MachineObserver* o) { observers_.push_back(o); }
    bool empty() const { return observers_.empty(); }
    // What to attach: the one observer itself when there is only one (no relay of every
    // event through this fan-out), else the fan-out.
    MachineObserver* attachable() { return observers_.size() == 1 ? observers_.front() : this; }
    bool follows_impulses() const override {
        for (auto* o : observers_) {
            if (o->follows_impulses()) {
                return true;
            }
        }
        return false;
    }
    bool follows_motion() const override {
        for (auto* o : observers_) {
            if (o->follows_motion()) {
                return true;
            }
        }
        return false;
    }
    void on_signal_defined(const SignalInfo& info, std::uint32_t initial) override {
        for (auto* o : observers_) {
            o->on_signal_defined(info, initial);
        }
    }
    void on_start() override {
        for (auto* o : observers_) {
            o->on_start();
        }
    }
    void on_signal(double t, SignalId id, std::uint32_t a, std::uint32_t b) override {
        for (auto* o : observers_) {
            o->on_signal(t, id, a, b);
        }
    }
    void on_motion(double t, const std::array<double, 5>& real) override {
        for (auto* o : observers_) {
            o->on_motion(t, real);
        }
    }
    void on_run_start(double t, const std::array<double, 5>& real) override {
        for (auto* o : observers_) {
            o->on_run_start(t, real);
        }
    }
    void on_brushes(double t, std::int64_t index, const cardreader::Card& card,
                    const cardreader::CardLayout& layout) override {
        for (auto* o : observers_) {
            o->on_brushes(t, index, card, layout);
        }
    }
    void on_card(double t, std::int64_t index, const cardreader::CardOrders& orders) override {
        for (auto* o : observers_) {
            o->on_card(t, index, orders);
        }
    }
    void on_stop(double t, const StopInfo& stop) override {
        for (auto* o : observers_) {
            o->on_stop(t, stop);
        }
    }
    void on_finish(double t) override {
        for (auto* o : observers_) {
            o->on_finish(t);
        }
    }
    void on_condition(double t, const ConditionEvent& e) override {
        for (auto* o : observers_) {
            o->on_condition(t, e);
        }
    }

private:
    std::vector<MachineObserver*> observers_;
};

} // namespace parsons::relaylogic
