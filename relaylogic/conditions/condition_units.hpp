// The condition units of EP 0640901 (Siemens) wired into the cabinet: converter UMS
// and internal buffer PFR (relaylogic/conditions/internal_buffer.hpp), monitoring unit PRG
// (relaylogic/conditions/monitoring_unit.hpp) and tripping unit ALE
// (relaylogic/conditions/tripping_unit.hpp). An addition, not in the 1952 patent: present only when
// the profile allows condition cards (parsons-extended); otherwise the cabinet has none of these
// relays and traces none of them.
//
// The seed's sequence, as the cabinet runs it (claims 1, 2, 4):
//   condition card read ..... UMS enters each record into PFR as a condition entry and an
//                             action entry with one identifier (state: stored)
//   motion card, relays pick  PFR supplies each stored condition to its PRG channel (armed)
//   an impulse steps the
//   watched axis's counter ... PRG's circuit closes: status signal = the identifier; ALE
//                             initiates the action (tripped) and the cabinet queues the
//                             acknowledgement for when the action is done
//   shaft 280 comes home ..... a condition still armed was never met: condition_not_met;
//                             else zeroizing waits until every action is acknowledged, then
//                             clears PFR and PRG and feeds the next card
#pragma once

#include "relaylogic/conditions/internal_buffer.hpp"
#include "relaylogic/conditions/monitoring_unit.hpp"
#include "relaylogic/conditions/tripping_unit.hpp"

#include <algorithm>
#include <memory>
#include <vector>

namespace parsons::relaylogic {

// One action a condition card tripped (an addition after EP 0640901), for the report.
struct ActionRecord {
    int event = 0;
    std::int64_t condition_card = 0;
    std::int64_t motion_card = 0;
    int motion_card_number = -1;
    cardreader::Axis axis = cardreader::Axis::table;
    cardreader::Thousandths position = 0;
    cardreader::ActionKind action = cardreader::ActionKind::lamp;
    int parameter = 0;
    double tripped_s = 0;
    double acknowledged_s = 0;
    double motion_end_s = 0; // when the motion card's last axis stopped
    bool every = false;      // an every-condition's firing (an addition beyond the seed's claims)
    int firing = 0;          // and which: 1, 2, ... (0 for a once-condition)
    // How long the action ran while the card's axes still moved: min(acknowledged, motion
    // end) - tripped, or 0. The time the seed saves over starting it at the card's end.
    double overlap_s() const {
        const double end = std::min(acknowledged_s, motion_end_s);
        return end > tripped_s ? end - tripped_s : 0.0;
    }
};

// The records as a saved state keeps them, every time to the bit.
nlohmann::json actions_to_json(const std::vector<ActionRecord>& actions);
std::vector<ActionRecord> actions_from_json(const nlohmann::json& j);

class ConditionUnits {
public:
    // Builds the units if the profile allows condition cards (their signals are defined then,
    // after the cabinet's own).
    void install(Tracer& tracer, const axes::MachineProfile& profile);
    bool present() const { return buffer_ != nullptr; }
    // Zeroizing held until every action is acknowledged (claim 2): traced.
    void set_waiting(bool waiting);

    // A condition card was sensed (deck position `index`): UMS enters it, or says why not.
    std::optional<std::string> convert(const cardreader::CardOrders& card, std::int64_t index);
    // A condition stored and never yet armed: waiting for its first motion card (an
    // every-condition stored again after its motion cards is not), or -1.
    int first_waiting() const;
    // Before a motion card's relays pick: a stored condition on an axis the card does not move
    // (check 0) cannot be met. Returns the message naming cards, event and axis.
    std::optional<std::string> refuse_unmoved(const cardreader::CardOrders& motion,
                                              std::int64_t index) const;
    // A motion card is sensed: converter UMS enters its statement into PFR (claim 1).
    void enter_motion(int card_number) { buffer_->set_motion(MotionEntry::entered, card_number); }
    // The motion card's relays pick: PFR supplies its statement to the axes, and every stored
    // condition is armed on PRG.
    void arm(std::int64_t motion_card);
    bool watching(cardreader::Axis axis) const { return prg_ && prg_->watching(axis); }
    // The counter of `axis` stepped to `counter`, counting in `direction`: the channels PRG
    // reports (bit k).
    unsigned on_counter_step(cardreader::Axis axis, const Digits& counter, int direction) {
        return prg_->on_counter_step(axis, counter, direction);
    }
    // ALE initiates channel k's action at t: returns when it is done.
    double trip(int k, double t);
    void acknowledge(int k, double t);
    bool all_acknowledged() const { return !buffer_ || !buffer_->any(PairState::tripped); }
    // The first channel of a once-condition still armed (never met), or -1 (an every-condition
    // need not be met on every card).
    int first_unmet() const;
    // The zeroizing circuit: PFR and PRG cleared, output lamps out; an every-condition's pair
    // is stored again for the next motion card (its firings counted).
    void zeroize();
    bool held(cardreader::Axis axis) const { return ale_ && ale_->held(axis); }
    void drive_spindle(axes::SpindleMotor& motor) {
        if (ale_) {
            ale_->drive_spindle(motor);
        }
    }
    void spindle_from_card(cardreader::Spindle s, double t) {
        if (ale_) {
            ale_->spindle_from_card(s, t);
        }
    }
    const InternalBuffer& buffer() const { return *buffer_; }
    const TrippingUnit& ale() const { return *ale_; }
    const MonitoringUnit& prg() const { return *prg_; }
    // What an observer is told of channel k.
    ConditionEvent event(int k, ConditionEventKind kind, std::int64_t card, int card_number) const;
    nlohmann::json save() const;
    void load(const nlohmann::json& j);

private:
    std::unique_ptr<InternalBuffer> buffer_;
    std::unique_ptr<MonitoringUnit> prg_;
    std::unique_ptr<TrippingUnit> ale_;
    Tracer* tracer_ = nullptr;
    SignalId waiting_ = 0;
};

} // namespace parsons::relaylogic
