// Condition cards (an addition after EP 0640901, Siemens) as an attachment of control cabinet 52
// (relaylogic/attachment.hpp): converter UMS and internal buffer PFR take a condition card;
// monitoring unit PRG watches the counters of the motion card after it; tripping unit ALE
// starts each action and holds the zeroizing circuit until every action is acknowledged
// (claims 1, 2, 4). The units are relaylogic/conditions/condition_units.hpp's.
#pragma once

#include "relaylogic/attachment.hpp"
#include "relaylogic/conditions/condition_units.hpp"
#include "relaylogic/fast_forward.hpp"

namespace parsons::relaylogic {

class ConditionsAttachment final : public Attachment, private CounterWatch {
public:
    ConditionsAttachment(Tracer& tracer, const axes::MachineProfile& profile);
    // The profile allows condition cards (otherwise the registry keeps none).
    bool present() const { return units_.present(); }

    std::string_view name() const override { return "conditions"; }
    std::optional<cardreader::CardKind> card_kind() const override {
        return cardreader::CardKind::condition;
    }
    void start(ControlCabinet& cab) override;
    void deck_ended(ControlCabinet& cab) override;
    void read_card(ControlCabinet& cab) override;
    void check_motion_card(ControlCabinet& cab) override;
    void relays_picked(ControlCabinet& cab) override;
    bool after_count(ControlCabinet& cab, AxisCircuit& c) override;
    const CounterWatch* counter_watch() const override { return this; }
    bool holds_axis(cardreader::Axis axis) const override { return units_.held(axis); }
    bool zeroizing_may_start(ControlCabinet& cab) override;
    void zeroized(ControlCabinet& cab) override;
    void on_event(ControlCabinet& cab, int channel) override;
    void save(const ControlCabinet& cab, nlohmann::json& state) const override;
    void load(ControlCabinet& cab, const nlohmann::json& state) override;
    void add_to(RunResult& result) const override;

private:
    bool watching(cardreader::Axis axis) const override { return units_.prg().watching(axis); }
    void each_watched(cardreader::Axis axis, int direction,
                      const std::function<void(int)>& f) const override {
        units_.prg().each_watched(axis, direction, f);
    }
    void acknowledge(ControlCabinet& cab, int channel);
    void interlock(ControlCabinet& cab, int channel);
    void tell(ControlCabinet& cab, int channel, ConditionEventKind kind);
    void dwell_follows(ControlCabinet& cab, int channel);

    ConditionUnits units_;
    bool used_ = false;                 // a condition card was read (the report shows it)
    bool zeroize_waiting_ = false;      // the zeroizing circuit waits for acknowledgements
    std::vector<ActionRecord> actions_; // every action acknowledged, for the report
};

} // namespace parsons::relaylogic
