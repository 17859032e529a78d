// Synchronisation control processor 17 of EP 0436887 (Mitsubishi), Fig. 4A and
// Fig. 5: an addition, not in the 1952 patent. Its parts, each built as relays here:
//
//   programmed position reader 60  holds the angle R of a sync card (a bank of holding relays
//                                  per decade, the angle in detector pulses) and, while the
//                                  card's motion waits for it, the hold relay that "stops
//                                  operation of the interpolation pulse distributor 5" (in
//                                  the 1952 cabinet: opens the motor circuits of the card)
//   synchronisation position       a comparer on the wipers of position register 14 against
//   detector 61                    60's relays: when it conducts the hold relay drops and the
//                                  card's motion starts ("start the interpolation pulse
//                                  distributor 5 when the position read from register 14
//                                  corresponds to the program-designated position value")
//   programmed feed speed reader 62  holds each axis's travel per pulse F
//   processor 63                   at each reference block (Fig. 6, every speed_sample_s) reads
//                                  the crank's speed from speed register 11 (pulses a second,
//                                  timed edge to edge) and position register 14, and works out
//                                  each synchronised axis's speed; the result goes to the drive
//                                  at the start of the next block
//
// Every speed of speed switch 236 follows the press: each position of the switch is a travel
// per detector pulse, F for the speed the card starts the axis on, and the 1952 motor's own
// speed over the press's rated pulses a second for each slow-down after it, so at the rated
// speed the slow-downs run exactly as the 1952 ones and a slower press slows them alike.
//
// Position data (claim 7: selected by the card's G101): on a card with position sync, 63 also
// keeps each synchronised axis on the crank. From the instant the axis starts, the reference
// travel grows by the travel per pulse of the switch's position for every pulse register 14
// counts; the axis's travel is the impulses commutator 102 sent since; 63 adds the difference
// times sync_drive.position_gain_per_s to the speed (at most half of it either way), so the
// offset that the drive's lag leaves after a change of the press's speed, or its start, is
// taken out (the seed: "the external position data and a numerically controlled coordinate
// position may be overlapped with each other to enable more fine control"). A speed-only card
// keeps what offset it gets, as Fig. 7's prior art does.
//
// Processing every block, both kinds of synchronisation in one pass (Fig. 5 left side): the
// position check holds or starts the card, and the speed is computed while it is held too, so
// the axis starts at the crank's own pace.
#pragma once

#include "axes/machine_profile.hpp"
#include "cardreader/orders.hpp"
#include "relaylogic/press/press_result.hpp"
#include "relaylogic/tracer.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <optional>

namespace parsons::relaylogic {

class SynchronisationProcessor {
public:
    SynchronisationProcessor(Tracer& tracer, const axes::MachineProfile& profile);

    // ---- the sync card and the motion card it stands before ----
    // A sync card's orders, waiting for the next motion card (card: its deck position).
    void take(const cardreader::SyncOrder& order, std::int64_t card, int number);
    bool pending() const { return pending_.has_value(); }
    std::int64_t pending_card() const { return pending_card_; }
    int pending_number() const { return pending_number_; }
    const cardreader::SyncOrder& pending_order() const { return *pending_; }
    // The motion card's relays pick: the pending orders go into 60 and 62.
    void arm();
    // The zeroizing circuit: 60 and 62 cleared, 63's outputs to zero.
    void clear();

    // ---- position synchronisation: 60 and 61 ----
    bool position_armed() const { return target_.has_value(); }
    int target_pulses() const { return target_.value_or(0); }
    bool holding() const { return holding_; }
    double hold_since() const { return hold_since_; }
    // The card's reading is complete: hold it unless register 14 already stands on R.
    // Returns true when it holds.
    bool hold_unless_at(int register_value, double t);
    // Detector 61 reads register 14 after each count: true when it conducts while holding
    // (the hold relay is to drop).
    bool detector_61(int register_value);
    void release(); // the hold relay drops: the card's motion starts

    // ---- speed synchronisation: 62 and 63 ----
    bool speed_synced(cardreader::Axis a) const {
        return feed_.at(cardreader::axis_index(a)).has_value();
    }
    bool any_speed_synced() const;
    // A synchronised axis is powered for the first time on its card: the speed position it
    // starts on, commutator 102's impulses so far and register 14 now.
    bool started(cardreader::Axis a) const { return follow_.at(cardreader::axis_index(a)).started; }
    void start_axis(cardreader::Axis a, int speed_position, std::int64_t impulses, int register_14);
    // The travel per detector pulse of the axis at a position of speed switch 236, inches.
    double per_pulse_in(cardreader::Axis a, int speed_position) const;
    // Speed switch 236 of a started axis stands on `speed_position` with commutator 102 at
    // `impulses`: a step since the last call leaves the axis on the equality that stepped it,
    // which it must leave within delay 258's hold (see drive_speed).
    void switch_at(cardreader::Axis a, int speed_position, std::int64_t impulses, int register_14);
    // The speed the drive runs the axis at on that position, in/s: the crank's speed in force
    // times the travel per pulse (the base), with the position correction in force, at most
    // half the base either way. Below the drive's least steady speed
    // (cardreader::kLeastTapFeedInPerMin) it stops and goes: the least speed while processor 63
    // found the axis behind its reference by more than a block of it, or while the axis still
    // stands on the equality that stepped switch 236; otherwise it stands.
    double drive_speed(cardreader::Axis a, int speed_position) const;
    // The drive is commanded on that position at machine time t, on motion card `card` (deck
    // position) numbered `number`: where the crank asks more than sync_drive.max_in_per_min
    // (the travel per pulse times the crank's speed in force, before any correction), the drive
    // runs at its top speed and the axis falls behind the crank. The first such command is kept,
    // and the most asked; nothing clears them (the run's record, saved with the state).
    void note_asked(cardreader::Axis a, int speed_position, double t, std::int64_t card,
                    int number);
    const std::optional<DriveSaturation>& saturation() const { return saturation_; }
    // What a reference block reads of a started, powered synchronised axis.
    struct Feedback {
        int speed_position = 0;
        std::int64_t impulses = 0; // commutator 102's impulses so far
    };
    // A reference block: the crank's speed and the corrections computed at the last block go
    // to the drive (returns true if any changed), then 63 computes the next from `rate`
    // (register 11: pulses a second), register 14 and the axes' travel.
    bool reference_block(double rate, bool turning, int register_14,
                         const std::array<std::optional<Feedback>, cardreader::kAxisCount>& axes);
    // The most a started synchronised axis was behind its reference travel at any block, on
    // cards with position sync (the loop) or on speed-only cards; and the most it was ahead.
    // The most a synchronised axis running on its card (one the last block read) was behind
    // its reference at the last block; nothing when none ran (the feeder's interlock).
    std::optional<double> most_behind_in() const { return most_behind_; }
    double worst_lag_in(bool with_loop) const { return worst_lag_.at(with_loop ? 1 : 0); }
    double worst_lead_in(bool with_loop) const { return worst_lead_.at(with_loop ? 1 : 0); }
    // The speed last sent to the axis's drive (traced), in/s.
    void commanded(cardreader::Axis a, double in_per_s);

    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    void show();

    Tracer& tracer_;
    int ppd_;
    std::optional<cardreader::SyncOrder> pending_;
    std::int64_t pending_card_ = 0;
    int pending_number_ = 0;
    std::optional<int> target_; // 60: R in pulses
    bool holding_ = false;
    double hold_since_ = 0;
    std::array<std::optional<int>, cardreader::kAxisCount> feed_{}; // 62: F, 1e-5 in per pulse
    struct Follow {
        bool started = false;
        int start_speed = 1;
        std::int64_t impulses0 = 0;     // commutator 102 when the axis started
        int register_prev = 0;          // register 14 at the last block
        double ref_in = 0;              // the reference travel since the start
        double lag_in = 0;              // reference minus counted travel at the last block
        double next = 0;                // 63: correction computed, in/s
        double out = 0;                 // 63: correction in force
        bool go_next = false;           // 63: below the least speed, go (computed)
        bool go_out = false;            // in force
        int position = 0;               // switch 236 as last seen (0: not yet)
        bool leaving = false;           // on the equality that stepped switch 236
        std::int64_t step_impulses = 0; // commutator 102 when it stepped
    };
    std::array<Follow, cardreader::kAxisCount> follow_{};
    bool loop_ = false;
    std::array<double, 2> worst_lag_{};         // speed only, with the loop
    std::array<double, 2> worst_lead_{};        // the same, ahead of the reference
    std::optional<DriveSaturation> saturation_; // the drive asked past its top speed
    std::optional<double> most_behind_;         // at the last block (not saved: used at once)
    double rate_next_ = 0;                      // 63: the crank's speed computed, pulses a second
    double rate_out_ = 0;                       // 63: in force
    bool turning_next_ = false; // register 11 timed it between pulses (the crank turns)
    bool turning_out_ = false;
    double rated_pulses_per_s_ = 1;
    std::array<std::array<double, 3>, cardreader::kAxisCount> speeds_{}; // the 1952 speeds, in/s
    double gain_per_s_ = 0;
    double block_s_ = 0.01; // speed_sample_s
    double max_in_per_s_ = 0;
    int device_16_ = 1440;
    SignalId sync_card_;
    SignalId angle_60_;
    SignalId hold_60_;
    SignalId detector_61_;
    std::array<SignalId, cardreader::kAxisCount> feed_62_{};
    std::array<SignalId, cardreader::kAxisCount> output_63_{};
    std::array<SignalId, cardreader::kAxisCount> behind_63_{};
    std::array<SignalId, cardreader::kAxisCount> ahead_63_{};
};

} // namespace parsons::relaylogic
