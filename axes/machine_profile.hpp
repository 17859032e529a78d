// The machine profile: every duration and rate of the 1952 machine as a named parameter.
//
// Nothing in relaylogic/ or axes/ hard-codes a time or a speed; they read it here. The
// built-in default ("parsons-1952") is documented, with the reasoning behind each figure, in
// docs/machine-profile.md; a JSON file (--profile FILE) may change any of them.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace parsons::axes {

inline constexpr int kAxisCount = 5;

struct AxisProfile {
    std::string name;
    // Speed positions 1, 2, 3 of speed switch 236 (fastest to slowest), through the three
    // resistance branches 242, 244, 246 of speed relay 240.
    std::array<double, 3> speed_in_per_min{5.4, 1.8, 0.6};
    // How fast the motor and its load change speed when the switch steps (both ways).
    double acceleration_in_per_s2 = 0.2;
    // Deceleration while coasting to rest once switched off: coast = v^2 / (2 a).
    double braking_in_per_s2 = 0.2;
    // Travel of the part; a limit switch stops the machine past either end.
    double travel_min_in = -0.5;
    double travel_max_in = 10.5;
    // The job's movement range (the soft limits of Mitsubishi's control, EP 0360190): a card whose
    // move would end outside it stops the machine before any axis moves, and a running axis that
    // could no longer brake to rest inside it is switched off in time. Off unless set (profile key
    // soft_limits_in, or run --limit AXIS=MIN:MAX).
    bool soft_limits = false;
    double soft_min_in = 0;
    double soft_max_in = 0;
    // Lead of the screw; 1000 commutator impulses an inch whatever the lead (gear train 82-92).
    double screw_lead_in_per_rev = 0.2;
    // Residual error of the screw the counters read, left after any correction: (screw position,
    // error) in inches, interpolated linearly; empty = a perfect screw.
    std::vector<std::pair<double, double>> screw_error_in;
    // Swivel and tilt: distance from the fixture's pivot to its screw (sine-plate geometry),
    // and the screw position at which the fixture stands level (angle 0), so that it can be
    // turned both ways within the counters' 0 .. 9.999 in.
    double pivot_to_screw_in = 10.0;
    double level_in = 0.0;

    // --- The measuring chain of Fig. 3 (lead screw 22, nut 78, instrument shaft 74, cam 160;
    // axes/lead_screw_nut.hpp, axes/instrument_shaft.hpp). All (position, error) tables in
    // inches as screw_error_in; empty = perfect. ---
    // Lead error of lead screw 22: the part stands at screw travel + this, the nut engaged.
    std::vector<std::pair<double, double>> lead_error_in;
    // Backlash in nut 78: screw travel with the part standing when the motion reverses.
    double backlash_in = 0.0;
    // The error of instrument shaft 74's own screw.
    std::vector<std::pair<double, double>> instrument_error_in;
    // The correction compensating cam 160 gives lead screw 22 (the patent: "illustrated herein
    // at 160 for the table lead screw 22"), subtracted from lead_error_in; under the
    // interpretation cam_160_on_instrument_shaft, from instrument_error_in instead.
    std::vector<std::pair<double, double>> cam_160_in;
};

// Condition cards (an addition after EP 0640901, Siemens): how long each action the
// tripping unit ALE starts takes before it is acknowledged. Figures for a 1950s knee mill with a
// powered drawbar and a tool magazine, docs/machine-profile.md.
struct ActionTimes {
    double spindle_run_up_s = 3.0;   // spindle motor from rest to cutting speed
    double spindle_run_down_s = 2.0; // from cutting speed to rest (plugging brake)
    double coolant_valve_s = 0.5;    // solenoid valve and the flow reaching the cutter
    double tool_change_s = 8.0;      // the changer's whole cycle, drawbar to drawbar
    double dwell_s = 1.0;            // how long a dwell holds its axis
    double lamp_s = 0.010;           // an output lamp's relay operating
};

// One tool of the changer: its number (the tool-change parameter) and its cutter radius.
struct Tool {
    int number = 1;
    double radius_in = 0.25;
};

// Press synchronisation (an addition after EP 0436887, Mitsubishi): the outside
// machine, a rotary press the control does not drive (Fig. 1A; axes/press.hpp). Motor 22
// turns crank 21 at a speed of its own; crank 21 raises and lowers die 20; detector 10 on the
// crank gives two-phase pulses. The crank's speed is piecewise constant: it changes only at the
// angles named here, so every detector pulse has an exact time. Figures: docs/press-sync.md.
struct PressProfile {
    double strokes_per_min = 2.0; // motor 22's nominal speed: crank revolutions a minute
    double start_angle_deg = 0.0; // where crank 21 stands when the run starts (0 = top)
    int pulses_per_degree = 4;    // detector 10: edges of phases A and B per degree
    bool reverse = false;         // the crank turns backwards (inching; tests of device 13)
    // Die 20: a slider crank. Height above its bottom dead centre, in inches.
    double stroke_in = 4.0; // top to bottom dead centre (twice the crank throw)
    double rod_in = 8.0;    // connecting rod, pin to pin
    // The press slows while the die works the metal (the load on the flywheel).
    double pressing_from_deg = 150.0;
    double pressing_to_deg = 210.0;
    double pressing_slowdown = 0.0; // fraction of speed lost while pressing (0 .. 0.9)
    double drift_per_cycle = 0.0;   // fraction the speed changes each revolution (+ or -)
    double variation = 0.0;         // each revolution's speed x (1 + u variation), u in -1..1
    unsigned seed = 1;              // ... from this seed: a pure function of seed and revolution
    // A lasting change of speed from revolution change_cycle (1 = the first) at change_angle_deg:
    // the speed times change_factor from there on (0 = no change). The seed's comparison slows
    // the press 25 % mid-cycle: change_factor 0.75.
    int change_cycle = 0;
    double change_angle_deg = 0.0;
    double change_factor = 1.0;
    // Motor 22 stops at revolution stop_cycle, angle stop_angle_deg (0 = it never stops).
    int stop_cycle = 0;
    double stop_angle_deg = 0.0;
    // The feeder's interlock (docs/press-sync.md, "The feeder holds the press"): processor 17
    // holds the press while a synchronised axis is behind its reference travel by more than
    // this, until every one is within half of it (0 = no interlock: the press never waits).
    double feeder_hold_lag_in = 0.0;
};

// The drive that follows a commanded speed, which speed synchronisation needs: the 1952 motors
// have three speeds only (docs/press-sync.md, "the motor question"). While an axis is speed-
// synchronised and its speed switch 236 stands on speed 1, this drive runs it at the speed
// processor 63 computes, changing speed at acceleration_in_per_s2 at most (the rate limit);
// each new speed takes effect one sampling interval of speed register 11 after the sample it
// comes from (the lag: Fig. 6, output at the start of the next reference block).
struct SyncDrive {
    double max_in_per_min = 5.4;         // the fastest it follows (the counters' 100 steps/s)
    double acceleration_in_per_s2 = 0.5; // its rate limit, both ways
    // Processor 63's position loop on a card with position sync (G101 with G95): the speed
    // added per inch the axis is behind the crank's reference travel (at most half the speed).
    double position_gain_per_s = 4.0;
};

// Spindle synchronisation (an addition after EP 0360190, Mitsubishi): spindle motor
// 27 with encoder 32 on its shaft, gear unit 30 and the interchangeable spindle heads 31, each
// holding one tool; programmable controller 130 exchanges the heads; the NC feeds one axis in
// step with the tool (S x A, tapping). Figures: docs/tapping.md.
struct SpindleHead {
    int tool = 1;       // the tool number T a tap card calls the head by (1..99)
    double ratio = 0.5; // gear unit 30 with this head: tool revolutions per motor revolution (A)
    // The tool the head holds: a tap of this pitch (inches per tool revolution), or a cutter of
    // this radius (exactly one of the two).
    std::optional<double> pitch_in;
    std::optional<double> radius_in;
};

// How the gear ratio reaches gear ratio data memory 12a: sent by PC 130 over bus 35 after each
// head exchange (the seed's first embodiment, Figs. 3-4), or stored for every tool number in
// advance and selected by the tool number the card calls for (second embodiment, Figs. 5-7).
enum class RatioSource : std::uint8_t { transferred, stored };

struct SpindleSyncProfile {
    // Motor 27: its fastest speed and how fast it runs up and down (rev/min per second).
    double max_rpm = 240.0;
    double run_up_rpm_per_s = 240.0;
    double run_down_rpm_per_s = 320.0;
    // Encoder 32 on the motor: edges of its phases A and B per motor revolution. Its counter in
    // spindle encoder interface 33 is stepping switches, so max_rpm x this / 60 must stay within
    // max_stepping_rate_per_s (checked when the profile is loaded).
    int encoder_pulses_per_rev = 24;
    // The NC reads the encoder (interface 33) and sets the feed this often.
    double sample_s = 0.050;
    // Position correction of the synchronised feed: the feed's speed gains this much per second
    // of the tool's lead the feed is behind (1/s).
    double feed_gain_per_s = 10.0;
    // A lasting change of the motor's speed (its supply sags, a heavy cut): from change_at_s
    // (machine time; none = no change) the motor turns at change_factor x its commanded speed.
    std::optional<double> change_at_s;
    double change_factor = 1.0;
    // Gear unit 30's heads and the one on the spindle when the run starts.
    std::vector<SpindleHead> heads = {{1, 0.25, 0.05, std::nullopt},
                                      {2, 1.0 / 3.0, 0.0625, std::nullopt},
                                      {3, 0.5, std::nullopt, 0.25}};
    int first_tool = 1;
    RatioSource ratio_source = RatioSource::transferred;
    // PC 130: one scan of its ladder; a head exchange; how long the NC waits for a transfer.
    double pc_scan_s = 0.020;
    double head_change_s = 6.0;
    double transfer_timeout_s = 2.0;
    // The tap's chamfer: the last threads at the bottom of a hole are not full (the thread
    // proof judges the pitch above them), in tool revolutions.
    double chamfer_revs = 3.0;

    const SpindleHead* head(int tool) const {
        for (const SpindleHead& h : heads) {
            if (h.tool == tool) {
                return &h;
            }
        }
        return nullptr;
    }
};

// Contouring (an addition after EP 0636958, Black & Decker): three stepper-motor axes X, Y, Z
// driven by the attachment's interpolator along segment cards, and the control cycle that
// decides at each junction of two segments whether to pass at the nominal speed or to slow to a
// minimum (docs/contouring.md). Rates are pulses (steps) a second.
enum class JunctionPolicy : std::uint8_t {
    rule,    // claim 1: pass unless the motors' speed parameters differ by more than the maximum
    pass,    // the rule off: every junction at the nominal speeds
    minimum, // the prior art the seed improves on: every junction slowed to the minimum speed
};

struct ContourProfile {
    int steps_per_in = 1000;                  // one step a thousandth, the card's resolution
    double pull_in_steps_per_s = 100.0;       // a change of pulse rate the motor follows at once
    double acceleration_steps_per_s2 = 2000;  // how fast its rotor can change its rate
    double ramp_steps_per_s2 = 1000;          // the interpolator's ramps (at most the above)
    double max_rate_change_steps_per_s = 100; // claim 1's maximum difference
    double minimum_in_per_min = 0.0;          // claims 1, 4: the speed a slowed junction is met at
    JunctionPolicy junctions = JunctionPolicy::rule;
    bool short_segment_rule = true; // claims 7, 8: slow before a segment shorter than the ramp
};

// What the counters measure (docs/design-rules.md rule 3).
enum class MeasuringChain : std::uint8_t {
    instrument_shaft_74, // the patent: the part's position, through shaft 74 and follower 76
    screw_turns,         // departure from the patent: the turns of the main screw
};

struct MachineProfile {
    std::string name = "parsons-1952";
    std::array<AxisProfile, kAxisCount> axes;
    // Card reader 134: one card cycle, and when the two brush banks sense the card within it.
    double reader_cycle_s = 0.6;
    double first_bank_s = 0.15;
    double second_bank_s = 0.30;
    // Of each card cycle, the first feed_gap_s pass while the gap between two separate cards
    // (the picker taking the next card from the hopper) goes by the brushes; brush times above
    // count from the start of the cycle, gap included.
    double feed_gap_s = 0.10;
    // Fig. 9: cards "secured end to end to form an elongated ribbon or tape" (and perforated
    // tape, col. 6). The next card follows the last with no gap, so every card after the first
    // is sensed feed_gap_s sooner. Off: separate cards from the hopper.
    bool ribbon_feed = false;
    // Relays (holding relays of Fig. 13, stepping relay 256): operate and release times.
    double relay_operate_s = 0.010;
    double relay_release_s = 0.008;
    // Rotary stepping switches (counters 104-110, 310-316; speed switch 236): one step, and the
    // fastest impulse rate they follow. Impulses closer together than 1/rate are lost.
    double stepping_switch_step_s = 0.010;
    double max_stepping_rate_per_s = 100.0;
    // Delay device 258: how long it holds channel 257 open after speed switch 236 steps. It must
    // outlast an equality at the slowest speed (0.001 in at speed 3, 0.6 in/min: 100 ms; the first
    // impulse from rest, 0.001 in at 0.2 in/s2, also 100 ms), or one equality steps the switch
    // twice (docs/design-rules.md rule 5). It also hides every number the axis passes during the
    // hold: 0.135 in at speed 1 needs slow-downs at least 0.014 in apart.
    double delay_258_s = 0.150;
    // Motor 278 moving stepping shaft 280 one position.
    double sequence_shaft_step_s = 0.100;
    // Departure from the patent, off by default: each slow-down and the stop get their own
    // register instead of sharing banks 350-356 (no spurious matches).
    bool separate_registers = false;
    // The patent's own answer to impulses faster than the switches (col. 8), off by default:
    // "count only every one-hundredth of an inch motion rather than every one-thousandth until
    // the slow down signal occurs". While an axis's speed switch stands on speed 1, switches
    // 110 and 310 stand still and commutator 100 steps 312 directly. The thousandths they
    // skip are right again only where the move passes whole hundredths the way it started.
    bool count_hundredths_at_speed_1 = false;

    // --- The measuring chain (Fig. 3; claims 8-10, 23) ---
    // The patent's counters measure the part through instrument shaft 74; counting the turns
    // of the main screw instead is a departure, kept to show what the chain is for.
    MeasuringChain measuring_chain = MeasuringChain::instrument_shaft_74;

    // ---- Readings of the patent and additions (docs/design-rules.md rules 5, 6, 12, 14) ----
    // The built-in profiles parsons-1952 (the default) and parsons-safe differ only here;
    // docs/machine-profile.md tells each option's story.
    //
    // Interpretations: earlier readings of the patent, off in every built-in profile.
    // "An incremental equality stops at any speed": an equality of comparer 122'' sends speed
    // switch 236 straight to off, whatever speed it stands on.
    bool incremental_equality_stops_at_any_speed = false;
    // Delay 258 holds channel 257 open until its time has passed AND the comparer has left the
    // equality that stepped the switch (one equality can never step it twice).
    bool delay_258_waits_for_equality_to_leave = false;
    // Lamps 270 and 272 light only when balancing circuit 266 trips (not on a good stop).
    bool lamps_only_on_trip = false;
    // Compensating cam 160 corrects instrument shaft 74's screw (the screw the counters read),
    // not lead screw 22 as the patent draws it. Matters only with the instrument chain.
    bool cam_160_on_instrument_shaft = false;
    // Additions (not in the patent), named as such in messages. The card reader refuses a card
    // with two punches in one digit column (stop bad_punch) instead of closing two relays of
    // the bank as a 1952 reader would. On in parsons-safe.
    bool refuse_double_punch = false;
    // Addition after EP 0640901 (Siemens): condition cards that trip an action
    // while an axis moves. Off in parsons-1952 and parsons-safe (a deck with one is refused),
    // on in parsons-extended.
    bool condition_cards = false;
    ActionTimes actions;
    // The tool changer's tools, and the one in the spindle when the run starts.
    std::vector<Tool> tools = {{1, 0.25}, {2, 0.125}};
    int first_tool = 1;
    // Addition after EP 0436887 (Mitsubishi): a press beside the machine, the sync
    // units 10-17 and sync cards. Off in parsons-1952 and parsons-safe (a deck with a sync card
    // is refused), on in parsons-extended.
    bool press_sync = false;
    PressProfile press;
    SyncDrive sync_drive;
    // The reference block of Fig. 6 (the seed: "generally less than 20ms"): speed register 11
    // is read and processor 63 computes every block, its result going out at the next.
    double speed_sample_s = 0.01;
    // How long the synchronisation control processor 17 waits for the crank (position sync) or
    // for a pulse (speed sync) before it stops the machine: sync_timeout.
    double sync_timeout_s = 90.0;
    // Addition after EP 0360190 (Mitsubishi): spindle synchronisation (motor 27
    // with a speed, encoder 32, gear unit 30, heads 31, PC 130, memory 12a) and tap cards. Off
    // in parsons-1952 and parsons-safe (a deck with a tap card is refused), on in
    // parsons-extended.
    bool spindle_sync = false;
    SpindleSyncProfile spindle;
    // Addition after EP 0636958 (Black & Decker): the contouring attachment (stepper axes, the
    // interpolator, the junction rule) and segment cards. Off in parsons-1952 and parsons-safe
    // (a deck with a segment card is refused), on in parsons-extended.
    bool contouring = false;
    ContourProfile contour;
    // The cutter radius of a tool, if the changer holds it.
    std::optional<double> tool_radius_in(int tool) const {
        for (const Tool& t : tools) {
            if (t.number == tool) {
                return t.radius_in;
            }
        }
        return std::nullopt;
    }
};

// The built-in profile, with the five axes named table, cross, vertical, swivel, tilt:
// parsons-1952, the patent as written.
MachineProfile default_profile();
// parsons-safe: parsons-1952 with the emulator's protective additions on.
MachineProfile safe_profile();
// parsons-extended: parsons-safe with the later seeds' additions on (condition cards, press
// synchronisation, spindle synchronisation).
MachineProfile extended_profile();
// The profile a name ("parsons-1952", ...) gives, if there is one; the names in order.
inline constexpr std::array<const char*, 3> kBuiltinProfiles = {"parsons-1952", "parsons-safe",
                                                                "parsons-extended"};
// The built-in profile of this name (parsons-1952, parsons-safe, parsons-extended), if any.
std::optional<MachineProfile> builtin_profile(const std::string& name);

} // namespace parsons::axes
