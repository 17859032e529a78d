// Control cabinet 52: five axis circuits wired to card reader 134, the card-number check,
// the stepping shaft 280 of the sequence control, balancing circuit 266 and the zeroizing
// circuit 290-304, run event by event in machine time.
//
// A card cycle, as the cabinet runs it:
//   feed ........ reader 134 takes the next card (zeroizing, channel 304, indexed it)
//   first bank .. spindle 165, motion -> reversing control 214, slow-downs and stop -> banks
//                 350-356, check -> banks 318-324, sequence pattern 222 -> switches 224; the
//                 card number is checked (no numeral in the patent); a bad punch stops the reader
//   second bank . speed columns -> sensing circuit 250 -> stepping device 252 steps each
//                 speed switch 236 one, two or three times
//   cycle end ... every axis whose contact is closed under rotary member 282 runs; each stop
//                 impulse steps shaft 280; after the fifth the members come home past
//                 contact 290 and the zeroizing circuit clears storage and the increment
//                 counters, opens the sequence contacts, resets device 288 and feeds a card.
//
// Time jumps from event to event: the next commutator impulse of an axis (solved exactly from
// its motion), or the next relay operation in the queue. Nothing polls a clock.
#pragma once

#include "axes/machine_profile.hpp"
#include "cardreader/deck_io.hpp"
#include "cardreader/layout.hpp"
#include "relaylogic/axis_circuit.hpp"
#include "relaylogic/balancing_circuit.hpp"
#include "relaylogic/conditions/condition_units.hpp"
#include "relaylogic/faults.hpp"
#include "relaylogic/press/sync_units.hpp"
#include "relaylogic/tapping/tapping_units.hpp"

#include <csignal>
#include <map>
#include <memory>
#include <optional>
#include <queue>
#include <vector>

namespace parsons::relaylogic {

struct AxisResult {
    double counter_in = 0;                   // what absolute counter 104-110 reads
    double real_in = 0;                      // where the part really is
    double error_in = 0;                     // real - counter, the counter's wraps counted
    std::int64_t impulses = 0;               // commutator 102 impulses the screw produced
    std::int64_t lost_steps = 0;             // impulses the stepping switches could not follow
    std::optional<double> fixture_angle_deg; // swivel and tilt
    std::optional<double> last_stop_in;      // the stop of the last card read, if any
    double slip_in = 0;                      // a slip fault: how far the part lags the screw
    double screw_in = 0;                     // the main screw's travel (turns x lead)
    int skipped_steps = 0;                   // skip faults that acted on its switches
};

struct CardTiming {
    std::int64_t index = 0;
    int number = -1;
    double start_s = 0;
    double end_s = 0;
};

// Press synchronisation (an addition after EP 0436887): the press and the job's cycles.
struct PressResult {
    int revolution = 0;          // the crank's revolution (1 = the first)
    double crank_angle_deg = 0;  // where crank 21 stood at the last detector edge taken
    int position_register = 0;   // register 14, detector pulses
    bool press_stopped = false;  // motor 22 stopped (the profile's stop)
    std::int64_t cycles = 0;     // how many times the job reached its loop card (M99)
    std::int64_t loop_backs = 0; // how many times the reader went back
    // Time between two loop-backs: the job's cycle (none with fewer than two loop-backs).
    std::optional<double> mean_cycle_s;
    std::optional<double> shortest_cycle_s;
    std::optional<double> longest_cycle_s;
    double waited_s = 0; // machine time cards spent held by position reader 60
};

struct RunResult {
    bool completed = false;
    std::int64_t cards_read = 0;
    double machine_seconds = 0;
    std::optional<StopInfo> stop;
    std::array<AxisResult, cardreader::kAxisCount> axes{};
    std::vector<CardTiming> cards;   // each card's machine time, if asked for (record_card_times)
    std::vector<FaultEffect> faults; // what each injected fault did
    // Condition cards (an addition): the actions acknowledged, and the tool in the spindle.
    std::vector<ActionRecord> actions;
    std::optional<int> tool_in_spindle;   // when the profile has a tool changer
    std::optional<PressResult> press;     // when the profile has press synchronisation
    std::optional<TappingResult> tapping; // when the profile has spindle synchronisation
};

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
        action_done,     // an action of ALE is done (axis: its channel)
        reference_block, // press synchronisation: a reference block of Fig. 6 (any card)
        sync_release,    // detector 61 conducted: 60's hold relay drops
        pc_scan,         // spindle synchronisation: a scan of PC 130 (a tap card's tool call)
        spindle_sample,  // spindle synchronisation: a sample of encoder interface 33
    };
    struct Event {
        double t;
        std::uint64_t seq;
        EventKind kind;
        int axis;
        std::int64_t
            card; // the card it belongs to: the zeroizing circuit ends every pending action
        bool operator>(const Event& o) const { return t != o.t ? t > o.t : seq > o.seq; }
    };

    void schedule(double t, EventKind kind, int axis = -1);
    void handle(const Event& e);
    void feed();
    void first_bank();
    void relays_pick();
    void read_complete();
    double next_axis_event(std::size_t i) const;
    void plan_quiet_stretches();
    void catch_up(double t);
    void run_impulses();
    // Returns true if the impulse only counted (nothing scheduled, no other axis touched).
    bool on_impulse(AxisCircuit& c, const axes::Impulse& impulse);
    bool evaluate(AxisCircuit& c);
    bool fault_drops(const AxisCircuit& c);
    void apply_faults(cardreader::CardSource& deck);
    void report_faults();
    std::string slip_effect(const Fault& f, const AxisCircuit& c) const;
    HoldingRelayBank& bank_numbered(AxisCircuit& c, int numeral);
    SteppingSwitch& switch_numbered(AxisCircuit& c, int numeral);
    [[gnu::cold]] void missed_impulse(AxisCircuit& c);
    [[gnu::cold]] void travel_limit(AxisCircuit& c);
    [[gnu::cold]] void soft_limit_watch(AxisCircuit& c);
    bool move_within_soft_limits();
    bool live(const AxisCircuit& c) const;
    void stop_axis(AxisCircuit& c);
    void release_after_stop(const AxisCircuit& c);
    void shaft_step();
    void shaft_home();
    void zeroize();
    void condition_card();
    bool conditions_met(AxisCircuit& c);
    void acknowledge(int channel);
    void tell(int channel, ConditionEventKind kind);
    std::optional<cardreader::Card> next_card();
    void sync_card();
    void loop_card();
    void press_edges(double t);
    void reference_block();
    void sync_release();
    bool press_running() const { return sync_.present() && !deck_finished_ && !stop_; }
    bool waiting_on_press() const;
    bool idle() const;
    void schedule_block();
    void resume_tape(std::int64_t taken);
    nlohmann::json capture_sync() const;
    void resume_sync(const nlohmann::json& j);
    void tap_card();
    void start_tool_call();
    void pc_scan();
    void spindle_sample();
    void spindle_edges(double t);
    void tap_counting_sense(AxisCircuit& c, int direction);
    void update_motors();
    void update_motor(AxisCircuit& c);
    void machine_stop(StopReason reason, std::optional<cardreader::Axis> axis,
                      const std::string& message, const std::string& lamp);
    void sequence_stall();
    RunResult result() const;
    nlohmann::json capture() const;
    bool interrupted();
    std::string card_name() const;

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
    std::array<std::int64_t, cardreader::kAxisCount> quiet_{}; // quiet impulses ahead of each axis
    std::array<double, cardreader::kAxisCount> quiet_end_{};   // when the stretch's next event is

    std::priority_queue<Event, std::vector<Event>, std::greater<>> queue_;
    std::uint64_t seq_ = 0;
    // The latest delay-258 release after a stop that was not queued (no observer), or -inf.
    double unqueued_release_s_ = -axes::kNever;
    bool keep_resume_point_ = false;
    bool resuming_ = false;
    nlohmann::json resume_point_;
    const volatile std::sig_atomic_t* interrupt_ = nullptr;
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
    // Condition cards (an addition): the seed's units, the card being a condition card, the
    // zeroizing circuit waiting for acknowledgements, when this card's last axis stopped.
    ConditionUnits conditions_;
    bool condition_card_ = false;
    bool zeroize_waiting_ = false;
    double motion_end_s_ = 0;
    std::vector<ActionRecord> actions_;
    // Press synchronisation (an addition): the units, the card being a sync card, the cards the
    // reader has taken (a loop card sends it back among them, as round a ribbon made into an
    // endless loop), the reference blocks, fast-forward's quiet detector edges.
    SyncUnits sync_;
    bool sync_card_ = false;
    std::vector<cardreader::Card> tape_;
    std::vector<int> tape_numbers_;
    std::size_t replay_ = 0;      // the next card comes from tape_[replay_] if within it
    std::size_t tape_index_ = 0;  // the card in the reader
    std::int64_t deck_taken_ = 0; // cards taken from the deck itself
    std::map<std::size_t, int> loops_left_;
    std::int64_t cycles_ = 0;
    std::int64_t loop_backs_ = 0;
    double last_loop_back_s_ = 0;
    double first_loop_back_s_ = 0;
    double shortest_cycle_s_ = 0;
    double longest_cycle_s_ = 0;
    double waited_s_ = 0;
    std::int64_t block_ = 1;       // the reference block queued next: at block_ x speed_sample_s
    int blocks_queued_ = 0;        // reference blocks in the queue (0 or 1)
    std::int64_t press_quiet_ = 0; // fast-forward: edges that only count, ahead of the press
    double press_quiet_end_ = axes::kNever; // ... and when the press's next event that matters is

    // Spindle synchronisation (an addition): the units, the card being a tap card.
    TappingUnits tapping_;
    bool tap_card_ = false;

    SignalId reader_card_;
    SignalId reader_feeding_;
    SignalId card_number_check_;
    SignalId spindle_165_;
    SignalId cutting_;
    SignalId zeroizing_;
    SignalId channel_294_;
    SignalId channel_298_;
    SignalId channel_300_;
    SignalId channel_302_;
    SignalId channel_304_;
};

} // namespace parsons::relaylogic
