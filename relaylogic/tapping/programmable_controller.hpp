// Programmable controller 130 of EP 0360190 (Mitsubishi), Fig. 3: the controller
// that does the machine's sequence control beside the NC, joined to it by parallel bus 35. An
// addition, not in the 1952 patent: present only when the profile has spindle synchronisation.
//
// Here PC 130 is a small ladder of relays with its own scan (the profile's pc_scan_s): every
// scan it reads the bus as the NC left it, solves its rungs top to bottom, and sets its outputs.
// What it does is the seed's Fig. 4, left column, for the tool the card calls for:
//   S1  tool specifying signal on the bus (a tap card's T): if another head is on the spindle,
//       exchange it (the motor at rest; the exchange takes the profile's head_change_s), the
//       new head's gear 30b engaging gear 30a
//   S2  must the gear ratio in the NC change? (first embodiment: yes after every exchange)
//   S3  select the new head's ratio A from the PC's memory 132 (the profile's heads)
//   S4  transfer request to the NC              S5  wait for the NC's "ready" (S13)
//   S6  transfer: the ratio on the data lines   S7/S8  wait for the NC's "received" (S15)
//   then drop request and data, and tell the NC the tool is ready.
// Second embodiment (ratio_source stored, Figs. 5-7): the PC exchanges the head and tells the NC
// the tool is ready; there is no transfer (steps S2-S8 answer "no"), the NC selects the ratio
// stored for the tool number in memory 12a itself (relaylogic/tapping/gear_ratio_memory.hpp).
//
// The NC's side of the handshake (operation I, S11-S16) is gear_ratio_memory.hpp. Both sides
// act once per scan each (PC first, then the NC), so every step of the handshake is a scan of
// its own, visible in the trace (scope "spindle": pc130.* relays, bus35.* signals).
//
// Faults the seed is about (run --fault, relaylogic/faults.hpp):
//   stale-ratio:N    at the Nth head exchange the PC's step S2 answers "no change": the head is
//                    exchanged and the ratio is not transferred; the NC computes with the old one
//   transfer-hang:N  the Nth transfer never completes: the PC raises the request and the NC
//                    answers ready, but the data never reaches the NC (the PC stands in S6); the
//                    NC gives up after transfer_timeout_s (transfer_timeout, exit 3)
#pragma once

#include "axes/machine_profile.hpp"
#include "axes/spindle.hpp"
#include "relaylogic/tracer.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>

namespace parsons::relaylogic {

// Parallel bus 35 between NC 10 and PC 130 (through interfaces 9 and 133a).
struct Bus35 {
    // NC -> PC
    int tool_call = 0;        // the tool specifying signal: T, 0 = none
    bool nc_ready = false;    // S13: NC device preparation completion
    bool nc_received = false; // S15: data reception completion
    // PC -> NC
    bool transfer_request = false; // S4
    bool data_valid = false;       // S6: the ratio stands on the data lines
    double data_ratio = 0;         // ... this ratio (from the PC's memory 132)
    bool tool_ready = false;       // the called head is on the spindle and the PC's sequence done

    bool operator==(const Bus35&) const = default;
};

// A ratio as the whole millionths its relays and memory 12a are traced in (below 0 as 0).
std::uint32_t ratio_millionths(double ratio);

class ProgrammableController {
public:
    ProgrammableController(Tracer& tracer, const axes::SpindleSyncProfile& profile);

    // Faults (stale-ratio:N, transfer-hang:N): N counts head exchanges / transfers from 1.
    void stale_ratio_at(std::int64_t exchange) { stale_ratio_at_ = exchange; }
    void transfer_hang_at(std::int64_t transfer) { transfer_hang_at_ = transfer; }

    // One scan of the ladder at machine time t. Reads the NC's signals on the bus, sets its own;
    // mounts the new head on the spindle when an exchange completes (the motor must stand).
    void scan(double t, Bus35& bus, axes::Spindle& spindle);
    // A scan could still change something: a call of a tool with a head not yet answered, or
    // relays to drop after the call went; an exchange timing or waiting for the motor to rest;
    // the handshake under way (a hung transfer: for ever; the NC's transfer_timeout is the
    // caller's); the NC's ready and received still to drop. False when idle, when tool ready
    // stands with nothing pending, and for a call of a tool memory 132 has no head for.
    bool busy(const Bus35& bus) const;

    std::int64_t exchanges() const { return exchanges_; } // head exchanges done
    std::int64_t transfers() const {
        return transfers_;
    } // transfers begun (S6), a hung one included
    bool exchanging() const { return exchange_done_s_ >= 0; }

    nlohmann::json save() const;
    void load(const nlohmann::json& j);

    // The ladder's relays, one rung each (programmable_controller.cpp: what picks and what
    // drops each, with the seed's steps).
    enum Relay : std::uint8_t {
        cr1_tool_call,
        cr2_exchange,
        cr3_exchanged,
        cr4_head_on,
        cr5_ratio_change,
        cr6_request,
        cr7_transfer,
        cr8_done,
        kRelays
    };

private:
    bool change_wanted() const;
    void show(const Bus35& bus);

    Tracer& tracer_;
    axes::SpindleSyncProfile profile_;
    std::int64_t stale_ratio_at_ = 0;
    std::int64_t transfer_hang_at_ = 0;
    std::int64_t exchanges_ = 0;
    std::int64_t transfers_ = 0;
    double exchange_done_s_ = -1; // when the exchange under way completes; -1 = none
    std::array<bool, kRelays> relay_{};
    int answered_tool_ = 0;   // the tool CR1 latched (the head an exchange fetches)
    double register_132_ = 0; // S3: the ratio selected from memory 132 for the transfer
    std::array<SignalId, kRelays> relay_signal_{};
    SignalId register_signal_;
    SignalId tool_call_signal_;
    SignalId request_signal_;
    SignalId data_valid_signal_;
    SignalId data_ratio_signal_;
    SignalId tool_ready_signal_;
};

// Bus 35's lines as JSON (the state file; data_ratio exactly), and back.
nlohmann::json save_bus35(const Bus35& bus);
Bus35 load_bus35(const nlohmann::json& j);

} // namespace parsons::relaylogic
