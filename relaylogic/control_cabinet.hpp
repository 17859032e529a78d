// Control cabinet 52: five axis circuits wired to card reader 134, the card-number check,
// the stepping shaft 280 of the sequence control, balancing circuit 266 and the zeroizing
// circuit 290-304, run event by event in machine time.
//
// A card cycle, as the cabinet runs it (each phase in a file of its own):
//   feed ........ reader 134 takes the next card (zeroizing, channel 304, indexed it)
//   first bank .. spindle 165, motion -> reversing control 214, slow-downs and stop -> banks
//                 350-356, check -> banks 318-324, sequence pattern 222 -> switches 224; the
//                 card number is checked (no numeral in the patent); a bad punch stops the reader
//                 ........................................... control_cabinet_reader.cpp
//   second bank . speed columns -> sensing circuit 250 -> stepping device 252 steps each
//                 speed switch 236 one, two or three times ...... control_cabinet_reader.cpp
//   cycle end ... every axis whose contact is closed under rotary member 282 runs; each
//                 commutator impulse steps the counters and the comparers are read; relay 256
//                 steps switch 236 through delay 258 ............ control_cabinet_comparers.cpp
//                 (fast-forward jumps the impulses that only count, in the same file); each
//                 stop impulse steps shaft 280; after the fifth the members come home past
//                 contact 290 ..........................................
//                 control_cabinet_sequence.cpp and the zeroizing circuit clears storage and the
//                 increment counters, opens the sequence contacts, resets device 288 and feeds a
//                 card
//                 ........................................... control_cabinet_zeroizing.cpp
// Faults (control_cabinet_faults.cpp) and the saved state and result (control_cabinet_state.cpp)
// have files of their own; this file keeps the wiring and the event loop.
//
// Time jumps from event to event: the next commutator impulse of an axis (solved exactly from
// its motion), or the next relay operation in the queue. Nothing polls a clock.
//
// The later systems (condition cards, press synchronisation, tapping) are attachments
// (relaylogic/attachment.hpp): the cabinet calls their hooks at fixed points of the card cycle
// and knows nothing else of them. Profile parsons-1952 has none.
#pragma once

#include "axes/machine_profile.hpp"
#include "axes/spindle_motor.hpp"
#include "cardreader/deck_io.hpp"
#include "cardreader/layout.hpp"
#include "relaylogic/attachment.hpp"
#include "relaylogic/axis_circuit.hpp"
#include "relaylogic/balancing_circuit.hpp"
#include "relaylogic/faults.hpp"
#include "relaylogic/phase_clock.hpp"
#include "relaylogic/run_result.hpp"

#include <csignal>
#include <memory>
#include <optional>
#include <queue>
#include <vector>

namespace parsons::relaylogic {

struct QuietConditions; // relaylogic/fast_forward.hpp

// How the cabinet spends its time. Both give the same machine, event for event: impulse level
// takes every commutator impulse one by one (the reference); fast-forward jumps analytically
// over the stretches of impulses between comparer equalities (relaylogic/fast_forward.hpp), so
// a card costs the same whatever the length of its moves. With an observer attached every
// impulse is written, and fast-forward takes them one by one too.
enum class Pace : std::uint8_t { fast_forward, impulse_level };

class ControlCabinet {
public:
    ControlCabinet(axes::MachineProfile profile, const cardreader::CardLayout& layout);

    // Attach before run(); announces every signal to the observer.
    void attach(MachineObserver* observer);
    // An injected fault (relaylogic/faults.hpp), in force from the start of run().
    void add_fault(Fault fault) { faults_.push_back(std::move(fault)); }
    void set_pace(Pace pace) { pace_ = pace; }
    // Keep each card's start and end time for the result (memory grows with the deck).
    void record_card_times(bool on) { record_times_ = on; }
    // Keep every tap's samples (tool revolutions, feed position) for the thread proof.
    void record_tap_samples(bool on) { record_tap_samples_ = on; }

    // Runs the deck to the end or to a stop, then lets every axis coast to rest. A deck file
    // that cannot be read throws cardreader::DeckError.
    RunResult run(cardreader::CardSource& deck);

    const Tracer& tracer() const { return tracer_; }
    // The later systems this cabinet carries (none under parsons-1952).
    const Attachments& attachments() const { return attachments_; }

    // Saved state. With keep_resume_point on, the machine is captured each time a card is
    // fed; resume_point() is the capture for the last card fed: the state a resumed run starts
    // from, to read that card again. resume() (before attach() and run()) loads such a state:
    // run() then passes over the cards read before it and feeds the next at the saved time.
    void keep_resume_point(bool on) { keep_resume_point_ = on; }
    const nlohmann::json& resume_point() const { return resume_point_; }
    void resume(const nlohmann::json& state);
    // The operator's stop: run() stops the machine at its next event once *flag is non-zero
    // (set by a signal handler).
    void watch_interrupt(const volatile std::sig_atomic_t* flag) { interrupt_ = flag; }
    // The benchmark's clock: run() marks on it each change of phase of the card cycle
    // (relaylogic/phase_clock.hpp). Null (the default): nothing is timed.
    void time_phases(PhaseClock* clock) { phases_ = clock; }

    // --- For attachments (relaylogic/attachment.hpp): what a later system may see and do ---
    double now() const { return now_; }
    Tracer& tracer() { return tracer_; }
    MachineObserver* observer() const { return tracer_.observer(); }
    const axes::MachineProfile& profile() const { return profile_; }
    const cardreader::CardLayout& layout() const { return layout_; }
    const std::vector<Fault>& faults() const { return faults_; }
    bool keeps_tap_samples() const { return record_tap_samples_; }
    bool jumping() const { return jumping_; }
    // The card in the reader: its orders, its place in the run, its name in messages.
    const cardreader::CardOrders& orders() const { return orders_; }
    std::int64_t cards_read() const { return cards_read_; }
    std::string card_name() const;
    AxisCircuit& circuit(cardreader::Axis axis) {
        return *circuits_.at(cardreader::axis_index(axis));
    }
    const std::vector<std::unique_ptr<AxisCircuit>>& circuits() const { return circuits_; }
    // The machine stopped (master switch open), or the deck is not done and no stop came.
    bool stopped() const { return stop_.has_value(); }
    const std::optional<StopInfo>& stop_info() const { return stop_; }
    bool running() const { return !deck_finished_ && !stop_; }
    // One of the attachment's events at time t, passed back to its on_event(code). A standing
    // event outlives the card (the zeroizing circuit does not clear it).
    void schedule(const Attachment& owner, double t, int code, bool standing = false);
    // One that outlives the card and is always handled, clock or none: the instants of a plant
    // of the attachment's own that moves on while the reader feeds (the contouring axes).
    void schedule_lasting(const Attachment& owner, double t, int code);
    void machine_stop(StopReason reason, std::optional<cardreader::Axis> axis,
                      const std::string& message, const std::string& lamp);
    // The axis's motor follows the circuits again; every comparer is read again.
    void update_motor(AxisCircuit& c);
    void update_motors();
    // Spindle control 165 commands the spindle motor (column 1 of the card); the trace shows it.
    // The condition cards' spindle actions drive the same motor, then show it.
    void command_spindle();
    void show_spindle();
    axes::SpindleMotor& spindle_motor() { return spindle_motor_; }
    void evaluate_all() {
        for (auto& c : circuits_) {
            evaluate(*c);
        }
    }
    // An impulse of the axis due now is counted before anything else acts on it (true if one
    // was due).
    bool count_due_impulse(AxisCircuit& c) {
        if (auto impulse = c.plant.advance_to(now_)) {
            on_impulse(c, *impulse);
            return true;
        }
        return false;
    }
    // The card's last motion ended now (condition cards report it).
    void motion_ended() { motion_end_s_ = now_; }
    double motion_end_s() const { return motion_end_s_; }
    // The card-number check expects `number` next (a loop card sends the reader back).
    void expect_card_number(int number) { previous_number_ = (number + 9999) % 10000; }
    // The zeroizing circuit runs now and feeds the next card.
    void zeroize();

private:
    enum class EventKind : std::uint8_t {
        feed,
        first_bank,
        relays_pick,
        second_bank,
        speed_step_252,
        read_complete,
        delay_258_release,
        shaft_step,
        attachment, // an attachment's event (owner, code in axis)
    };
    struct Event {
        double t;
        std::uint64_t seq;
        EventKind kind;
        std::uint8_t owner; // attachment: its place in attachments_
        bool standing;      // attachment: outlives the card
        int axis;
        std::int64_t
            card; // the card it belongs to: the zeroizing circuit ends every pending action
        bool lasting = false; // attachment: outlives the card and the deck (schedule_lasting)
        bool operator>(const Event& o) const { return t != o.t ? t > o.t : seq > o.seq; }
    };

    // control_cabinet.cpp: the wiring and the event loop
    void schedule(double t, EventKind kind, int axis = -1);
    void handle(const Event& e);
    void resume_holds();
    // Called once a loop, only from run(): inlined into it, as when they were its own lines.
    [[gnu::always_inline]] double next_event_time();
    [[gnu::always_inline]] void advance(double t);
    bool clock_running() const { return clock_ != nullptr && running(); }
    bool attachment_holds() const {
        for (const Attachment* a : holders_) {
            if (a->holding()) {
                return true;
            }
        }
        return false;
    }
    bool idle() const;
    bool interrupted();
    // control_cabinet_reader.cpp: the reader and the two banks
    void feed();
    void first_bank();
    bool first_bank_refuses();
    std::optional<cardreader::Card> next_card();
    bool move_within_soft_limits();
    void relays_pick();
    void pick_double_punches(AxisCircuit& c);
    void second_bank();
    void read_complete();
    // control_cabinet_comparers.cpp: impulses, comparers, speed switch 236, fast-forward
    bool live(const AxisCircuit& c) const {
        return balancing_.master_switch_closed() && reading_complete_ && !c.stopped &&
               !c.speed_switch.off() && c.sequence_switch.closed(shaft_.position()) &&
               !attachment_holds();
    }
    // Returns true if the impulse only counted (nothing scheduled, no other axis touched).
    bool on_impulse(AxisCircuit& c, const axes::Impulse& impulse);
    bool evaluate(AxisCircuit& c);
    bool fault_drops(const AxisCircuit& c);
    [[gnu::cold]] void missed_impulse(AxisCircuit& c);
    [[gnu::cold]] void travel_limit(AxisCircuit& c);
    [[gnu::cold]] void soft_limit_watch(AxisCircuit& c);
    double next_axis_event(std::size_t i) const {
        return jumping_ ? quiet_end_[i] : circuits_[i]->plant.next_event_time();
    }
    QuietConditions quiet_conditions(AxisCircuit& c);
    void plan_quiet_stretches();
    void catch_up(double t);
    // Recording: an observer follows every change and motion (a trace, the page's record): the
    // impulses are still taken straight from the plants, each reported as advance() reports it.
    template <bool Recording>
    void run_impulses();
    // The five axes' real positions at t (inches), and the same to the observer that follows
    // motion.
    std::array<double, 5> real_positions(double t) const;
    void report_motion(double t);
    // Impulse level: an axis's quiet impulses still to come, and when to ask again.
    struct QuietRun {
        static constexpr int kFirstWait = 4;     // impulses one by one before asking again
        static constexpr int kLongestWait = 256; // ... at most, however often the answer is none
        std::int64_t quiet = 0;                  // impulses count_quiet_impulse() may take
        int ask_in = 0;                          // impulses one by one before asking
        int wait = kFirstWait;                   // ask_in after the next answer of none
    };
    void ask_quiet(AxisCircuit& c, QuietRun& run);
    template <bool Recording>
    bool impulse_one_by_one(AxisCircuit& c, QuietRun& run);
    [[gnu::always_inline]] bool count_impulse(AxisCircuit& c, const axes::Impulse& impulse,
                                              bool hundredths_only);
    template <bool Recording>
    [[gnu::always_inline]] void count_quiet_impulse(AxisCircuit& c, const axes::Impulse& impulse);
    // control_cabinet_sequence.cpp: stops, stepping shaft 280, the sequence
    void stop_axis(AxisCircuit& c);
    // Balancing circuit 266 through contact 238: an axis whose switch 236 stands on off with
    // one comparer conducting trips it (`when`: what the cabinet was doing). True if it tripped.
    bool watch_balance(AxisCircuit& c, std::string_view when);
    void release_after_stop(const AxisCircuit& c);
    void shaft_step();
    void shaft_home();
    void sequence_stall();
    // control_cabinet_faults.cpp
    void apply_faults(cardreader::CardSource& deck);
    void report_faults();
    std::string slip_effect(const Fault& f, const AxisCircuit& c) const;
    HoldingRelayBank& bank_numbered(AxisCircuit& c, int numeral);
    SteppingSwitch& switch_numbered(AxisCircuit& c, int numeral);
    // control_cabinet_state.cpp
    RunResult result() const;
    // The panel as an operator reads it now, as the trace shows it: indicator 268 if it sounds,
    // lamps 270 and 272 of each axis whose switch 236 stands on off while its comparer conducts
    // (col. 11), then the check lamps of the additions.
    std::vector<std::string> panel_lamps() const;
    nlohmann::json capture() const;

    axes::MachineProfile profile_;
    const cardreader::CardLayout& layout_;
    Tracer tracer_;
    std::vector<std::unique_ptr<AxisCircuit>> circuits_;
    SteppingShaft shaft_;
    BalancingCircuit balancing_;
    std::vector<Fault> faults_;
    std::vector<FaultEffect> effects_;
    std::unique_ptr<FaultyFeed> faulty_feed_;
    double min_interval_s_; // 1 / the stepping switches' fastest rate
    Pace pace_ = Pace::fast_forward;
    bool jumping_ = false;                                     // fast-forward with no observer
    bool follows_motion_ = false;                              // the observer follows motion
    std::array<std::int64_t, cardreader::kAxisCount> quiet_{}; // quiet impulses ahead of each axis
    std::array<double, cardreader::kAxisCount> quiet_end_{};   // when the stretch's next event is

    std::priority_queue<Event, std::vector<Event>, std::greater<>> queue_;
    std::uint64_t seq_ = 0;
    int standing_queued_ = 0; // standing events in the queue (an attachment's clock)
    // The latest delay-258 release after a stop that was not queued (no observer), or -inf.
    double unqueued_release_s_ = -axes::kNever;
    bool keep_resume_point_ = false;
    bool resuming_ = false;
    nlohmann::json resume_point_;
    const volatile std::sig_atomic_t* interrupt_ = nullptr;
    PhaseClock* phases_ = nullptr;
    static Phase phase_of(EventKind kind);
    void mark(Phase p) {
        if (phases_ != nullptr) {
            phases_->enter(p);
        }
    }
    double now_ = 0;
    cardreader::CardSource* deck_ = nullptr;
    std::optional<cardreader::Card> card_;
    cardreader::CardOrders orders_;
    // Relays a double-punched digit column picks beyond the orders' digit (card_reader.hpp).
    std::array<std::array<std::array<std::uint16_t, 4>, 4>, cardreader::kAxisCount> extra_relays_{};
    std::optional<int> previous_number_; // the card-number check (no numeral)
    bool reading_complete_ = false;
    bool deck_finished_ = false;
    int last_sequence_position_ = 5;
    std::int64_t cards_read_ = 0;
    bool record_times_ = false;
    bool record_tap_samples_ = false;
    std::vector<CardTiming> timings_;
    std::optional<StopInfo> stop_;
    double motion_end_s_ = 0; // when this card's last axis stopped

    // The later systems: their hooks are called in this order. own_card_: the attachment whose
    // kind of card is in the reader (none for a motion card); supplier_: the one the reader
    // takes its cards through, if any. The hot hooks (Attachment::Hooks) are called only of
    // those that have them, from a list of their own, in the same order: those whose hold
    // keeps every axis dead, that see an impulse before or after it is counted or a jump of them,
    // that hold an axis's motor circuit open, that drive a motor, that turn a clock (the press) and
    // that move plants of their own (the spindle).
    Attachments attachments_;
    Attachment* own_card_ = nullptr;
    Attachment* supplier_ = nullptr;
    std::vector<const Attachment*> holders_;
    std::vector<Attachment*> before_count_;
    std::vector<Attachment*> after_count_;
    std::vector<Attachment*> before_jump_;
    std::vector<const Attachment*> axis_holders_;
    std::vector<Attachment*> drivers_;
    Attachment* clock_ = nullptr;           // at most one
    double clock_quiet_end_ = axes::kNever; // fast-forward: the clock's next event that matters
    std::vector<Attachment*> plants_;
    std::vector<const CounterWatch*> counter_watches_;

    SignalId reader_card_;
    SignalId reader_feeding_;
    SignalId card_number_check_;
    SignalId spindle_165_;
    SignalId cutting_;
    // The spindle motor that column 1 commands through spindle control 165: it runs down and up
    // in the profile's times (actions.spindle_run_down_s, spindle_run_up_s), not at once.
    axes::SpindleMotor spindle_motor_;
    SignalId spindle_motor_signal_;
    bool spindle_changing_ = false; // the trace shows it between speeds
    SignalId zeroizing_;
    SignalId channel_294_;
    SignalId channel_298_;
    SignalId channel_300_;
    SignalId channel_302_;
    SignalId channel_304_;
};

} // namespace parsons::relaylogic
