// The spindle synchronisation of EP 0360190 (Mitsubishi) wired into the cabinet:
// spindle motor 27 with encoder 32, gear unit 30 and heads 31 (axes/spindle.hpp), programmable
// controller 130 and bus 35 (programmable_controller.hpp), gear ratio data memory 12a with the
// NC's side of the handshake (gear_ratio_memory.hpp), spindle encoder interface 33 (direction
// judging device 13, position register 14 and speed register 11 of the press synchronisation,
// reused on encoder 32), and the seed's "synchronous operation control means", which feeds one
// axis in step with the tool. An addition, not in the 1952 patent: present only when the
// profile has spindle synchronisation (parsons-extended).
//
// A tap card, as the cabinet runs it:
//   read complete ... the NC puts the card's tool T on bus 35 (the tool specifying signal);
//                     PC 130 scans every pc_scan_s: exchanges the head if another is on,
//                     transfers the ratio to 12a (first embodiment) or the NC selects the one
//                     stored for T (second); a transfer not done within transfer_timeout_s of
//                     its request stops the machine (transfer_timeout)
//   tool ready ...... motor 27 is commanded forward at S; every sample_s the NC reads interface
//                     33 (the encoder's net edges d and the edges of the last sample n) and the
//                     feed axis's absolute counter, and sets the follower drive (the sync drive
//                     of the profile) to
//                         v = d / ppr x A x pitch / sample_s  +  gain x (z_cmd - z_counted)
//                     where z_cmd, the depth the tool's turns call for, grows by d / ppr x A x
//                     pitch each sample (S x A: A is the ratio in 12a, right or stale)
//   index wait ...... (rigid tapping, an addition; column 19) motor 27 turns, the feed stands
//                     until the index of encoder 32 at which the tool has its angle of every
//                     pass (A = 1/n: every n-th index); z_cmd counts from that edge
//   near the depth .. the speed measured from the times of the last sample's edges; when the
//                     depth left, less what motor 27 covers running down from that speed, comes
//                     within a sample's travel, the NC times the reversal (-S) for the instant it
//                     is due: the motor runs down, stops at the depth (within an edge) and runs
//                     up backwards; the feed follows it out
//   near the top .... the same, commanding the motor to rest; once it stands, the feed creeps
//                     to the counter reading it started from and stops (the card ends there)
//   peck ............ (rigid peck tapping, an addition; columns 21-24) the first pass reverses
//                     at Q, not the depth; with the feed on its starting count motor 27 runs
//                     forward at S again, in to 2Q, and so on to the depth. z_cmd is not reset:
//                     the feed follows the same count of encoder 32's edges, one helix
//   end ............. the NC drops the tool call; the zeroizing circuit indexes the next card
//
// Emulation notes: the counters of the feed axis count the way the drive really turns during a
// tap (the NC sets reversing control 214 from the drive's sense). The feed's place is judged
// from the 1952 counter (thousandths). Every decision is taken at a sample instant, so the
// machine is the same at impulse level and in fast-forward, where the encoder's edges between
// two samples are taken in one jump.
#pragma once

#include "axes/machine_profile.hpp"
#include "axes/spindle.hpp"
#include "cardreader/orders.hpp"
#include "relaylogic/faults.hpp"
#include "relaylogic/press/direction_judging_device.hpp"
#include "relaylogic/press/position_register.hpp"
#include "relaylogic/press/speed_register.hpp"
#include "relaylogic/tapping/gear_ratio_memory.hpp"
#include "relaylogic/tapping/programmable_controller.hpp"
#include "relaylogic/tracer.hpp"

#include <nlohmann/json.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace parsons::relaylogic {

// Spindle synchronisation (an addition after EP 0360190): each tap card's hole.
struct TapSample {
    double t = 0;         // machine time (every sample of interface 33, and the tap's ends)
    double tool_revs = 0; // the tool's revolutions (the plant's, unwrapped; the true ones)
    double feed_in = 0;   // where the part really is on the feed axis
};

struct HoleRecord {
    std::int64_t card = 0; // position in the deck (1-based)
    int number = 0;        // the card number
    int tool_called = 0;   // the tool the card called for
    int tool = 0; // the head on the spindle while it tapped (what really cut; 0: never began)
    std::optional<double> tap_pitch_in; // that head's tap (none: the head holds a cutter)
    double head_ratio = 0;              // that head's real ratio A
    double ratio_used = 0;              // the ratio in memory 12a the NC computed with
    double pitch_ordered_in = 0;
    int rpm = 0; // S ordered
    cardreader::Axis axis = cardreader::Axis::vertical;
    int sense = -1;        // +1 / -1: the part's travel into the work
    double start_in = 0;   // the part on the feed axis where the tap started
    double depth_in = 0;   // ordered
    double deepest_in = 0; // how far into the work it really went (along sense)
    double end_in = 0;     // where it stood when the card ended
    double start_s = 0;
    double reverse_s = 0; // when the NC reversed the spindle at the bottom
    double end_s = 0;
    // Rigid tapping's index wait (an addition; column 19): the feed's count began at the index
    // of encoder 32 that came at sync_s (without the wait, at start_s, where the motor stood).
    // sync_tool_revs: the tool's revolutions there (the plant's), whose fraction is the tool's
    // angle where the thread's helix is referred to; sync_s - start_s is the time waited.
    bool index_wait = false;
    double sync_s = 0;
    double sync_tool_revs = 0;
    // The faster retract (an addition; column 20): out at retract x S (1: as going in).
    int retract = 1;
    // Rigid peck tapping (an addition; columns 21-24): the peck depth Q, inches (0: none, one
    // pass), and the passes into the hole it made (in to Q, 2Q, ... the depth; reverse_s is the
    // last pass's reversal, deepest_in the deepest of all).
    double peck_in = 0;
    int pecks = 1;
    bool completed = false;         // came back out and stood (false: the machine stopped first)
    std::vector<TapSample> samples; // if asked for (record_tap_samples)
};

struct TappingResult {
    int tool_on_spindle = 0;
    double ratio_in_memory = 0; // 12a when the run ended
    std::int64_t head_exchanges = 0;
    std::int64_t transfers = 0;       // ratios PC 130 sent (S6)
    std::int64_t ratios_received = 0; // ratios the NC stored (S16)
    std::vector<HoleRecord> holes;
    bool used = false; // the deck used it (a tap card was read): the report shows it only then
    int encoder_pulses_per_rev = 1; // encoder 32's edges a motor revolution (the profile's)
};

// How far a completed hole bottomed from its depth beyond what the NC resolves: a thousandth,
// or one encoder edge's feed (pitch ordered x ratio in 12a / ppr) where that is coarser
// (docs/tapping.md, "Near the depth"). Positive: past the depth; negative: short of it; 0 for
// a hole within that, or not completed (a stop says why).
double depth_miss_in(const HoleRecord& hole, int encoder_pulses_per_rev);

// A hole's record in a saved state and back (tap_holes.cpp): a resumed run reports the holes
// tapped before the card it resumes at, as an uninterrupted run does.
nlohmann::json tap_hole_json(const HoleRecord& hole);
HoleRecord tap_hole_from_json(const nlohmann::json& j);

// The net edges d of encoder 32 over one sample of interface 33, as the NC reads them. Register
// 14 counts modulo a revolution (device 16: ppr edges), so its two readings a sample apart give
// d only modulo ppr: `reading_change` is the later reading less the earlier. Register 11 counts
// every edge of the sample whichever its sense, `edges` = forward + backward, while d = forward
// - backward: so |d| <= edges and edges - d is even (twice the backward ones). d is the value
// agreeing with all three; of two (edges exactly half a revolution, +-edges), the one in the
// sense device 13 judged the last edge (the sample turned one way only: an edge the other way
// would make |d| < edges). Exact whenever a sample holds at most half a revolution of edges (an
// odd ppr: at most a whole one), which the profile's check keeps (axes/spindle_json.cpp).
int net_edges(int reading_change, int edges, int ppr, int last_sense);

// What the synchronous operation control asks of the feed axis's follower drive.
struct FeedCommand {
    int direction = +1;          // along the axis: +1 forward (counters up), -1 reverse
    double speed_in_per_s = 0.0; // >= 0
};

class TappingUnits {
public:
    // index_wait (rigid tapping, an addition): motor 27 turns, the feed stands until the index.
    enum class Phase : std::uint8_t { idle, tool, run_in, run_out, stopping, settle, index_wait };

    void install(Tracer& tracer, const axes::MachineProfile& profile);
    bool present() const { return spindle_ != nullptr; }
    // Faults for PC 130 (stale-ratio, transfer-hang); others are ignored.
    void inject(const std::vector<Fault>& faults);

    axes::Spindle& spindle() { return *spindle_; }
    const axes::Spindle& spindle() const { return *spindle_; }
    const ProgrammableController& pc() const { return *pc_; }
    const GearRatioMemory& memory() const { return *memory_; }
    const Bus35& bus() const { return bus_; }

    // Encoder 32's edges, counted by interface 33: one, or (fast-forward) n in one sense, the
    // last of them `last`.
    void on_edge(const axes::DetectorEdge& edge, double t);
    // Takes every event of the spindle due by time t (edges counted), one by one; with a
    // tracer, each edge at its own time (the tracer is left at t).
    void catch_up(double t);
    // Fast-forward: the spindle's events before t in one jump a segment (edges only count).
    void jump_to(double t);

    // Why the cabinet cannot take this tap card (tap_refused), or nothing.
    std::optional<std::string> refusal(const cardreader::TapOrder& order,
                                       const axes::MachineProfile& profile) const;
    // Read complete on a tap card: the tool call goes on the bus.
    void begin(const cardreader::TapOrder& order, double t);
    // One scan of PC 130 and the NC's handshake. Returns true when the tool is ready and the
    // ratio in 12a (the tap may start); sets timed_out() when a transfer took too long.
    bool scan(double t);
    bool timed_out() const { return timed_out_; }
    // Tool ready: motor 27 forward at S. counter: the feed axis's absolute counter reading.
    void start(double t, int counter, double real_in);
    // A sample of interface 33 at time t. Returns true when the tap is done (the feed stands
    // on its starting count, or the settle gave up).
    bool sample(double t, int counter, double real_in, bool feed_at_rest);

    // The reversal at the depth the last sample timed, once (the cabinet schedules it), and
    // the reversal itself at that instant.
    std::optional<double> take_reversal();
    void reverse(double t);

    // The machine stopped: motor 27 is commanded to rest, the tap is over.
    void halt();

    Phase phase() const { return phase_; }
    bool feeding(cardreader::Axis axis) const {
        return phase_ != Phase::idle && phase_ != Phase::tool && axis == order_.axis;
    }
    FeedCommand feed() const { return feed_; }
    const cardreader::TapOrder& order() const { return order_; }

    // The run's holes (one a tap card that started), the samples if asked for.
    void keep_samples(bool on) { keep_samples_ = on; }
    std::vector<HoleRecord>& holes() { return holes_; }
    const std::vector<HoleRecord>& holes() const { return holes_; }
    const axes::MachineProfile& profile() const { return profile_; }
    HoleRecord& open_hole(std::int64_t card, int number, int tool_called);

    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    void show();
    void withdraw_call(double t);
    void record(double t, double real_in);
    double travel_per_edge() const; // inches of feed per encoder edge, with the ratio in 12a
    double run_down_travel(double edges_per_sample) const;
    void measure_speed(double t, int d);
    void measure_afresh(double t);
    void plan_reversal(double t, double depth, double per_edge);
    void next_peck(double t); // rigid peck tapping: in again, to the next pass's target
    void look_for_index(std::int64_t m, double t); // an edge onto count m came at t
    bool show_index(int sense, std::int64_t count);

    axes::MachineProfile profile_;
    double max_feed_in_per_s_ = 0;
    std::unique_ptr<axes::Spindle> spindle_;
    std::unique_ptr<ProgrammableController> pc_;
    std::unique_ptr<GearRatioMemory> memory_;
    std::unique_ptr<DirectionJudgingDevice> device_13_;
    std::unique_ptr<PositionRegister> counter_33_;
    std::unique_ptr<SpeedRegister> speed_33_;
    Tracer* tracer_ = nullptr;
    Bus35 bus_;
    bool keep_samples_ = false;
    std::vector<HoleRecord> holes_;

    // The tap under way.
    cardreader::TapOrder order_{};
    Phase phase_ = Phase::idle;
    bool timed_out_ = false;
    bool selected_ = false;
    int last_counter_33_ = 0; // interface 33's counter at the last sample
    int start_counter_ = 0;   // the feed axis's absolute counter where the tap started
    double z_cmd_in_ = 0;     // the depth the tool's turns call for (kept between pecks)
    int pass_target_ = 0;     // this pass's depth, thousandths: min(k Q, depth), or the depth
    double settle_since_s_ = 0;
    double last_edge_s_ = 0; // when interface 33 counted its last edge
    double prev_edge_s_ = 0; // the last edge of the last sample that saw one
    double rate_ = 0;        // the measured speed, edges a second (signed)
    double accel_ = 0;       // and its change, edges a second a second
    double mid_s_ = 0;       // the instant the measured speed belongs to
    bool measured_ = false;
    std::optional<double> reverse_at_s_; // the reversal at the depth, timed
    bool reversal_scheduled_ = false;
    // The index wait: the feed starts at the index where the motor's count is a multiple of
    // index_every_ (n x ppr, A = 1/n: the tool at one angle); set when it came.
    std::int64_t index_every_ = 1;
    std::optional<std::int64_t> index_count_;
    FeedCommand feed_{};

    SignalId motor_rpm_ = 0;
    SignalId tool_rpm_ = 0;
    SignalId head_ = 0;
    SignalId phase_signal_ = 0;
    SignalId z_cmd_signal_ = 0;
    SignalId feed_signal_ = 0;
    SignalId index_signal_ = 0;
    bool index_shown_ = false;
};

} // namespace parsons::relaylogic
