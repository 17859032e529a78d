// Gear ratio data memory 12a of EP 0360190 (Mitsubishi), with the NC's side of the
// transfer handshake (the seed's operation I, Fig. 4 right column) and its buffer memory in
// input/output interface 9. An addition, not in the 1952 patent.
//
// First embodiment (ratio_source transferred): each scan the NC takes one step of
//   S11 a transfer request from PC 130 on bus 35?   S12 ready to receive?
//   S13 "preparation completion" (ready) to the PC  S14 the ratio on the data lines into the
//   buffer memory                                   S15 "reception completion" to the PC
//   S16 buffer -> memory 12a; the handshake ends when the PC drops its request.
// Second embodiment (ratio_source stored, Fig. 6): 12a holds a ratio per tool number, stored in
// advance (the profile's heads); select(T) reads the one for the tool the card calls for
// (Fig. 7, S31-S33). Either way ratio() is the A the NC computes the tool's speed with (S x A).
//
// Built as the rest of the cabinet: the memory is a bank of holding relays standing for the
// ratio's digits (traced as memory_12a.ratio in millionths), the handshake's signals relays.
#pragma once

#include "axes/machine_profile.hpp"
#include "relaylogic/tapping/programmable_controller.hpp"
#include "relaylogic/tracer.hpp"

#include <nlohmann/json.hpp>

#include <optional>

namespace parsons::relaylogic {

class GearRatioMemory {
public:
    // When the run starts, 12a holds the ratio of the head on the spindle (profile first_tool).
    GearRatioMemory(Tracer& tracer, const axes::SpindleSyncProfile& profile);

    // The NC's operation I: one step per scan at machine time t (transferred embodiment).
    void scan(double t, Bus35& bus);
    // Second embodiment: the ratio stored for tool T into use; false if none is stored.
    bool select(int tool);

    double ratio() const { return ratio_; } // A in use
    // A transfer request is standing and the NC has not stored its data yet; since when.
    bool transfer_under_way() const { return request_since_s_ >= 0; }
    double request_since_s() const { return request_since_s_; }
    std::int64_t received() const { return received_; } // ratios stored by S16

    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    void idle();

    Tracer& tracer_;
    axes::SpindleSyncProfile profile_;
    double ratio_ = 0;
    std::optional<double> buffer_; // interface 9's buffer memory (S14)
    double request_since_s_ = -1;
    std::int64_t received_ = 0;
    int step_ = 0; // the seed's step the NC stands at (11..16; 0 idle)
    SignalId ratio_signal_;
    SignalId buffer_signal_;
    SignalId ready_signal_;
    SignalId received_signal_;
    SignalId step_signal_;
};

} // namespace parsons::relaylogic
