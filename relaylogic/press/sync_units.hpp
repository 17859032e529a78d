// The press synchronisation of EP 0436887 (Mitsubishi) wired into the cabinet: the
// press beside the machine (axes/press.hpp: crank 21, motor 22, die 20, detector 10), direction
// judging device 13, position register 14 with setter 15, device 16 and switch 16A, speed
// register 11 and synchronisation control processor 17 (60-63). An addition, not in the 1952
// patent: present only when the profile has press synchronisation (parsons-extended);
// otherwise the cabinet has none of these relays and traces none of them.
//
// The seed's sequence, as the cabinet runs it:
//   every detector edge ....... 13 judges the sense; 14 counts up or down (setter 15 presets
//                               it each revolution); 11 counts the pulse
//   every reference block ..... the speeds 63 computed at the last block go to the drive;
//                               11's count is stored and read; 63 computes the next speeds;
//                               a wait longer than the profile's sync_timeout_s stops the
//                               machine (sync_timeout)
//   sync card read ............ a reset order operates switch 16A (14 clears); its
//                               synchronisation waits in 60 and 62 for the next motion card
//   motion card, relays pick .. the orders are armed on this card
//   reading complete .......... position sync: 60's hold relay holds the card's motion unless
//                               14 stands on R; 61 drops it when 14 reaches R
//   a synced axis, any speed . the follower drive runs the axis at 63's speed
//   zeroizing ................. 60 and 62 cleared
//   feeder interlock .......... (press.feeder_hold_lag_in) at each block: a synchronised axis
//                               too far behind holds the press from the next block
//                               (relaylogic/press/feeder_interlock.hpp)
#pragma once

#include "axes/press.hpp"
#include "relaylogic/press/direction_judging_device.hpp"
#include "relaylogic/press/feeder_interlock.hpp"
#include "relaylogic/press/position_register.hpp"
#include "relaylogic/press/speed_register.hpp"
#include "relaylogic/press/synchronisation_processor.hpp"

#include <memory>

namespace parsons::relaylogic {

class SyncUnits {
public:
    // Builds the press and the units if the profile has press synchronisation.
    void install(Tracer& tracer, const axes::MachineProfile& profile);
    bool present() const { return press_ != nullptr; }

    axes::Press& press() { return *press_; }
    const axes::Press& press() const { return *press_; }
    SynchronisationProcessor& scp() { return *scp_; }
    const SynchronisationProcessor& scp() const { return *scp_; }
    const PositionRegister& position_register() const { return *register_14_; }
    PositionRegister& position_register() { return *register_14_; }
    const SpeedRegister& speed_register() const { return *register_11_; }
    // The feeder's interlock, when the profile sets press.feeder_hold_lag_in (else nullptr).
    FeederInterlock* interlock() { return interlock_.get(); }
    const FeederInterlock* interlock() const { return interlock_.get(); }

    // A detector edge at time t: 13, 14, 11. Returns true when detector 61 conducts (the
    // card's motion is to start).
    bool on_edge(const axes::DetectorEdge& edge, double t);
    // A reference block at time t: speed register 11's count moves into its holding relays,
    // and the crank's speed is read from it: the sample's pulses over the time from the last
    // pulse before them to the last of them (the register's timer notes when each pulse
    // comes), so a speed is exact once two pulses have been timed, however few a block holds.
    // A block with no pulse bounds the speed by one pulse in the time since the last.
    // Returns pulses a second.
    double sample_speed(double t);
    // The last reading was timed between two pulses, not bounded by a block without one: the
    // crank turns.
    bool turning() const { return turning_; }
    // Fast-forward: n edges in the press's sense, the first of them at `first_t`, the last of
    // them `last`, at time t.
    void on_edges(std::int64_t n, const axes::DetectorEdge& last, double first_t, double t);
    // Fast-forward: how many coming edges are only counts (the one that makes 61 conduct is
    // not), at most `limit`.
    std::int64_t quiet_edges(std::int64_t limit) const;
    // The machine time of the last detector edge (the start, before any).
    double last_edge_s() const { return last_edge_s_; }
    // Crank angle and die height as trace signals (at each edge, with an observer).
    void show_press();

    // The units' state (present() only: the cabinet keeps null for a machine without them).
    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    std::uint32_t crank_tenths() const;
    std::uint32_t die_thousandths() const;

    std::unique_ptr<axes::Press> press_;
    std::unique_ptr<DirectionJudgingDevice> device_13_;
    std::unique_ptr<PositionRegister> register_14_;
    std::unique_ptr<SpeedRegister> register_11_;
    std::unique_ptr<SynchronisationProcessor> scp_;
    std::unique_ptr<FeederInterlock> interlock_;
    Tracer* tracer_ = nullptr;
    double last_edge_s_ = 0;
    double first_edge_s_ = -1;   // the first pulse timed (-1: none yet)
    double sampled_edge_s_ = -1; // the last pulse of the last sample that had one
    double rate_ = 0;            // pulses a second, as last read
    bool turning_ = false;       // the last read was timed between pulses (not a bound)
    SignalId crank_21_ = 0;
    SignalId die_20_ = 0;
    SignalId motor_22_ = 0;
    SignalId speed_11_ = 0;
};

} // namespace parsons::relaylogic
