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
//   processor 63                   at each reference block (Fig. 6) multiplies the pulses
//                                  speed register 11 counted in the last interval by F, over
//                                  the interval: the speed the axis must run at; the result
//                                  goes to the drive at the start of the next block
//
// Processing every block, both kinds of synchronisation in one pass (Fig. 5 left side): the
// position check holds or starts the card, and the speed is computed while it is held too, so
// the axis starts at the crank's own pace.
#pragma once

#include "cardreader/orders.hpp"
#include "relaylogic/tracer.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <optional>

namespace parsons::relaylogic {

class SynchronisationProcessor {
public:
    SynchronisationProcessor(Tracer& tracer, int pulses_per_degree, double block_s);

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
    // The drive speed in force for the axis, in/s.
    double output(cardreader::Axis a) const { return output_.at(cardreader::axis_index(a)); }
    // A reference block: the speeds computed at the last block go to the drive (returns true if
    // any changed), then 63 computes the next from `pulses` (speed register 11's stored data).
    bool reference_block(int pulses, double max_in_per_s);

    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    void show();

    Tracer& tracer_;
    int ppd_;
    double block_s_;
    std::optional<cardreader::SyncOrder> pending_;
    std::int64_t pending_card_ = 0;
    int pending_number_ = 0;
    std::optional<int> target_; // 60: R in pulses
    bool holding_ = false;
    double hold_since_ = 0;
    std::array<std::optional<int>, cardreader::kAxisCount> feed_{}; // 62: F, 1e-5 in per pulse
    std::array<double, cardreader::kAxisCount> next_{};             // 63: computed, not yet out
    std::array<double, cardreader::kAxisCount> output_{};           // 63: in force
    SignalId sync_card_;
    SignalId angle_60_;
    SignalId hold_60_;
    SignalId detector_61_;
    std::array<SignalId, cardreader::kAxisCount> feed_62_{};
    std::array<SignalId, cardreader::kAxisCount> output_63_{};
};

} // namespace parsons::relaylogic
