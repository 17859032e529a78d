// An attachment: a later system joined to control cabinet 52, which the 1952 machine does not
// have. parsons carries three, each in a folder of its own (docs/architecture.md):
//   relaylogic/conditions/  condition cards, after EP 0640901 (Siemens)
//   relaylogic/press/       press synchronisation, after EP 0436887 (Mitsubishi)
//   relaylogic/tapping/     spindle synchronisation for tap cards, after EP 0360190 (Mitsubishi)
// The registry (relaylogic/attachments.cpp) builds those a profile asks for, in that order;
// profile parsons-1952 asks for none, and the cabinet then runs the 1952 card cycle alone.
//
// An attachment joins the card cycle only here: the card kind it owns, the events it schedules
// (schedule(), back to on_event()), the hooks below at fixed points of the cycle, what it adds
// to a saved state and to the run's result, and the trace signals it defines when built. Every
// hook does nothing unless the attachment overrides it. The cabinet calls a hook on each
// attachment in the registry's order; what an attachment may do to the cabinet is the public
// part of ControlCabinet headed "For attachments".
#pragma once

#include "axes/lead_screw_axis.hpp"
#include "cardreader/deck_io.hpp"
#include "cardreader/orders.hpp"

#include <nlohmann/json.hpp>

#include <memory>
#include <optional>
#include <string_view>
#include <type_traits>
#include <vector>

namespace parsons::axes {
struct MachineProfile;
}

namespace parsons::relaylogic {

class ControlCabinet;
class Tracer;
class CounterWatch;
struct AxisCircuit;
struct RunResult;
struct Fault;
struct FaultEffect;

class Attachment {
public:
    Attachment() = default;
    Attachment(const Attachment&) = delete;
    Attachment& operator=(const Attachment&) = delete;
    virtual ~Attachment() = default;

    // Its name, and its member of a saved state: "conditions", "press", "tapping".
    virtual std::string_view name() const = 0;

    // The card kind it reads (column 80's extension code), if any.
    virtual std::optional<cardreader::CardKind> card_kind() const { return std::nullopt; }

    // --- the run ---
    // Before the first feed (or the resumed card's): faults, the first scheduled events.
    virtual void start(ControlCabinet& /*cab*/) {}
    // Resuming: pass over the cards read before the saved one. True if it did (the cabinet
    // otherwise skips cards_read() cards of the deck itself).
    virtual bool resume_deck(ControlCabinet& /*cab*/, cardreader::CardSource& /*deck*/) {
        return false;
    }

    // --- the reader and the two banks ---
    // The reader takes its cards through this attachment (at most one may): the next card, or
    // none at the end of the deck. It may stop the machine instead.
    virtual bool supplies_cards() const { return false; }
    virtual std::optional<cardreader::Card> next_card(ControlCabinet& /*cab*/,
                                                      cardreader::CardSource& deck) {
        return deck.next();
    }
    // The deck ended: refuse if something waits for a card that will not come.
    virtual void deck_ended(ControlCabinet& /*cab*/) {}
    // The first bank sensed a card and the card-number check passed (every kind of card).
    virtual void sensed(ControlCabinet& /*cab*/) {}
    // The first bank sensed a card of this attachment's kind: no axis moves by the 1952 columns.
    virtual void read_card(ControlCabinet& /*cab*/) {}
    // The end of that card's reading cycle: true if the reader indexes the next card now
    // (channel 304); false if the attachment carries the card on and ends it (end_card()).
    virtual bool card_read(ControlCabinet& /*cab*/) { return true; }
    // A motion card, sensed: refuse it before anything moves.
    virtual void check_motion_card(ControlCabinet& /*cab*/) {}
    // The holding relays of a motion card picked.
    virtual void relays_picked(ControlCabinet& /*cab*/) {}
    // A motion card read: true if its motion waits (the cabinet does not start the motors).
    virtual bool holds_motion(ControlCabinet& /*cab*/) { return false; }
    // The card's motion is held: no axis is live while it is.
    virtual bool holding() const { return false; }

    // --- impulses, comparers and motors ---
    // An impulse of the axis, before the counters count it (direction: the screw's sense).
    virtual void before_count(ControlCabinet& /*cab*/, AxisCircuit& /*c*/, int /*direction*/) {}
    // After the counters stepped on an impulse: true if it did more than count.
    virtual bool after_count(ControlCabinet& /*cab*/, AxisCircuit& /*c*/) { return false; }
    // Fast-forward is about to jump n quiet impulses of the axis, the first at its next impulse.
    virtual void before_jump(ControlCabinet& /*cab*/, AxisCircuit& /*c*/, double /*t*/) {}
    // Counter readings it watches, which end a fast-forward stretch (nullptr: none).
    virtual const CounterWatch* counter_watch() const { return nullptr; }
    // The axis's motor circuit is held open.
    virtual bool holds_axis(cardreader::Axis /*axis*/) const { return false; }
    // Drives the axis's motor itself (true), or leaves it to speed switch 236 (false). `on`:
    // the 1952 circuit would run it.
    virtual bool drive(ControlCabinet& /*cab*/, AxisCircuit& /*c*/, bool /*on*/) { return false; }

    // --- stops, the sequence and zeroizing ---
    // Members 282 came home: true if zeroizing may go on now (false: it stopped the machine or
    // will call zeroize() itself later).
    virtual bool zeroizing_may_start(ControlCabinet& /*cab*/) { return true; }
    // The zeroizing circuit cleared the 1952 storage and reset device 288.
    virtual void zeroized(ControlCabinet& /*cab*/) {}
    // The machine stopped (master switch 204 open).
    virtual void machine_stopped(ControlCabinet& /*cab*/) {}

    // --- time ---
    // One of its events came due (code: what schedule() was given).
    virtual void on_event(ControlCabinet& /*cab*/, int /*code*/) {}
    // A clock of its own that turns whatever the cabinet does (the press): its next event
    // (axes::kNever: none); in fast-forward, its quiet stretch planned, returning its next
    // event that matters (the one that ends the stretch); its edges before and at an instant;
    // and whether the cabinet waits on it. An attachment has a clock when it overrides
    // next_clock_event (see Hooks below); the cabinet turns one clock at most.
    virtual double next_clock_event(const ControlCabinet& /*cab*/) const { return axes::kNever; }
    virtual double plan_quiet(ControlCabinet& /*cab*/) { return axes::kNever; }
    virtual void clock_edges_before(ControlCabinet& /*cab*/, double /*t*/) {}
    virtual void clock_edges_at(ControlCabinet& /*cab*/, double /*t*/) {}
    virtual bool waited_on(const ControlCabinet& /*cab*/) const { return false; }
    // Plants of its own moved alongside the axes (the spindle): brought up to time t once the
    // axes' quiet impulses before t are taken.
    virtual void advance_plants(ControlCabinet& /*cab*/, double /*t*/) {}

    // --- saved state and result ---
    // Its members of the saved state (the registry writes an absent attachment's).
    virtual void save(const ControlCabinet& /*cab*/, nlohmann::json& /*state*/) const {}
    virtual void load(ControlCabinet& /*cab*/, const nlohmann::json& /*state*/) {}
    virtual void add_to(RunResult& /*result*/) const {}
    // After the run: what an injected fault that acts on its units did (`e` as the cabinet left
    // it; an attachment sets acted and the effect for the faults it carries out).
    virtual void fault_effect(const ControlCabinet& /*cab*/, const Fault& /*f*/,
                              FaultEffect& /*e*/) const {}

    // The hooks that come at every impulse or every instant of the event loop: the cabinet
    // calls each only of the attachments whose class overrides it. The registry records them
    // from the class itself (hooks_of), so they cannot disagree with it.
    struct Hooks {
        bool holding = false;
        bool before_count = false;
        bool after_count = false;
        bool before_jump = false;
        bool holds_axis = false;
        bool drive = false;
        bool clock = false;  // next_clock_event and the clock's other hooks
        bool plants = false; // advance_plants
    };
    const Hooks& hooks() const { return hooks_; }
    void record_hooks(const Hooks& hooks) { hooks_ = hooks; }

private:
    Hooks hooks_;
};

// The hot hooks class A overrides: &A::f names Attachment's own f unless A declares one.
template <class A>
constexpr Attachment::Hooks hooks_of() {
    auto overrides = [](auto of_a, auto of_base) {
        return !std::is_same_v<decltype(of_a), decltype(of_base)>;
    };
    Attachment::Hooks h;
    h.holding = overrides(&A::holding, &Attachment::holding);
    h.before_count = overrides(&A::before_count, &Attachment::before_count);
    h.after_count = overrides(&A::after_count, &Attachment::after_count);
    h.before_jump = overrides(&A::before_jump, &Attachment::before_jump);
    h.holds_axis = overrides(&A::holds_axis, &Attachment::holds_axis);
    h.drive = overrides(&A::drive, &Attachment::drive);
    h.clock = overrides(&A::next_clock_event, &Attachment::next_clock_event);
    h.plants = overrides(&A::advance_plants, &Attachment::advance_plants);
    return h;
}

using Attachments = std::vector<std::unique_ptr<Attachment>>;

// The registry (relaylogic/attachments.cpp): the attachments a profile asks for, built in order
// (each defines its trace signals as it is built).
Attachments make_attachments(Tracer& tracer, const axes::MachineProfile& profile);
// A card of a later kind with no attachment to read it: the machine stops (the registry words it).
void refuse_unattached_card(ControlCabinet& cab, cardreader::CardKind kind);
// A saved state's members for the later systems the profile does not have, and their check on
// resuming (a state from a machine that has one).
void save_absent(const Attachments& present, nlohmann::json& state);
void load_all(ControlCabinet& cab, const Attachments& present, const nlohmann::json& state);

} // namespace parsons::relaylogic
