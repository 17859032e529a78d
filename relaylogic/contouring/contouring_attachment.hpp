// Contouring (an addition after EP 0636958, Black & Decker) as an attachment of control cabinet
// 52 (relaylogic/attachment.hpp): segment cards, read one ahead of the tool, drive three stepper
// axes X, Y, Z together along straight segments (the interpolator), and at each junction the
// control cycle, run while the tool travels the first segment (claim 6), decides whether to pass
// at the nominal speed or slow to the minimum (claims 1, 4, 7, 8). Its motors are plants of its
// own (axes/stepper_motor.hpp): they lose steps where their pulse rate jumps further than they
// follow, and nothing measures them (docs/contouring.md). The 1952 axes do not move on a
// segment card; a motion card after segments waits until the stepper axes are at rest.
#pragma once

#include "relaylogic/attachment.hpp"
#include "relaylogic/contouring/contouring_result.hpp"
#include "relaylogic/contouring/interpolator.hpp"
#include "relaylogic/tracer.hpp"

#include "axes/stepper_motor.hpp"

#include <array>
#include <optional>

namespace parsons::relaylogic {

class ContouringAttachment final : public Attachment {
public:
    ContouringAttachment(Tracer& tracer, const axes::MachineProfile& profile);
    // The profile has contouring (otherwise the registry keeps none).
    bool present() const { return present_; }

    std::string_view name() const override { return "contouring"; }
    std::optional<cardreader::CardKind> card_kind() const override {
        return cardreader::CardKind::segment;
    }
    bool card_read(ControlCabinet& cab) override;
    bool holds_motion(ControlCabinet& cab) override;
    void machine_stopped(ControlCabinet& cab) override;
    void on_event(ControlCabinet& cab, int code) override;
    void save(const ControlCabinet& cab, nlohmann::json& state) const override;
    void load(ControlCabinet& cab, const nlohmann::json& state) override;
    void add_to(RunResult& result) const override;

private:
    struct AxisSignals {
        SignalId period;
        SignalId direction;
        SignalId lost;
    };
    void begin(ControlCabinet& cab, const PathSegment& s, double entry);
    void replan(ControlCabinet& cab, double exit);
    void tick(ControlCabinet& cab);
    void reach_end(ControlCabinet& cab);
    void show_rates(const Point3& rates, double speed);
    void take_losses(const Point3& rates, JunctionRecord* record);
    double s_now(double t) const;
    double v_now(double t) const;

    bool present_;
    axes::ContourProfile profile_;
    Tracer& tracer_;
    std::array<axes::StepperMotor, cardreader::kSegmentAxes> motors_;
    std::array<AxisSignals, cardreader::kSegmentAxes> axis_signals_{};
    SignalId segment_signal_;
    SignalId junction_signal_;
    SignalId difference_signal_;
    SignalId speed_signal_;

    Point3 position_{}; // where the current segment began, or where the axes rest
    std::optional<PathSegment> current_;
    std::optional<PathSegment> next_;
    JunctionDecision decision_; // for current_ -> next_
    SegmentPlan plan_;
    int generation_ = 0;                    // events of an older plan are passed over
    bool card_held_ = false;                // next_'s card stays in the reader until current_ ends
    bool motion_waiting_ = false;           // a motion card waits for the axes to rest
    std::optional<JunctionRecord> pending_; // decided, not yet reached
    int rested_after_ = 0;                  // the card number the axes came to rest after (0: none)
    ContouringResult result_;
};

} // namespace parsons::relaylogic
