// Programmable controller 130 of EP 0360190 (Mitsubishi), Figs. 3-4 and 5-7: the ladder. An
// addition (docs/design-rules.md rule 14), after Mitsubishi's patent, not in the 1952 machine.
//
// Each scan reads its inputs first (bus 35 as the NC left it, the spindle's head-on switch and
// its at-rest contact, the exchange timer), then solves eight rungs, then drives bus 35. The
// rungs are written last step first (CR8 down to CR1), so a rung reads the relay of the step
// before it as the last scan left it: a sequence advances one step a scan and never two, and
// the trace shows each step at a scan of its own. Every rung but the exchange timer's has the
// contact "call standing" in series (CR1 picked, the bus still calling the tool CR1 latched), so
// when the NC withdraws its call everything drops in one scan.
//
//   relay             seed step   picks when                          drops when
//   CR1 tool_call     S1          the bus calls a tool memory 132     the call goes (or names
//                                 holds a head for, no exchange       another tool: CR1 picks
//                                 running; latches the tool T         again a scan later)
//   CR2 exchange      S1          call standing, another head on,     the timer is done: the
//                                 motor at rest (else it waits);      first scan at or after
//                                 the timer starts: head_change_s     pick + head_change_s; T
//                                                                     is mounted, ++exchanges
//   CR3 exchanged     S1 done     the timer is done (this call's      the call goes
//                                 exchange); sealed in
//   CR4 head_on       -           the head on the spindle is T (its   the call goes, or the
//                                 limit switch, read at scan start)   head comes off
//   CR5 ratio_change  S2 yes, S3  CR3 and CR4, ratio_source           CR8 picks
//                                 transferred, and the stale-ratio
//                                 fault not at this exchange; S3:
//                                 T's ratio into register 132
//   CR6 request       S4, S5      CR5 (the request stands while S5    CR8 picks
//                                 asks for the NC's ready)
//   CR7 transfer      S6-S8       CR6 and the NC's ready (S13):       CR8 picks
//                                 ++transfers; data_valid and the
//                                 ratio on the data lines
//   CR8 done          end         S2 no (CR4 without CR3: no          the call goes
//                                 exchange; CR3 and CR4 with no
//                                 change wanted: stale-ratio, or
//                                 ratio_source stored); S8 yes (CR7
//                                 and the NC's received, S15)
//
// Outputs: transfer_request = CR6, data_valid = CR7 (but see transfer-hang), data_ratio =
// register 132 while data_valid (else 0), tool_ready = CR8.
//
// Transferred embodiment, a head exchange, scan by scan (n = the scan CR2 drops):
//   0 CR1 | 1 CR2, timer | n CR2 drops, T mounted, CR3 | n+1 CR4 | n+2 CR5 (S2, S3)
//   n+3 CR6: request (NC: S11) | n+4 (NC: S12) | n+5 (NC: S13 ready) | n+6 CR7: data (NC: S14)
//   n+7 (NC: S15 received) | n+8 CR8: request and data drop, tool ready (NC: S16 into 12a)
//   n+9 (NC: ready and received drop)
// The called head already on: 0 CR1 | 1 CR4 | 2 CR8, tool ready. Stored embodiment, or the
// stale-ratio fault: CR8 at n+2 with no request.
//
// Faults: stale-ratio:N (N counts exchanges) makes S2 answer no after the Nth exchange.
// transfer-hang:N (N counts transfers, CR7's picks): the Nth time CR7 picks the PC stands in S6
// with the transfer relay picked but never puts valid data on the lines (data_valid 0, data_ratio
// 0): the data never reaches the NC, which stands in S13 with ready up; the request stands
// forever and busy() stays true. The cabinet's transfer_timeout stops the run.
//
// Emulation note: the seed's S1 also unloads and loads workpieces and reads sensors 171-173 to
// choose the program; here the card's T is the tool specifying signal and S2's "kind of
// workpiece" is "was the head exchanged". A tool memory 132 holds no head for is ignored (CR1
// never picks, busy() is false): the cabinet refuses such a card (tap_refused) before it calls.
// An exchange once started completes even if the call is withdrawn (the mechanism does not stop
// halfway); the NC holds its call until tool ready, so that does not happen in a run.
#include "relaylogic/tapping/programmable_controller.hpp"

#include "axes/state_json.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace parsons::relaylogic {
namespace {

struct RelayName {
    const char* name;
    const char* what;
};

constexpr std::array<RelayName, ProgrammableController::kRelays> kRelayNames = {{
    {"pc130.cr1_tool_call", "PC 130 relay CR1 (S1): the NC's tool specifying signal, latched"},
    {"pc130.cr2_exchange",
     "PC 130 relay CR2 (S1): head exchange timer running (the motor at rest)"},
    {"pc130.cr3_exchanged", "PC 130 relay CR3 (S1): this call's head exchange is done"},
    {"pc130.cr4_head_on", "PC 130 relay CR4: the called head stands on the spindle"},
    {"pc130.cr5_ratio_change",
     "PC 130 relay CR5 (S2 yes, S3): the ratio in the NC must change; selected from memory 132"},
    {"pc130.cr6_request", "PC 130 relay CR6 (S4, S5): transfer request, waiting for ready"},
    {"pc130.cr7_transfer",
     "PC 130 relay CR7 (S6-S8): the ratio on the data lines, waiting for received"},
    {"pc130.cr8_done", "PC 130 relay CR8: the sequence is done, tool ready to the NC"},
}};

} // namespace

std::uint32_t ratio_millionths(double ratio) {
    return static_cast<std::uint32_t>(std::lround(std::fmax(ratio, 0.0) * 1e6));
}

ProgrammableController::ProgrammableController(Tracer& tracer,
                                               const axes::SpindleSyncProfile& profile)
    : tracer_(tracer), profile_(profile) {
    for (std::size_t i = 0; i < relay_.size(); ++i) {
        relay_signal_.at(i) =
            tracer.define("spindle", kRelayNames.at(i).name, kRelayNames.at(i).what, "130", 1);
    }
    register_signal_ = tracer.define("spindle", "pc130.register_132",
                                     "PC 130: the ratio selected from memory 132 (S3), "
                                     "millionths",
                                     "132", 24);
    tool_call_signal_ = tracer.define("spindle", "bus35.tool_call",
                                      "bus 35: the NC's tool specifying signal T as PC 130 reads "
                                      "it at its scan (0 = none)",
                                      "35", 7);
    request_signal_ = tracer.define("spindle", "bus35.transfer_request",
                                    "bus 35: PC 130's data transfer request (S4)", "35", 1);
    data_valid_signal_ =
        tracer.define("spindle", "bus35.data_valid",
                      "bus 35: the gear ratio stands on the data lines (S6)", "35", 1);
    data_ratio_signal_ =
        tracer.define("spindle", "bus35.data_ratio",
                      "bus 35: the gear ratio on the data lines, millionths", "35", 24);
    tool_ready_signal_ =
        tracer.define("spindle", "bus35.tool_ready",
                      "bus 35: PC 130's sequence for the called tool is done", "35", 1);
}

bool ProgrammableController::change_wanted() const {
    // S2, first embodiment: yes after every exchange, unless the fault hits this one.
    return profile_.ratio_source == axes::RatioSource::transferred && exchanges_ != stale_ratio_at_;
}

void ProgrammableController::scan(double t, Bus35& bus, axes::Spindle& spindle) {
    // Inputs, read once at the start of the scan.
    const int call = bus.tool_call;
    const bool known = call != 0 && profile_.head(call) != nullptr;
    const bool standing = relay_[cr1_tool_call] && call == answered_tool_;
    const int head = spindle.tool();
    const bool at_rest = spindle.at_rest();
    const bool ready = bus.nc_ready;
    const bool received = bus.nc_received;
    const bool timer_done = exchanging() && t >= exchange_done_s_;
    const std::array<bool, kRelays> old = relay_;
    std::array<bool, kRelays>& r = relay_;

    // CR8: done (S2 no, or S8 yes); sealed in while the call stands.
    r[cr8_done] = standing && (old[cr8_done] || (old[cr4_head_on] && !old[cr3_exchanged]) ||
                               (old[cr4_head_on] && old[cr3_exchanged] && !change_wanted()) ||
                               (old[cr7_transfer] && received));
    // CR7: S6 when the NC is ready; S7/S8 wait for received.
    r[cr7_transfer] =
        standing && !r[cr8_done] && (old[cr7_transfer] || (old[cr6_request] && ready));
    if (r[cr7_transfer] && !old[cr7_transfer]) {
        ++transfers_;
    }
    // CR6: S4, the request; S5 waits for ready with the request standing.
    r[cr6_request] = standing && !r[cr8_done] && (old[cr6_request] || old[cr5_ratio_change]);
    // CR5: S2 yes, S3 the ratio selected.
    r[cr5_ratio_change] =
        standing && !r[cr8_done] &&
        (old[cr5_ratio_change] || (old[cr3_exchanged] && old[cr4_head_on] && change_wanted()));
    if (r[cr5_ratio_change] && !old[cr5_ratio_change]) {
        register_132_ = profile_.head(answered_tool_)->ratio;
    }
    // CR4: the called head on the spindle (its switch, read at the start of the scan).
    r[cr4_head_on] = standing && head == answered_tool_;
    // CR3: this call's exchange done.
    r[cr3_exchanged] = standing && (old[cr3_exchanged] || timer_done);
    // CR2: the exchange timer.
    if (old[cr2_exchange]) {
        r[cr2_exchange] = !timer_done;
        if (timer_done) {
            spindle.mount(answered_tool_);
            ++exchanges_;
            exchange_done_s_ = -1;
        }
    } else {
        r[cr2_exchange] = standing && head != answered_tool_ && at_rest && !old[cr3_exchanged];
        if (r[cr2_exchange]) {
            exchange_done_s_ = t + profile_.head_change_s;
        }
    }
    // CR1: the call, latched; a new call waits for an exchange under way.
    if (old[cr1_tool_call]) {
        r[cr1_tool_call] = call == answered_tool_;
    } else {
        r[cr1_tool_call] = known && !r[cr2_exchange];
        if (r[cr1_tool_call]) {
            answered_tool_ = call;
        }
    }

    // Outputs.
    const bool hung = r[cr7_transfer] && transfers_ == transfer_hang_at_;
    bus.transfer_request = r[cr6_request];
    bus.data_valid = r[cr7_transfer] && !hung;
    bus.data_ratio = bus.data_valid ? register_132_ : 0.0;
    bus.tool_ready = r[cr8_done];
    show(bus);
}

void ProgrammableController::show(const Bus35& bus) {
    for (std::size_t i = 0; i < relay_.size(); ++i) {
        tracer_.set(relay_signal_.at(i), relay_.at(i) ? 1U : 0U);
    }
    tracer_.set(register_signal_, ratio_millionths(register_132_));
    tracer_.set(tool_call_signal_, static_cast<std::uint32_t>(std::max(bus.tool_call, 0)));
    tracer_.set(request_signal_, bus.transfer_request ? 1U : 0U);
    tracer_.set(data_valid_signal_, bus.data_valid ? 1U : 0U);
    tracer_.set(data_ratio_signal_, ratio_millionths(bus.data_ratio));
    tracer_.set(tool_ready_signal_, bus.tool_ready ? 1U : 0U);
}

bool ProgrammableController::busy(const Bus35& bus) const {
    if (bus.transfer_request || bus.data_valid || bus.nc_ready || bus.nc_received) {
        return true; // a handshake under way, or the NC's ready and received still to drop
    }
    const bool standing = relay_[cr1_tool_call] && bus.tool_call == answered_tool_;
    if (standing) {
        return !relay_[cr8_done]; // the sequence runs (or waits for the motor to rest)
    }
    // No call standing: relays still to drop, or a call of a known tool to pick. CR2 is among
    // them: an exchange runs on without the call, and a scan at or after its end mounts the
    // head.
    for (const bool picked : relay_) {
        if (picked) {
            return true;
        }
    }
    return bus.tool_call != 0 && profile_.head(bus.tool_call) != nullptr;
}

nlohmann::json ProgrammableController::save() const {
    nlohmann::json relays = nlohmann::json::object();
    for (std::size_t i = 0; i < relay_.size(); ++i) {
        relays[std::string(kRelayNames.at(i).name).substr(6)] = relay_.at(i);
    }
    return {{"relays", relays},
            {"answered_tool", answered_tool_},
            {"exchange_done_s", axes::exact(exchange_done_s_)},
            {"exchanges", exchanges_},
            {"transfers", transfers_},
            {"register_132", axes::exact(register_132_)}};
}

void ProgrammableController::load(const nlohmann::json& j) {
    const nlohmann::json& relays = axes::member(j, "relays");
    std::array<bool, kRelays> r{};
    for (std::size_t i = 0; i < r.size(); ++i) {
        r.at(i) = axes::read<bool>(relays, std::string(kRelayNames.at(i).name).substr(6).c_str());
    }
    const int tool = axes::read<int>(j, "answered_tool");
    if (tool != 0 && profile_.head(tool) == nullptr) {
        throw axes::StateError("pc130: answered_tool has no head in the profile");
    }
    const double done = axes::exact(axes::member(j, "exchange_done_s"));
    if (r[cr2_exchange] != (done >= 0)) {
        throw axes::StateError("pc130: the exchange timer and relay CR2 disagree");
    }
    relay_ = r;
    answered_tool_ = tool;
    exchange_done_s_ = done;
    exchanges_ = axes::read<std::int64_t>(j, "exchanges");
    transfers_ = axes::read<std::int64_t>(j, "transfers");
    register_132_ = axes::exact(axes::member(j, "register_132"));
}

nlohmann::json save_bus35(const Bus35& bus) {
    return {{"tool_call", bus.tool_call},     {"nc_ready", bus.nc_ready},
            {"nc_received", bus.nc_received}, {"transfer_request", bus.transfer_request},
            {"data_valid", bus.data_valid},   {"data_ratio", axes::exact(bus.data_ratio)},
            {"tool_ready", bus.tool_ready}};
}

Bus35 load_bus35(const nlohmann::json& j) {
    Bus35 bus;
    bus.tool_call = axes::read<int>(j, "tool_call");
    bus.nc_ready = axes::read<bool>(j, "nc_ready");
    bus.nc_received = axes::read<bool>(j, "nc_received");
    bus.transfer_request = axes::read<bool>(j, "transfer_request");
    bus.data_valid = axes::read<bool>(j, "data_valid");
    bus.data_ratio = axes::exact(axes::member(j, "data_ratio"));
    bus.tool_ready = axes::read<bool>(j, "tool_ready");
    return bus;
}

} // namespace parsons::relaylogic
