// Spindle synchronisation for tap cards (an addition after EP 0360190, Mitsubishi) as an
// attachment of control cabinet 52 (relaylogic/attachment.hpp): a tap card's tool call goes on
// bus 35; PC 130 exchanges the head and transfers its gear ratio to memory 12a; the
// synchronous operation control then drives the feed axis's follower in step with spindle
// encoder 32, reverses at the depth and brings the feed back to its starting count. The units
// are relaylogic/tapping/tapping_units.hpp's (which tells the sequence).
#pragma once

#include "relaylogic/attachment.hpp"
#include "relaylogic/tapping/tapping_units.hpp"

namespace parsons::relaylogic {

class TappingAttachment final : public Attachment {
public:
    TappingAttachment(Tracer& tracer, const axes::MachineProfile& profile);
    // The profile has spindle synchronisation (otherwise the registry keeps none).
    bool present() const { return units_.present(); }

    std::string_view name() const override { return "tapping"; }
    std::optional<cardreader::CardKind> card_kind() const override {
        return cardreader::CardKind::tap;
    }
    void start(ControlCabinet& cab) override;
    void read_card(ControlCabinet& cab) override;
    bool card_read(ControlCabinet& cab) override;
    void before_count(ControlCabinet& cab, AxisCircuit& c, int direction) override;
    void before_jump(ControlCabinet& cab, AxisCircuit& c, double t) override;
    bool drive(ControlCabinet& cab, AxisCircuit& c, bool on) override;
    void machine_stopped(ControlCabinet& cab) override;
    void on_event(ControlCabinet& cab, int code) override;
    void advance_plants(ControlCabinet& cab, double t) override;
    void save(const ControlCabinet& cab, nlohmann::json& state) const override;
    void load(ControlCabinet& cab, const nlohmann::json& state) override;
    void add_to(RunResult& result) const override;
    void fault_effect(const ControlCabinet& cab, const Fault& f, FaultEffect& e) const override;

private:
    enum Code : int { pc_scan_event = 0, spindle_sample_event = 1, reversal_event = 2 };
    void pc_scan(ControlCabinet& cab);
    void spindle_sample(ControlCabinet& cab);
    static void counting_sense(AxisCircuit& c, int direction);

    TappingUnits units_;
    bool used_ = false; // a tap card was read (the report shows the spindle)
};

} // namespace parsons::relaylogic
